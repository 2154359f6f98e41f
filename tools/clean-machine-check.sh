#!/usr/bin/env bash
# A newcomer's first hour on a clean Debian 13, replayed: not part of make test (a cold
# make test is about 40 minutes). It makes a clean Debian 13 root (debootstrap minbase)
# with only what the README says a newcomer installs by hand (git and make), clones this
# checkout's HEAD into it and there
#   1. runs `make test` before Rust is installed: the preflight must stop it with its list
#      of what is missing, before anything is built and without a raw tool error;
#   2. installs Rust, then runs the README's two commands: `make test`, then `make play`
#      under a virtual display for PLAY_SECONDS (the game must still be running then).
# This workplace reaches no rustup server, so step 2's Rust is the host's rustup
# toolchain mounted read-only where rustup would have put it: the same files a newcomer's
# `rustup default stable` installs. Cargo's and pip's downloads, Godot's root, ODE and
# everything else start from nothing. Logs go to build/logs/clean-machine-*.log.
#   tools/clean-machine-check.sh [--keep] [--preflight-only | --play-only]
# --keep reuses the root of an earlier run; --preflight-only stops after step 1;
# --play-only runs step 3 alone in the checkout an earlier run left (with --keep).
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
mkdir -p build/logs
PLAY_SECONDS=60
suite=trixie
root="$CACHE_ROOT/clean-machine-$suite"
logs="$PROJECT_ROOT/build/logs"
[ "$(id -u)" -eq 0 ] || die "run as root: it makes and enters a Debian root"
[ -d "${RUSTUP_HOME:-$HOME/.rustup}/toolchains" ] || die "needs the host's rustup toolchain to stand in for rustup"

keep=false preflight_only=false play_only=false
for option in "$@"; do
  case "$option" in
    --keep) keep=true ;;
    --preflight-only) preflight_only=true ;;
    --play-only) play_only=true keep=true ;;
    *) die "usage: tools/clean-machine-check.sh [--keep] [--preflight-only | --play-only]" ;;
  esac
done

if ! $keep || [ ! -x "$root/usr/bin/git" ]; then
  log "making a clean Debian 13 root in $root (git and make only)"
  rm -rf "$root"
  debootstrap --variant=minbase --include=git,make "$suite" "$root" "$(debian_mirror)" \
    >"$logs/clean-machine-debootstrap.log" 2>&1 \
    || { tail -20 "$logs/clean-machine-debootstrap.log" >&2; die "debootstrap failed"; }
fi
if $play_only && [ ! -d "$root/root/counter-steer/native/target" ]; then
  die "--play-only needs the checkout an earlier run left"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
# The network's own set-up goes in with the name server: where the host reaches the
# registries through a TLS-inspecting gateway, the root trusts its CA as the host does
# (the host's extra CA certificates and pip's configuration naming the system bundle).
# That is this machine's network, not something the project needs.
mkdir -p "$root/usr/local/share/ca-certificates"
cp /usr/local/share/ca-certificates/*.crt "$root/usr/local/share/ca-certificates/" 2>/dev/null || true
[ ! -f /etc/pip.conf ] || cp /etc/pip.conf "$root/etc/pip.conf"
if ! $play_only; then
  rm -rf "$root/root/counter-steer" "$root/root/.cache" "$root/root/.cargo" "$root/root/.local"
  git clone -q --no-local "$PROJECT_ROOT" "$root/root/counter-steer"
fi

# Runs a command in the root as its root user, in namespaces of its own, with a clean
# environment; $1 says whether the host's Rust toolchain is mounted.
in_root() {
  local with_rust=$1; shift
  unshare --mount --pid --fork bash -c '
    root=$1 with_rust=$2; shift 2
    mount --rbind /dev "$root/dev" && mount -t proc proc "$root/proc" &&
    mount -t sysfs sys "$root/sys" && mount -t tmpfs tmpfs "$root/tmp" || exit 1
    path=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin
    if [ "$with_rust" = yes ]; then
      mkdir -p "$root/root/.rustup" "$root/root/.cargo/bin"
      mount --bind -o ro "${RUSTUP_HOME:-$HOME/.rustup}" "$root/root/.rustup"
      cp -a "${CARGO_HOME:-$HOME/.cargo}/bin/." "$root/root/.cargo/bin/"
      path=/root/.cargo/bin:$path
    fi
    exec chroot "$root" /usr/bin/env -i HOME=/root PATH="$path" TERM=dumb LANG=C.UTF-8 \
      bash -c "cd /root/counter-steer && $*"' _ "$root" "$with_rust" "$@"
}

if ! $play_only; then
  log "1. make test before Rust is installed"
  set +e
  in_root no make test >"$logs/clean-machine-without-rust.log" 2>&1
  status=$?
  set -e
  [ $status -ne 0 ] || die "make test passed without Rust (see $logs/clean-machine-without-rust.log)"
  grep -q "this machine is missing what the build needs" "$logs/clean-machine-without-rust.log" \
    || { tail -30 "$logs/clean-machine-without-rust.log" >&2; die "the preflight did not stop the build"; }
  if grep -qE "command not found|No such file or directory|Traceback|error\[" "$logs/clean-machine-without-rust.log"; then
    die "a raw tool error came before the preflight's message ($logs/clean-machine-without-rust.log)"
  fi
  sed -n '/this machine is missing/,$p' "$logs/clean-machine-without-rust.log"
  $preflight_only && exit 0

  log "2. make test with Rust (a cold make test; about 40 minutes on 2 cores)"
  # Step 1's preflight installed ca-certificates: bring the gateway's CA into its bundle.
  in_root no "update-ca-certificates >/dev/null"
  started=$SECONDS
  in_root yes make test >"$logs/clean-machine-make-test.log" 2>&1 \
    || { tail -40 "$logs/clean-machine-make-test.log" >&2; die "make test failed in the clean root"; }
  log "make test passed in $(((SECONDS - started) / 60)) min; its steps:"
  sed -n '/^ok  /p' "$logs/clean-machine-make-test.log"
fi

log "3. make play under a virtual display for $PLAY_SECONDS s"
set +e
in_root yes "timeout $PLAY_SECONDS xvfb-run -a -s '-screen 0 1280x720x24' make play" \
  >"$logs/clean-machine-make-play.log" 2>&1
status=$?
set -e
# 124: still running when the timeout ended it, as a game should be.
[ $status -eq 124 ] || { tail -30 "$logs/clean-machine-make-play.log" >&2; die "make play ended by itself (status $status)"; }
# The root has no sound device: Godot says ALSA cannot open one and plays silently, as on
# any machine without sound. That error alone is expected; any other fails the check.
errors=$(grep "^ERROR" "$logs/clean-machine-make-play.log" || true)
if grep -q "All audio drivers failed, falling back to the dummy driver" "$logs/clean-machine-make-play.log"; then
  errors=$(grep -vx 'ERROR: Condition "status < 0" is true. Returning: ERR_CANT_OPEN' <<<"$errors" || true)
fi
[ -z "$errors" ] || { printf '%s\n' "$errors" >&2; die "make play printed errors"; }
size() { du -sh "$root/$1" 2>/dev/null | cut -f1; }
log "disk: the cache $(size root/.cache/counter-steer), native/target $(size root/counter-steer/native/target)," \
  ".venv $(size root/counter-steer/.venv), build/ $(size root/counter-steer/build)," \
  "cargo's downloads $(size root/.cargo/registry); the whole root $(du -sh --exclude=root/.rustup "$root" | cut -f1)"
log "clean-machine check passed"
