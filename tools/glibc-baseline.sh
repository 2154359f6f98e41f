#!/usr/bin/env bash
# Prints the newest glibc symbol version each shipped binary needs, and fails when any
# needs a newer one than MAX_GLIBC (Debian 12's 2.36 by default): a binary that asks for
# more does not start on that desktop.
# Usage: tools/glibc-baseline.sh BINARY...
source "$(dirname "$0")/common.sh"
[ $# -gt 0 ] || die "usage: glibc-baseline.sh BINARY..."
max=${MAX_GLIBC:-2.36}
worst=0
for binary in "$@"; do
  newest=$(objdump -T "$binary" | grep -o 'GLIBC_[0-9.]*' | sed 's/GLIBC_//' | sort -V | tail -n1)
  echo "glibc ${newest:-none} $binary"
  if [ -n "$newest" ] && [ "$(printf '%s\n%s\n' "$newest" "$max" | sort -V | tail -n1)" != "$max" ]; then
    worst=1
  fi
done
[ "$worst" -eq 0 ] || die "a shipped binary needs a glibc newer than $max"
