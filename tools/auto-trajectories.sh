#!/usr/bin/env bash
# What the learned cost-to-go buys the game's automatic trajectory count (issue 59): each
# bike with a cost-to-go (models/value-<bike>.safetensors) rides the test level with
# combined and auto N, headless in real time, in blocks taken in turn with the player's
# switch on and off; prints the paired ratios of N and of the planning time
# (tests/bench/auto_trajectories.gd). Run it on an otherwise idle machine: auto N follows
# what this machine plans in time. Usage: tools/auto-trajectories.sh [pairs] [block seconds]
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
mkdir -p build/logs
for model in models/value-*.safetensors; do
  bike=$(basename "$model" .safetensors); bike=${bike#value-}
  [ -f "scenes/bike/bikes/$bike.tres" ] || continue
  use_scratch_user_data "auto-trajectories-$bike"
  log=build/logs/auto-trajectories-$bike.log
  timeout 1800 tools/godot --headless --path . --audio-driver Dummy \
    res://tests/bench/auto_trajectories.tscn -- --bike="res://scenes/bike/bikes/$bike.tres" \
    --pairs="${1:-6}" --block="${2:-20}" >"$log" 2>&1 \
    || { cat "$log" >&2; die "the auto trajectories run ($bike) failed"; }
  grep "^auto trajectories" "$log"
done
