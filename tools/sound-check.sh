#!/usr/bin/env bash
# Records the game's sound with Godot's movie writer (under Xvfb, 60 frames a second of
# game time) while tests/sound/sound_capture rides by simulated input, then checks the
# recording against the engine's logged state (tools/sound_check): the pitch is the
# firing frequency and rises with speed, tyres and engine are heard, pause is silent.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
command -v xvfb-run >/dev/null || die "xvfb-run is missing; run make setup"
out=build/sound
rm -rf "$out" && mkdir -p "$out" build/logs
log=build/logs/sound-capture.log
use_scratch_user_data sound-check
# The movie writer saves every frame as a picture beside the sound (the capture leaves out
# the 3D scene, so they are cheap); --quit-after ends a capture that fails to load.
timeout 600 xvfb-run -a -s "-screen 0 1280x720x24" tools/godot --path . --rendering-driver opengl3 \
  --fixed-fps 60 --quit-after 900 --write-movie "$PROJECT_ROOT/$out/ride.png" \
  res://tests/sound/sound_capture.tscn -- --log="$PROJECT_ROOT/$out/ride.csv" >"$log" 2>&1 \
  || { cat "$log" >&2; die "the sound capture failed"; }
tools/check-godot-log "$log"
rm -f "$out"/ride[0-9]*.png
.venv/bin/sound-check "$out/ride.wav" "$out/ride.csv"
