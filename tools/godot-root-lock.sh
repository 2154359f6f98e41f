#!/usr/bin/env bash
# Compares the private Godot root's packages with tools/godot-root.lock, or (--update)
# writes the lock from the root. The root comes from Debian unstable on the day it is
# built, and the engine and the C library (whose libm the simulation calls) decide how a
# ride comes out, so a root that drifted from the lock is reported: a warning on a
# developer's machine, an error in CI (CI=true). docs/experiment.md, "Reproducibility",
# says how to accept new versions.
source "$(dirname "$0")/common.sh"

LOCK="$PROJECT_ROOT/tools/godot-root.lock"
# Packages whose version decides rides: the engine's, and the C library's.
DECISIVE_RE='^(godot|libc6) '

installed_versions() {
  awk '/^Package: /{p=$2} /^Status: .* installed$/{ok=1} /^Version: /{v=$2}
       /^$/{if (ok && p) print p, v; p=""; v=""; ok=0}
       END{if (ok && p) print p, v}' "$GODOT_ROOT/var/lib/dpkg/status" | LC_ALL=C sort
}

# "4.6.3+ds-3" -> "4.6": a new minor version of the engine may change physics and scripts.
minor_of() { sed -E 's/^([0-9]+:)?([0-9]+\.[0-9]+).*/\2/' <<<"$1"; }

update_lock() {
  {
    echo "# Packages of the private Godot root (tools/provision-godot.sh), one 'name version' a"
    echo "# line, written by tools/godot-root-lock.sh --update. godot and libc6 decide rides:"
    echo "# setup warns (CI fails) when a root is built with other versions of them."
    installed_versions
  } >"$LOCK.tmp"
  mv "$LOCK.tmp" "$LOCK"
  log "wrote $(grep -vc '^#' "$LOCK") package versions to ${LOCK#"$PROJECT_ROOT"/}"
}

check_lock() {
  [ -f "$LOCK" ] || die "no ${LOCK#"$PROJECT_ROOT"/}: write it with tools/godot-root-lock.sh --update"
  local now locked drift=() others=0 name version want
  now=$(installed_versions)
  locked=$(grep -v '^#' "$LOCK")
  while read -r name want; do
    version=$(awk -v n="$name" '$1 == n {print $2}' <<<"$now")
    [ "$version" = "$want" ] && continue
    if [ "$name" = godot ] && [ "$(minor_of "$version")" = "$(minor_of "$want")" ]; then
      log "note: godot $version in the root, $want in the lock (same minor version)"
    elif [[ "$name $version" =~ $DECISIVE_RE ]] || [[ "$name $want" =~ $DECISIVE_RE ]]; then
      drift+=("$name ${version:-(missing)} (lock: $want)")
    else
      others=$((others + 1))
    fi
  done <<<"$locked"
  [ "$others" -eq 0 ] || log "note: $others other package(s) of the root differ from the lock"
  [ "${#drift[@]}" -eq 0 ] && return 0
  local message="the Godot root has other versions than tools/godot-root.lock: ${drift[*]}.
  Results made with the locked versions may not re-ride exactly. To accept the new versions:
  tools/godot-root-lock.sh --update, make test, tools/experiment verify (docs/experiment.md)."
  if [ "${CI:-}" = true ]; then die "$message"; fi
  log "warning: $message"
}

if [ -n "${GODOT:-}" ]; then
  exit 0 # the user's own engine: no private root to compare
fi
[ -f "$GODOT_ROOT/.complete" ] || die "the Godot root is not provisioned yet: run make setup"
case "${1:-}" in
  --update) update_lock ;;
  "") check_lock ;;
  *) die "usage: tools/godot-root-lock.sh [--update]" ;;
esac
