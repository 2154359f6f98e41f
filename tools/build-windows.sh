#!/usr/bin/env bash
# Builds the Windows pieces of the export and prints the release template's path: the
# native module as addons/cpbp/bin/cpbp.dll and a Godot 4.6 Windows release template, both
# cross-compiled with MinGW-w64 from Debian's sources (tools/windows-build-inside.sh).
#
# Debian ships no Windows Rust standard library for its own Rust (libstd-rust-dev-windows
# is in no suite this mirror serves), but it ships Rust's library source (rust-src), so
# the standard library is built for Windows with Cargo's build-std, as Rust's own
# Windows targets are bootstrapped. That and MinGW-w64 need Debian unstable: a private
# root here, as for Godot (tools/provision-godot.sh), entered with chroot.
#
# The template is cached under a key of the recipe; the work inside the root (/build) is
# kept, so an interrupted build resumes: stamped steps are skipped and SCons is incremental.
source "$(dirname "$0")/common.sh"
source "$PROJECT_ROOT/tools/debian-sources.sh"
lock_cache
ensure_host_packages debootstrap dpkg-dev

root="$WINDOWS_ROOT"
template="$WINDOWS_TEMPLATE_DIR/godot.windows.template_release.x86_64.exe"
if [ ! -f "$root/.complete" ]; then
  log "making the Windows toolchain root in $root (a few minutes, ~2 GB, once)"
  as_root rm -rf "$root.partial"
  as_root debootstrap --variant=minbase --include="$WINDOWS_ROOT_PACKAGES" sid "$root.partial" \
    "$(debian_mirror)" >"$CACHE_ROOT/windows-debootstrap.log" 2>&1 \
    || { tail -20 "$CACHE_ROOT/windows-debootstrap.log" >&2; die "debootstrap of the Windows root failed"; }
  touch "$root.partial/.complete"
  mv "$root.partial" "$root"
fi
# Cargo inside fetches crates from crates.io: with the host's name servers and the
# certificates the host trusts.
as_root cp /etc/resolv.conf "$root/etc/resolv.conf"
as_root cp /etc/ssl/certs/ca-certificates.crt "$root/etc/ssl/certs/ca-certificates.crt"

started=$(date +%s)
debian_sources_setup "$CACHE_ROOT/windows-build.work"
engine_version=$(tools/godot --headless --version | sed -n 's/^\([0-9]*\.[0-9]*\.[0-9]*\).*/\1/p')
[ -n "$engine_version" ] || die "cannot tell the private root's Godot version"
build="$root/build"
mkdir -p "$build/src"
source "$PROJECT_ROOT/tools/template-common.sh"
for name in "godot $engine_version+ds" "ode 2:$ODE_VERSION_WANTED" $TEMPLATE_DEPENDENCIES; do
  set -- $name
  fetch_source "$1" "${2:-}"
  [ -d "$build/src/$1" ] || cp -a "$work/src/$1" "$build/src/$1"
done
rm -rf "$build/tools" && mkdir -p "$build/tools"
cp -r tools/windows-*.sh tools/template-common.sh tools/ode-patches tools/windows-static-libraries "$build/tools/"
# The project's native code, without its Linux build products; Windows' own are kept.
mkdir -p "$build/native"
tar -C native --exclude=./target -cf - . | tar -C "$build/native" -xf -
# And the project files it includes from outside native/ (include_str!: the reference
# bike's file, the test level's log field), at the same paths relative to it.
grep -rlE --include='*.rs' --exclude-dir=target 'include_(str|bytes)!\(' native \
  | while read -r source; do
      grep -oE 'include_(str|bytes)!\("[^"]+"\)' "$source" | sed -E 's/.*\("([^"]+)"\)/\1/' \
        | while read -r included; do
            file=$(realpath --relative-to=. "$(dirname "$source")/$included")
            case $file in native/*) ;; *) install -D -m 644 "$file" "$build/$file" ;; esac
          done
    done

skip_template=
if [ -f "$template" ]; then skip_template=1; else
  log "building the Windows native module and a Godot $engine_version Windows release template (about 30 minutes on 2 cores, once)"
fi
as_root unshare --mount --fork bash -c \
  'mount -t proc proc "$1/proc" &&
   exec chroot "$1" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/root SKIP_TEMPLATE="$2" \
     BUILD_NAME="$3" bash /build/tools/windows-build-inside.sh' \
  _ "$root" "$skip_template" "counter_steer.debian$(sed -n 's/^godot //p' "$work/versions")" >&2 \
  || die "the Windows build failed (SCons log: $build/scons.log)"

install -m 644 "$build/out/cpbp.dll" addons/cpbp/bin/cpbp.dll
if [ -z "$skip_template" ]; then
  mkdir -p "$WINDOWS_TEMPLATE_DIR"
  grep -E "^(godot|ode|$(echo $TEMPLATE_DEPENDENCIES | tr ' ' '|')) " "$work/versions" >"$WINDOWS_TEMPLATE_DIR/sources.txt"
  echo "built in $(( ($(date +%s) - started) / 60 )) min (this run) on $(nproc) cores, $(date -u +%F)" \
    >"$WINDOWS_TEMPLATE_DIR/build.txt"
  install -m 755 "$build/out/godot.windows.template_release.x86_64.exe" "$template"
  log "Windows template ready: $template ($(du -h "$template" | cut -f1))"
fi
echo "$template"
