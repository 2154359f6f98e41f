#!/bin/sh
# Runs inside the clean Debian 12 root of tools/export-check.sh, as a player would: the
# exported game started from its folder on an X display, the track picked in the start
# menu with the keyboard (the second level: Down, Enter), five seconds on the throttle (W),
# and a picture of the screen. Writes /opt/ride.png.
set -eu
# A player's first start: no settings saved by an earlier check (the menu would open on
# the level picked last).
rm -rf "$HOME/.local/share/godot"
cd /opt/counter-steer
./counter-steer.x86_64 --headless --audio-driver Dummy -- --native-info 2>&1 | grep "^native" \
  || { echo "the native module did not load"; exit 1; }
# Without its native library the game says what is wrong and exits with 1: no crash.
mkdir -p /opt/no-library
cp counter-steer.x86_64 counter-steer.pck /opt/no-library/
status=0
/opt/no-library/counter-steer.x86_64 --headless --audio-driver Dummy -- --native-info \
  >/opt/no-library.log 2>&1 || status=$?
grep "^Native module not loaded: libcpbp.so" /opt/no-library.log && [ "$status" -eq 1 ] \
  || { cat /opt/no-library.log; echo "without its library the game exited $status"; exit 1; }

Xvfb :7 -screen 0 1280x720x24 -nolisten tcp >/opt/xvfb.log 2>&1 &
xvfb=$!
export DISPLAY=:7
sleep 2
./counter-steer.x86_64 --resolution 1280x720 >/opt/game.log 2>&1 &
game=$!
trap 'kill $game $xvfb 2>/dev/null || true' EXIT
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
