#!/usr/bin/env bash
# Proves the GDScript test runner can fail: runs it on the deliberately failing fixture
# suite and checks the exit code, the closing counts and file:line reporting.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"

out=$(timeout 300 tools/run-suites.sh runner-self-test --dir=res://tests/fixtures/runner 2>&1) && status=0 || status=$?
fail() { printf '%s\n' "$out" >&2; die "runner self-test: $1"; }

[ "$status" -ne 0 ] || fail "the runner exited 0 on a failing suite"
grep -qx "GDScript: 3 passed, 6 failed, 1 skipped" <<<"$out" || fail "wrong closing counts"
grep -q "test_runner_fixture.gd:[0-9][0-9]* one is not two: expected 2, got 1" <<<"$out" || fail "no file:line for a failed assertion"
grep -q "unexpected error: fixture: an error nobody expected" <<<"$out" || fail "an unexpected engine error was not attributed to its test"
grep -q "expected an error containing \"fixture: silence\"" <<<"$out" || fail "a missing expected error went unnoticed"
grep -A2 "FAIL test_script_error_fails" <<<"$out" | grep -q "unexpected error" || fail "a script error did not fail its test"

# Outside a scratch data home (here: one the runner was not told about) it runs nothing.
use_scratch_user_data runner-refusal
out=$(timeout 300 env -u COUNTER_STEER_SCRATCH tools/godot --headless --path . --audio-driver Dummy \
  res://tests/test_runner.tscn -- --dir=res://tests/fixtures/runner 2>&1) && status=0 || status=$?
[ "$status" -ne 0 ] || fail "the runner ran outside a scratch data home"
grep -q "refusing to run in the player's data" <<<"$out" || fail "no refusal outside a scratch data home"
grep -qx "GDScript: 0 passed, 1 failed, 0 skipped" <<<"$out" || fail "a test ran outside a scratch data home"
echo "Runner self-test: 2 passed, 0 failed"
