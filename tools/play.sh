#!/usr/bin/env bash
# Launches the game window. Needs a display; says how to get one when there is none.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  cat >&2 <<'MSG'
[play] No display found (neither DISPLAY nor WAYLAND_DISPLAY is set), so the game window
       cannot open. On a machine without a screen, run it under a virtual display:
         xvfb-run -a -s "-screen 0 1280x720x24" make play
       or take a screenshot of a scene with:
         tools/screenshot.sh res://scenes/ui/start_menu.tscn build/screenshots/start-menu.png
MSG
  exit 1
fi
exec tools/godot --path . "$@"
