#!/usr/bin/env bash
# Exports the Linux build into build/linux/ with the release template of the private
# Godot root (or the user's own templates when GODOT is set), then checks that the
# exported game starts and loads its native module, and that the native module needs no
# glibc newer than Debian 12's. With PORTABLE_TEMPLATE=1 the template is the portable one
# built from source (tools/build-template.sh), which runs on Debian 12 as it is: what
# `make export-check` ships.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
out_dir=build/linux
binary="$out_dir/counter-steer.x86_64"
mkdir -p "$out_dir" build/logs
use_scratch_user_data export

if [ -z "${GODOT:-}" ]; then
  # Godot finds templates under $XDG_DATA_HOME/godot/export_templates/<version>; point that
  # at the cache so nothing is written outside it.
  version=$(tools/godot --headless --version | cut -d. -f1-4)
  export XDG_DATA_HOME="$CACHE_ROOT/godot-data"
  templates="$XDG_DATA_HOME/godot/export_templates/$version"
  mkdir -p "$templates"
  release_template="$GODOT_ROOT/usr/bin/godot-template-release"
  if [ -n "${PORTABLE_TEMPLATE:-}" ]; then release_template=$(tools/build-template.sh); fi
  ln -sf "$release_template" "$templates/linux_release.x86_64"
  ln -sf "$GODOT_ROOT/usr/bin/godot-template-debug" "$templates/linux_debug.x86_64"
fi

rm -rf "${out_dir:?}"/*
# Convert every resource afresh, as a clean clone does: a script that stays loaded past the
# exit shows only when its resources are converted, not from the cache of an export before.
rm -rf .godot/exported
tools/godot --headless --path . --export-release "Linux" "$PROJECT_ROOT/$binary" >build/logs/export.log 2>&1 \
  || { cat build/logs/export.log >&2; die "export failed"; }
tools/check-godot-log build/logs/export.log
[ -x "$binary" ] || die "the export produced no $binary"
# The credits and licences ship beside the game.
cp LICENSE CREDITS.md "$out_dir/"

# Start the exported game once. Here its binary needs the private root's newer glibc; run
# through that root's loader it would take the loader for itself and miss its .pck and
# native library, so a copy gets the root's interpreter and libraries instead. The
# shipped files are left as they are.
smoke="build/export-smoke"
smoke_binary="$smoke/$(basename "$binary")"
rm -rf "$smoke"; cp -r "$out_dir" "$smoke"
run_env=()
if [ -z "${GODOT:-}" ] && [ -z "${PORTABLE_TEMPLATE:-}" ]; then
  patchelf --set-interpreter "$GODOT_ROOT/usr/lib64/ld-linux-x86-64.so.2" "$smoke_binary"
  libs="$GODOT_ROOT/usr/lib/x86_64-linux-gnu"
  run_env=(LD_LIBRARY_PATH="$libs:$libs/pulseaudio")
fi
use_scratch_user_data export-smoke-run
timeout 120 env "${run_env[@]}" "$smoke_binary" --headless --audio-driver Dummy -- --native-info >build/logs/export-run.log 2>&1 \
  || { cat build/logs/export-run.log >&2; die "the exported game did not start with its native module"; }
tools/check-godot-log build/logs/export-run.log --release-template
grep "^native " build/logs/export-run.log
tools/glibc-baseline.sh "$out_dir"/*.so
log "exported to $binary ($(du -sh "$out_dir" | cut -f1))"
