#!/usr/bin/env bash
# A player's check of the exported game (make export-check): the Linux build, exported with
# the portable template (tools/build-template.sh), is unpacked into a clean Debian 12 root
# that has what an ordinary desktop has (X under Xvfb, Mesa, ALSA, fontconfig; none of
# Debian unstable's libraries, no private root), started there, driven to the track by
# the keyboard, ridden for a few seconds and photographed. Also checks that no shipped
# binary needs a glibc newer than Debian 12's.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
mkdir -p build/logs build/screenshots

# What a desktop has, plus the harness: Xvfb, xdotool to press keys, ImageMagick to take
# the picture.
DESKTOP_PACKAGES="xvfb,xauth,xdotool,imagemagick,libgl1,libegl1,libgl1-mesa-dri,libglx-mesa0,libx11-6,libxcursor1,libxinerama1,libxrandr2,libxi6,libxext6,libxrender1,libxkbcommon0,libasound2,libfontconfig1,fonts-dejavu-core,libdbus-1-3,libudev1,procps"
desktop="$CACHE_ROOT/bookworm-desktop-$(printf '%s' "$DESKTOP_PACKAGES" | sha256sum | cut -c1-12)"
if [ ! -x "$desktop/usr/bin/Xvfb" ]; then
  log "making a clean Debian 12 desktop root in $desktop (a few minutes, once)"
  rm -rf "$desktop.partial"
  as_root debootstrap --variant=minbase --include="$DESKTOP_PACKAGES" bookworm "$desktop.partial" \
    "$(debian_mirror)" >build/logs/export-check-debootstrap.log 2>&1 \
    || { tail -20 build/logs/export-check-debootstrap.log >&2; die "debootstrap of the desktop root failed"; }
  mv "$desktop.partial" "$desktop"
fi

PORTABLE_TEMPLATE=1 tools/export.sh
tools/glibc-baseline.sh build/linux/counter-steer.x86_64 build/linux/*.so

game="$desktop/opt/counter-steer"
as_root rm -rf "$game" && as_root cp -r build/linux "$game"
as_root install -m 755 tools/export-check-ride.sh "$desktop/opt/ride.sh"
log "riding the exported game in the Debian 12 root"
# In mount and process namespaces of its own: /dev and /proc are mounted for the root
# alone, and whatever the ride leaves running ends with it.
as_root unshare --mount --pid --fork bash -c \
  'mount --bind /dev "$1/dev" && mount -t proc proc "$1/proc" &&
   exec chroot "$1" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/root /opt/ride.sh' _ "$desktop" \
  >build/logs/export-check.log 2>&1 \
  || { tail -40 build/logs/export-check.log >&2; die "the exported game did not ride in the Debian 12 root"; }
cp "$desktop/opt/ride.png" build/screenshots/export-check.png
grep -E "^(native|Native|ride)" build/logs/export-check.log
log "export check passed: build/screenshots/export-check.png"
