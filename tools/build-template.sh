#!/usr/bin/env bash
# Builds a portable Godot 4.6 Linux release template (the exported game's engine) and
# prints its path. Debian's godot source package, the private root's engine version, is
# compiled here on the host (Debian 12, glibc 2.36) with Godot's own portability options,
# as Godot's official Linux builds are made: X11, GL, audio, fonts, D-Bus, udev and speech
# opened at run time through Godot's dlopen wrappers (use_sowrap), the C++ runtime linked
# in, and the libraries Debian's repack strips from the source built statically from their
# own Debian source packages (tools/template-deps.sh). The result needs nothing newer than
# Debian 12's glibc and no library an ordinary desktop lacks.
#
# Cached in the provisioning cache under a key of this recipe. The work folder is kept
# between runs and recipes, so an interrupted or changed build picks up where it stopped:
# each library is stamped with the recipe it was built by, and SCons rebuilds only what
# changed.
source "$(dirname "$0")/common.sh"
source "$PROJECT_ROOT/tools/template-deps.sh"
source "$PROJECT_ROOT/tools/debian-sources.sh"
source "$PROJECT_ROOT/tools/template-common.sh"
lock_cache
ensure_host_packages dpkg-dev cmake ninja-build pkg-config g++ binutils python3-venv

template="$TEMPLATE_DIR/godot.linuxbsd.template_release.x86_64"
if [ -x "$template" ]; then echo "$template"; exit 0; fi
debian_sources_setup "$CACHE_ROOT/godot-template.work"
deps="$work/deps"
mkdir -p "$deps"
started=$(date +%s)

engine_version=$(tools/godot --headless --version | sed -n 's/^\([0-9]*\.[0-9]*\.[0-9]*\).*/\1/p')
[ -n "$engine_version" ] || die "cannot tell the private root's Godot version"
log "building a portable Godot $engine_version release template (about 50 minutes on 2 cores, once)"
fetch_source godot "$engine_version+ds"
deps_recipe=$(cat "$PROJECT_ROOT"/tools/template-{deps,common}.sh | sha256sum | cut -c1-12)
for name in $TEMPLATE_DEPENDENCIES; do
  [ "$(cat "$work/stamps/built-$name" 2>/dev/null)" = "$deps_recipe" ] && continue
  fetch_source "$name"
  log "  static $name"
  rm -rf "$work/src/$name/build-static"
  build_dependency "$name" "$work/src/$name"
  echo "$deps_recipe" >"$work/stamps/built-$name"
done

# SCons from PyPI; pkg-config asked for static link flags, so a library's own
# dependencies (freetype's brotli and zlib, SDL's libm) are linked too.
if [ ! -x "$work/venv/bin/scons" ]; then
  python3 -m venv "$work/venv"
  "$work/venv/bin/pip" install -q --disable-pip-version-check "scons==4.9.1"
fi
mkdir -p "$work/bin"
printf '#!/bin/sh\nexec /usr/bin/pkg-config --static "$@"\n' >"$work/bin/pkg-config"
chmod +x "$work/bin/pkg-config"

src="$work/src/godot"
# The repack strips the certificate bundle too; the template uses the system's.
mkdir -p "$src/thirdparty/certs" && touch "$src/thirdparty/certs/ca-bundle.crt"
scons_options=(
  platform=linuxbsd "-j$(nproc)" use_sowrap=yes
  # Rendering by OpenGL 3 (the project's compatibility renderer) under X11, which Wayland
  # desktops run too; the Vulkan renderer and the Wayland display are left out.
  wayland=no
  builtin_certs=no system_certs_path=/etc/ssl/certs/ca-certificates.crt
  "${TEMPLATE_COMMON_OPTIONS[@]}"
)
log "  compiling the engine (the long part; progress in $work/scons.log)"
(cd "$src" && PATH="$work/bin:$PATH" PKG_CONFIG_PATH="$deps/lib/pkgconfig" \
  BUILD_NAME="counter_steer.debian$(sed -n 's/^godot //p' "$work/versions")" \
  "$work/venv/bin/scons" "${scons_options[@]}" >"$work/scons.log" 2>&1) \
  || { tail -40 "$work/scons.log" >&2; die "the template did not build (log: $work/scons.log)"; }

built=$(ls "$src"/bin/godot.linuxbsd.template_release.x86_64* | head -n1)
[ -x "$built" ] || die "SCons finished without a template in $src/bin"
mkdir -p "$TEMPLATE_DIR"
cp "$work/versions" "$TEMPLATE_DIR/sources.txt"
echo "built in $(( ($(date +%s) - started) / 60 )) min (this run) on $(nproc) cores, $(date -u +%F)" \
  >"$TEMPLATE_DIR/build.txt"
install -m 755 "$built" "$template"
log "template ready: $template ($(du -h "$template" | cut -f1))"
echo "$template"
