#!/usr/bin/env bash
# Records the game's sound with Godot's movie writer (under Xvfb, 60 frames a second of
# game time) while tests/sound/sound_capture rides each bike a player chooses by simulated
# input, then checks each recording against the engine's logged state (tools/sound_check):
# the pitch is the firing frequency of the bike's engine layout and rises with speed,
# tyres and engine are heard, pause is silent. Each bike's spectrogram is drawn to
# build/sound/<bike>.png (docs/sound/ keeps them).
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
command -v xvfb-run >/dev/null || die "xvfb-run is missing; run make setup"
out=build/sound
rm -rf "$out" && mkdir -p "$out" build/logs
for bike in street_390 dirt_125 sport_600; do
  log=build/logs/sound-capture-$bike.log
  use_scratch_user_data "sound-check-$bike"
  # The movie writer saves every frame as a picture beside the sound (the capture leaves
  # out the 3D scene, so they are cheap); --quit-after ends a capture that fails to load.
  timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" tools/godot --path . --rendering-driver opengl3 \
    --fixed-fps 60 --quit-after 900 --write-movie "$PROJECT_ROOT/$out/$bike.png" \
    res://tests/sound/sound_capture.tscn -- --log="$PROJECT_ROOT/$out/$bike.csv" --bike="$bike" \
    >"$log" 2>&1 || { cat "$log" >&2; die "the sound capture of the $bike failed"; }
  tools/check-godot-log "$log"
  rm -f "$out/$bike"[0-9]*.png
  log "$bike:"
  .venv/bin/sound-check "$out/$bike.wav" "$out/$bike.csv" \
    --spectrogram "$out/$bike-spectrogram.png" --title "$bike: pull away, through the gears, coast, brake, pause" \
    || die "the $bike does not sound as its engine"
done
