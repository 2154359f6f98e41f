#!/bin/sh
# Runs inside the clean Debian root of tools/export-check.sh, as a player would: the
# exported game BINARY (run through RUNNER, Wine for the Windows build) started from its
# folder on an X display, the track picked in the start menu with the keyboard (the second
# level: Down, Enter), six seconds on the throttle (W), and a picture of the screen.
# Writes /opt/ride.png. Usage: ride.sh BINARY [RUNNER]
set -eu
binary=$1
runner=${2:-}
# A player's first start: no settings saved by an earlier check (the menu would open on
# the level picked last), and for Wine a fresh Windows user folder.
rm -rf "$HOME/.local/share/godot" "$HOME/.wine"
export WINEDEBUG=-all
cd /opt/counter-steer
$runner "./$binary" --headless --audio-driver Dummy -- --native-info 2>&1 | grep "^native" \
  || { echo "the native module did not load"; exit 1; }
# Without its native library the game says what is wrong and exits with 1: no crash.
rm -rf /opt/no-library && mkdir -p /opt/no-library
cp "$binary" counter-steer.pck /opt/no-library/
status=0
(cd /opt/no-library && $runner "./$binary" --headless --audio-driver Dummy -- --native-info) \
  >/opt/no-library.log 2>&1 || status=$?
grep "^Native module not loaded: " /opt/no-library.log && [ "$status" -eq 1 ] \
  || { cat /opt/no-library.log; echo "without its library the game exited $status"; exit 1; }

# This script is the first process of its own PID namespace: when it ends, the kernel kills
# what is left at once, so it waits for X to go. A lock left by a check that was killed
# anyway belongs to no server (none but ours can run in this namespace).
rm -f /tmp/.X7-lock /tmp/.X11-unix/X7
Xvfb :7 -screen 0 1280x720x24 -nolisten tcp >/opt/xvfb.log 2>&1 &
xvfb=$!
export DISPLAY=:7
sleep 2
$runner "./$binary" --resolution 1280x720 >/opt/game.log 2>&1 &
game=$!
trap 'kill $game $xvfb 2>/dev/null; wait 2>/dev/null || true' EXIT
window=$(xdotool search --sync --name "Counter-Steer" | head -n1)
xdotool windowfocus --sync "$window"
# The software renderer draws a few frames a second: give the menu time to appear.
sleep 10
xdotool key --window "$window" Down
sleep 2
xdotool key --window "$window" Return
sleep 20
xdotool keydown --window "$window" w
sleep 6
import -window root /opt/ride.png
xdotool keyup --window "$window" w
kill -0 "$game" || { cat /opt/game.log; echo "the game stopped"; exit 1; }
cat /opt/game.log
echo "ride: 6 s on the throttle after picking the track; picture in /opt/ride.png"
