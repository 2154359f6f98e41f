#!/usr/bin/env bash
# Builds ODE 0.16 from Debian's source package: static, position-independent,
# double precision, with thread-local collision data (OU).
# Debian's binary libode lacks OU (unsafe trimesh collision from several threads)
# and its libode.a is not PIC, so it cannot be linked into the extension.
source "$(dirname "$0")/common.sh"
lock_cache

# `ode-current` names the build this checkout wants, so a plain `cargo build` in native/
# (rust-analyzer, a newcomer) finds ODE without the Makefile exporting ODE_PREFIX.
point_current_at_prefix() { ln -sfn "$(basename "$ODE_PREFIX")" "$CACHE_ROOT/ode-current"; }
if [ -f "$ODE_PREFIX/.complete" ]; then
  point_current_at_prefix
  exit 0
fi

work="$CACHE_ROOT/ode-build"
rm -rf "$work"; mkdir -p "$work/apt/lists/partial" "$work/src"

# A private apt configuration with a deb-src line for Debian 12 whatever the host runs:
# every machine builds the same ODE (Debian 13 has 0.16.6, whose rollouts need not repeat
# 0.16.2's bit for bit). The host's own sources are neither read nor changed.
suite=bookworm
echo "deb-src $(debian_mirror) $suite main" > "$work/apt/sources.list"
apt_opts=(-o "Dir::Etc::SourceList=$work/apt/sources.list" -o "Dir::Etc::SourceParts=-"
          -o "Dir::State::Lists=$work/apt/lists" -o "APT::Sandbox::User=root" -qq)
log "fetching ODE's Debian source package"
apt-get "${apt_opts[@]}" update >/dev/null
(cd "$work/src" && apt-get "${apt_opts[@]}" source --download-only ode >/dev/null)
dsc=$(ls "$work"/src/ode_*.dsc | head -n1)
[ -n "$dsc" ] || die "no ODE source package found"
(cd "$work/src" && dpkg-source --no-check -x "$(basename "$dsc")" ode >/dev/null)
version=$(sed -n 's/^Version: \([0-9]*:\)\{0,1\}\([0-9.]*\).*/\2/p' "$dsc")
case "$version" in "$ODE_VERSION_WANTED") ;; *) die "expected ODE $ODE_VERSION_WANTED, the source package is $version";; esac

# Four small patches (tools/ode-patches/, applied in order); the first three make rollouts
# reproducible:
# 1. QuickStep reorders constraint rows with dRandInt, whose seed is one process-wide
#    atomic; worlds stepped on different threads would perturb each other's order. With a
#    thread-local seed every World carries its own sequence and swaps it in for its steps.
# 2. dBodySetQuaternion renormalises, so a restored body would differ from the original in
#    the last bits; dBodySetQuaternionExact restores the stored quaternion as it is.
# 3. An Euler-mode angular motor caches its angles during a step and dJointSetAMotorAngle
#    ignores them outside user mode; a restored world would report stale angles until its
#    next step. The setter now also restores the cache in Euler mode.
# 4. dWorldStep's Dantzig solver bounds friction by normal forces solved without friction,
#    so a spinning or locked wheel never gets the load its own traction transfers onto it
#    (no wheelie, no stoppie, half the grip under power). When a tyre's friction row slides
#    at a bound other than mu times its solved normal force, the step is solved again with
#    the loaded bounds (contacts marked by dContactApprox1_N; see cpbp-ode's contact.rs).
# The ODE cache's key (common.sh) covers this script and the patches.
for patch in "$PROJECT_ROOT"/tools/ode-patches/*.patch; do
  (cd "$work/src/ode" && patch -p1 --forward --quiet) <"$patch" \
    || die "could not apply $(basename "$patch") to ODE $version"
done

log "building ODE $version (static, PIC, double, OU)"
cmake -S "$work/src/ode" -B "$work/build" -G "Unix Makefiles" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$ODE_PREFIX.partial" \
  -DBUILD_SHARED_LIBS=OFF -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
  -DODE_DOUBLE_PRECISION=ON -DODE_WITH_OU=ON -DODE_WITH_DEMOS=OFF -DODE_WITH_TESTS=OFF \
  -DODE_WITH_LIBCCD=ON -DODE_WITH_LIBCCD_SYSTEM=OFF >"$work/cmake.log" 2>&1 \
  || { tail -n 30 "$work/cmake.log" >&2; die "cmake configure of ODE failed"; }
cmake --build "$work/build" -j"$(nproc)" >"$work/build.log" 2>&1 \
  || { tail -n 30 "$work/build.log" >&2; die "ODE build failed"; }
rm -rf "$ODE_PREFIX.partial"
cmake --install "$work/build" >/dev/null
touch "$ODE_PREFIX.partial/.complete"
rm -rf "$ODE_PREFIX"; mv "$ODE_PREFIX.partial" "$ODE_PREFIX"
point_current_at_prefix
rm -rf "$work"
log "ODE ready in $ODE_PREFIX"
