#!/usr/bin/env bash
# Builds the native extension (release), installs it into addons/cpbp/bin/ and lets Godot
# import the project (class cache, extension list) so scenes and tests can run.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
tools/cargo build --release -p cpbp-godot --quiet
mkdir -p addons/cpbp/bin build/logs
# Keep Godot from scanning build products.
touch build/.gdignore
built=native/target/release/libcpbp.so
installed=addons/cpbp/bin/libcpbp.so
if ! cmp -s "$built" "$installed"; then
  cp "$built" "$installed.tmp" && mv "$installed.tmp" "$installed"
fi
use_scratch_user_data import
first_import=true
[ -f .godot/extension_list.cfg ] && first_import=false
if ! tools/godot --headless --path . --import >build/logs/import.log 2>&1; then
  # Godot 4.6's headless editor crashes at exit the first time it discovers a GDExtension
  # (godotengine/godot#111048, #123511); the import itself is complete and a second run
  # exits cleanly. Any other failure, or a second crash, is an error.
  $first_import || { cat build/logs/import.log >&2; die "Godot could not import the project"; }
  tools/godot --headless --path . --import >build/logs/import.log 2>&1 \
    || { cat build/logs/import.log >&2; die "Godot could not import the project"; }
fi
tools/check-godot-log build/logs/import.log
