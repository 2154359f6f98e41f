#!/usr/bin/env bash
# Proves the GDScript test runner can fail: runs it on the deliberately failing fixture
# suite and checks the exit code, the closing counts and file:line reporting.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"

out=$(timeout 300 tools/godot --headless --path . --fixed-fps 60 res://tests/test_runner.tscn -- --dir=res://tests/fixtures/runner 2>&1) && status=0 || status=$?
fail() { printf '%s\n' "$out" >&2; die "runner self-test: $1"; }

[ "$status" -ne 0 ] || fail "the runner exited 0 on a failing suite"
grep -qx "GDScript: 3 passed, 6 failed, 1 skipped" <<<"$out" || fail "wrong closing counts"
grep -q "test_runner_fixture.gd:[0-9][0-9]* one is not two: expected 2, got 1" <<<"$out" || fail "no file:line for a failed assertion"
grep -q "unexpected error: fixture: an error nobody expected" <<<"$out" || fail "an unexpected engine error was not attributed to its test"
grep -q "expected an error containing \"fixture: silence\"" <<<"$out" || fail "a missing expected error went unnoticed"
grep -A2 "FAIL test_script_error_fails" <<<"$out" | grep -q "unexpected error" || fail "a script error did not fail its test"
echo "Runner self-test: 1 passed, 0 failed"
