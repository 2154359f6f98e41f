#!/usr/bin/env bash
# Exports the Windows build into build/windows/: counter-steer.exe, its pack and the native
# module cpbp.dll, with the release template cross-built by tools/build-windows.sh (which
# also builds the DLL). Then checks that neither the game nor the DLL needs a DLL that
# Windows does not have (MinGW's C++, GCC and thread runtimes are linked in).
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
out_dir=build/windows
mkdir -p "$out_dir" build/logs

template=$(tools/build-windows.sh)
version=$(tools/godot --headless --version | cut -d. -f1-4)
export XDG_DATA_HOME="$CACHE_ROOT/godot-data"
templates="$XDG_DATA_HOME/godot/export_templates/$version"
mkdir -p "$templates"
ln -sf "$template" "$templates/windows_release_x86_64.exe"

rm -rf "${out_dir:?}"/*
tools/godot --headless --path . --export-release "Windows" "$PROJECT_ROOT/$out_dir/counter-steer.exe" \
  >build/logs/export-windows.log 2>&1 || { cat build/logs/export-windows.log >&2; die "Windows export failed"; }
tools/check-godot-log build/logs/export-windows.log
for file in counter-steer.exe counter-steer.pck cpbp.dll; do
  [ -f "$out_dir/$file" ] || die "the Windows export has no $file"
done
# The credits and licences ship beside the game.
cp LICENSE CREDITS.md "$out_dir/"
runtime=$(objdump -p "$out_dir/counter-steer.exe" "$out_dir/cpbp.dll" | sed -n 's/^\tDLL Name: //p' \
  | grep -iE '^lib|mingw' || true)
[ -z "$runtime" ] || die "the Windows build needs DLLs Windows does not have: $runtime"
log "exported to $out_dir/counter-steer.exe ($(du -sh "$out_dir" | cut -f1))"
