#!/usr/bin/env bash
# A player's check of the exported game (make export-check, make export-check-windows): the
# build is unpacked into a clean Debian root that has what an ordinary desktop has (X under
# Xvfb and Mesa; none of Debian unstable's libraries, no private root), started there,
# driven to the track by the keyboard, ridden for a few seconds and photographed.
# `linux` (the default) checks the Linux build, exported with the portable template
# (tools/build-template.sh), in Debian 12, and that no shipped binary needs a glibc newer
# than Debian 12's; `windows` checks the Windows build (tools/export-windows.sh) under
# Debian 13's Wine.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
mkdir -p build/logs build/screenshots
platform=${1:-linux}

# The harness: Xvfb, xdotool to press keys, ImageMagick to take the picture.
HARNESS="xvfb,xauth,xdotool,imagemagick,procps,fonts-dejavu-core"
case "$platform" in
  # With what a Linux desktop has: Mesa, X, ALSA, fontconfig, D-Bus, udev.
  linux) binary=counter-steer.x86_64 runner= suite=bookworm
    packages="$HARNESS,libgl1,libegl1,libgl1-mesa-dri,libglx-mesa0,libx11-6,libxcursor1,libxinerama1,libxrandr2,libxi6,libxext6,libxrender1,libxkbcommon0,libasound2,libfontconfig1,libdbus-1-3,libudev1" ;;
  # With Wine and Mesa. Debian 13's Wine 10: Debian 12's Wine 8 lacks bcryptprimitives.dll,
  # which Rust's standard library calls for random numbers on Windows 10 and later (what
  # Godot 4.6 needs too).
  windows) binary=counter-steer.exe runner=wine suite=trixie
    packages="$HARNESS,wine,wine64,libgl1-mesa-dri,libglx-mesa0" ;;
  *) die "usage: tools/export-check.sh [linux|windows]" ;;
esac
desktop="$CACHE_ROOT/$suite-desktop-$(printf '%s' "$packages" | sha256sum | cut -c1-12)"
if [ ! -x "$desktop/usr/bin/Xvfb" ]; then
  log "making a clean Debian $suite desktop root in $desktop (a few minutes, once)"
  rm -rf "$desktop.partial"
  as_root debootstrap --variant=minbase --include="$packages" "$suite" "$desktop.partial" \
    "$(debian_mirror)" >build/logs/export-check-debootstrap.log 2>&1 \
    || { tail -20 build/logs/export-check-debootstrap.log >&2; die "debootstrap of the desktop root failed"; }
  mv "$desktop.partial" "$desktop"
fi

if [ "$platform" = linux ]; then
  PORTABLE_TEMPLATE=1 tools/export.sh
  tools/glibc-baseline.sh build/linux/counter-steer.x86_64 build/linux/*.so
else
  tools/export-windows.sh
fi

game="$desktop/opt/counter-steer"
as_root rm -rf "$game" && as_root cp -r "build/$platform" "$game"
as_root install -m 755 tools/export-check-ride.sh "$desktop/opt/ride.sh"
log "riding the exported $platform game in the Debian $suite root"
# In mount and process namespaces of its own: /dev and /proc are mounted for the root
# alone, and whatever the ride leaves running ends with it.
as_root unshare --mount --pid --fork bash -c \
  'mount --bind /dev "$1/dev" && mount -t proc proc "$1/proc" &&
   exec chroot "$1" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/root /opt/ride.sh "$2" $3' \
  _ "$desktop" "$binary" "$runner" >"build/logs/export-check-$platform.log" 2>&1 \
  || { tail -40 "build/logs/export-check-$platform.log" >&2; die "the exported game did not ride in the Debian $suite root"; }
picture="build/screenshots/export-check$([ "$platform" = linux ] || echo "-$platform").png"
cp "$desktop/opt/ride.png" "$picture"
grep -E "^(native|Native|ride)" "build/logs/export-check-$platform.log"
log "export check passed: $picture"
