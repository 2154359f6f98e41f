#!/usr/bin/env bash
# Runs the GDScript suites headless (tests/test_runner.tscn) with a Godot data home of
# their own, emptied first (build/scratch/NAME): the runner refuses to run anywhere else,
# so a test can never read or write the player's settings, records and ghosts.
# Usage: tools/run-suites.sh NAME [--dir=res://tests/… …] [--filter=TEXT]
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
[ $# -ge 1 ] || die "usage: tools/run-suites.sh NAME [runner arguments]"
use_scratch_user_data "$1"
shift
exec tools/godot --headless --path . --audio-driver Dummy --fixed-fps 60 res://tests/test_runner.tscn -- "$@"
