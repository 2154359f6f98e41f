#!/usr/bin/env bash
# Provisions Godot 4.6 into a private Debian-unstable root inside the cache.
# Debian 12 only ships Godot 3, and installing unstable's godot into the host would
# replace libc; a debootstrap root run through its own dynamic loader avoids both.
source "$(dirname "$0")/common.sh"
lock_cache

if [ -n "${GODOT:-}" ]; then
  log "using GODOT=$GODOT; no private root needed"
  exit 0
fi
# The root's engine and C library decide how rides come out: compare them with the lock
# (a warning here, an error in CI) every time, not only when the root is built.
if [ -f "$GODOT_ROOT/.complete" ]; then
  exec "$(dirname "$0")/godot-root-lock.sh"
fi

command -v debootstrap >/dev/null || die "debootstrap is missing; run make setup first"
mirror=$(debian_mirror)
partial="$GODOT_ROOT.partial"
log "building the Godot 4.6 root in $GODOT_ROOT from $mirror (about a minute, ~1 GB)"
as_root rm -rf "$partial"
as_root debootstrap --variant=minbase --include="$GODOT_ROOT_PACKAGES" sid "$partial" "$mirror" >"$CACHE_ROOT/debootstrap.log" 2>&1 \
  || { tail -n 30 "$CACHE_ROOT/debootstrap.log" >&2; die "debootstrap failed (log: $CACHE_ROOT/debootstrap.log)"; }
# The root is only read from here on; drop the package cache to save ~150 MB.
as_root rm -rf "$partial/var/cache/apt/archives/"*.deb
if [ "$(id -u)" -ne 0 ]; then as_root chown -R "$(id -u):$(id -g)" "$partial"; fi
touch "$partial/.complete"
mv "$partial" "$GODOT_ROOT"
log "Godot root ready"
# Debian's mirror serves only its current versions, so the lock cannot be installed from
# it; what can be done is to notice when the mirror moved on.
exec "$(dirname "$0")/godot-root-lock.sh"
