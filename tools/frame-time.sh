#!/usr/bin/env bash
# Frame-time cost of the game-feel features (engine sound, replay recorder, ghost race) and
# each graphics quality preset's frame time (low, medium, high) at
# 1280x720 on the software renderer, planner off (arcade) and on (combined): each one's
# per-frame work timed in place, and the ghost's drawing as paired blocks
# with the ghost shown and hidden in one run each (tests/bench/frame_time.gd). The ghost
# raced is the bot's lap from the GDScript suites (build/ghosts/track.ghost), ridden here
# first when missing (about a minute).
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
mkdir -p build/logs
if [[ ! -f build/ghosts/track.ghost ]]; then
  log "riding the bot's lap for a ghost to race"
  tools/run-suites.sh frame-time-ghost --dir=res://tests/levels --filter=then_its_ghost \
    >build/logs/frame-time-ghost.log 2>&1 \
    || die "the bot's lap failed (build/logs/frame-time-ghost.log)"
fi
for controller in arcade combined; do
  use_scratch_user_data frame-time-$controller
  log=build/logs/frame-time-$controller.log
  timeout 900 xvfb-run -a -s "-screen 0 1280x720x24" tools/godot --path . --rendering-driver opengl3 \
    --resolution 1280x720 --fixed-fps 60 res://tests/bench/frame_time.tscn -- \
    --controller=$controller >"$log" 2>&1 \
    || { cat "$log" >&2; die "the frame-time run ($controller) failed"; }
  grep "^frame time" "$log"
done
