#!/usr/bin/env bash
# Proves the preflight stops a machine that lacks what the build needs, with its list and
# nothing else: a Rust older than rust-version and a Python older than 3.11 (shims first
# on PATH) are both named, with how to install each, and it exits 1; on this machine as it
# is it passes. Nothing is installed either way (what is missing here is not apt's).
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
shims=$(mktemp -d)
trap 'rm -rf "$shims"' EXIT
printf '#!/bin/sh\necho "rustc 1.80.0 (an old toolchain)"\n' >"$shims/rustc"
printf '#!/bin/sh\nexit 0\n' >"$shims/cargo"
printf '#!/bin/sh\necho 3.9\n' >"$shims/python3"
chmod +x "$shims"/*

out=$(env -u RUSTUP_TOOLCHAIN PATH="$shims:/usr/sbin:/usr/bin:/sbin:/bin" tools/preflight.sh 2>&1) \
  && status=0 || status=$?
fail() { printf '%s\n' "$out" >&2; die "preflight self-test: $1"; }
[ "$status" -eq 1 ] || fail "exited $status on a machine with an old Rust and Python, not 1"
grep -qE "Rust [0-9.]+ or newer \(native/Cargo.toml's rust-version\); this machine has 1.80.0" <<<"$out" \
  || fail "the old Rust was not named"
grep -q "Python 3.11 or newer (the pinned scipy and statsmodels); python3 is 3.9" <<<"$out" \
  || fail "the old Python was not named"
grep -q "Nothing was built" <<<"$out" || fail "no closing line"
[ "$(grep -c '^  - ' <<<"$out")" -eq 2 ] || fail "expected exactly the two missing items"

out=$(tools/preflight.sh 2>&1) || fail "failed on this machine, which builds"
echo "preflight self-test passed"
