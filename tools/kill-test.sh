#!/usr/bin/env bash
# Nothing a player saved is lost to a kill: tests/saves/save_stress saves settings, records
# and a ghost in a loop and is killed with SIGKILL at random moments; after each kill the
# game's own loaders must read every file back whole (the last save or the one before).
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
mkdir -p build/logs
rounds=${1:-8}
# One data home for all rounds: each round reads back what the killed writer left.
use_scratch_user_data kill-test
for round in $(seq "$rounds"); do
  fresh=$([[ $round -eq 1 ]] && echo --fresh || true)
  tools/godot --headless --path . --audio-driver Dummy res://tests/saves/save_stress.tscn -- --write $fresh \
    >build/logs/kill-test-writer.log 2>&1 &
  writer=$!
  # Once it saves (Godot's start takes seconds on a busy machine: a fixed wait killed it
  # before its first save when make test ran beside a training run), let it save for a
  # while: 0.2 to 2.5 s more.
  for _ in $(seq 600); do
    grep -q "^saved round" build/logs/kill-test-writer.log && break
    kill -0 "$writer" 2>/dev/null || break
    sleep 0.1
  done
  sleep "$(awk -v r="$RANDOM" 'BEGIN { printf "%.2f", 0.2 + 2.3 * r / 32767 }')"
  kill -9 "$writer"
  wait "$writer" 2>/dev/null || true
  saved=$(grep -c "^saved round" build/logs/kill-test-writer.log || true)
  (( saved > 0 )) || die "round $round: the writer saved nothing before the kill (build/logs/kill-test-writer.log)"
  printf 'round %d: killed after %d saves; ' "$round" "$saved"
  tools/godot --headless --path . --audio-driver Dummy res://tests/saves/save_stress.tscn -- --check \
    2>&1 | grep "^kill test" || die "round $round: the saved files did not read back"
  [[ ${PIPESTATUS[0]} -eq 0 ]] || die "round $round: the saved files did not read back"
done
