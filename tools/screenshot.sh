#!/usr/bin/env bash
# Renders a scene in a real window under Xvfb and saves a screenshot; fails if it is blank.
# Each frame advances exactly 1/60 s of game time (--fixed-fps), so pictures are repeatable.
# Usage: tools/screenshot.sh res://scene.tscn build/screenshots/name.png [frames [--set=… --hold=… --tap=…]]
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
scene=$1; out=$2; frames=${3:-30}
command -v xvfb-run >/dev/null || die "xvfb-run is missing; run make setup"
mkdir -p "$(dirname "$out")" build/logs
log="build/logs/screenshot-$(basename "$out" .png).log"
use_scratch_user_data "screenshot-$(basename "$out" .png)"
timeout 300 xvfb-run -a -s "-screen 0 1280x720x24" tools/godot --path . --rendering-driver opengl3 --audio-driver Dummy \
  --resolution 1280x720 --fixed-fps 60 res://tests/screenshots/capture.tscn -- \
  --scene="$scene" --out="$PROJECT_ROOT/$out" --frames="$frames" "${@:4}" >"$log" 2>&1 \
  || { cat "$log" >&2; die "screenshot of $scene failed"; }
grep "^screenshot " "$log"
tools/check-godot-log "$log"
