#!/usr/bin/env bash
# Draws every picture of the game the docs show, from the game as it is now, under Xvfb
# (tools/screenshot.sh: each fails on a blank picture), into build/screenshots/; make test
# runs it so every picture is drawn by every run. `--docs` (make pictures) then puts them
# in docs/images/, the galleries laid out by tools/picture_compose.py, so no picture there
# is older than the code it shows. Pictures drawn by other tools are listed in MADE_ELSEWHERE
# with the command that draws them; a picture in docs/images/ that nothing draws fails.
# Usage: tools/pictures.sh [--docs]
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
mkdir -p build/screenshots
shots=build/screenshots

# docs/images/ pictures other tools draw, with the command that draws each.
declare -A MADE_ELSEWHERE=(
  [auto-trajectories.png]="a real-time ride's window (make play, telemetry on): a capture waits for every plan, so it cannot show what auto chooses in time"
  [benchmark-bicycle.png]="tools/bicycle-benchmark --chart docs/images/benchmark-bicycle.png"
  [look-before-after.png]="a before/after of issue 101's world, from two trees (docs/levels.md)"
  [bikes-before-after.png]="a before/after of issue 101's bikes, from two trees (docs/bike-model.md)"
)

draw_screenshots() {
  local game=res://scenes/game/game.tscn levels=res://scenes/levels
  local lessons=res://scenes/challenges/lessons
  tools/screenshot.sh res://scenes/ui/start_menu.tscn build/screenshots/start-menu.png \
    && tools/screenshot.sh res://scenes/ui/start_menu.tscn build/screenshots/school.png 30 \
         "--copy=res://tests/fixtures/medals/some_medals.cfg>user://test-medals.cfg" \
    && tools/screenshot.sh res://scenes/ui/start_menu.tscn build/screenshots/level-challenges.png 30 \
         "--copy=res://tests/fixtures/medals/level_medals.cfg>user://test-medals.cfg" \
    && tools/screenshot.sh $game build/screenshots/lesson-briefing.png 60 \
         --set=challenge_path=$lessons/counter_steer.tres \
    && tools/screenshot.sh $game build/screenshots/lesson-medal.png 790 \
         --set=challenge_path=$lessons/ride_off.tres --hold=throttle:0.5@0-117 \
         --hold=brake:1.0@689-790 \
    && tools/screenshot.sh $game build/screenshots/lesson-failed.png 300 \
         --set=challenge_path=$lessons/ride_off.tres --hold=throttle:0.5 \
    && tools/screenshot.sh $game build/screenshots/test-level.png 150 \
         --set=level_path=$levels/test_level/test_level.tscn \
    && tools/screenshot.sh $game build/screenshots/track.png 240 \
         --set=level_path=$levels/track/track.tscn --hold=throttle:0.7 \
    && tools/screenshot.sh $game build/screenshots/telemetry.png 240 \
         --set=level_path=$levels/track/track.tscn --hold=throttle:0.7 \
         --setting=telemetry=true --setting=ui_scale=125 \
    && tools/screenshot.sh $game build/screenshots/track-low.png 240 \
         --set=level_path=$levels/track/track.tscn --hold=throttle:0.7 \
         --setting=graphics_quality=low \
    && tools/screenshot.sh $game build/screenshots/skate-park.png 150 \
         --set=level_path=$levels/skate_park/skate_park.tscn --tap=next_spawn@5 --hold=throttle:0.6 \
    && tools/screenshot.sh $game build/screenshots/tyre-marks.png 235 \
         --set=level_path=$levels/track/track.tscn --hold=throttle:1.0@5-150 \
         --hold=brake:1.0@150-235 \
    && tools/screenshot.sh $game build/screenshots/crash.png 214 \
         --set=level_path=$levels/track/track.tscn --call=Bike:set_controller:manual@140 \
         --hold=throttle:1.0@5-150 --hold=steer_right:1.0@150-175 \
    && tools/screenshot.sh $game build/screenshots/rewind.png 345 \
         --set=level_path=$levels/track/track.tscn --call=Bike:set_controller:manual@200 \
         --hold=throttle:0.6@0-400 --hold=steer_left:0.5@210-220 --tap=rewind@330 \
    && tools/screenshot.sh $game build/screenshots/dust.png 285 \
         --set=level_path=$levels/track/track.tscn --tap=next_spawn@5 --tap=next_spawn@10 \
         --hold=throttle:1.0@15- \
    && tools/screenshot.sh $game build/screenshots/pause-menu.png 60 \
         --set=level_path=$levels/track/track.tscn --tap=pause@40 \
    && tools/screenshot.sh $game build/screenshots/lab.png 70 \
         --set=level_path=$levels/track/track.tscn --tap=pause@40 --call=PauseMenu:open_lab@45 \
    && tools/screenshot.sh $game build/screenshots/controls.png 70 \
         --set=level_path=$levels/track/track.tscn --tap=pause@40 \
         --call=PauseMenu:open_controls@45 \
    && tools/screenshot.sh $game build/screenshots/camera-low-side.png 200 \
         --set=level_path=$levels/track/track.tscn --hold=throttle:0.7 --hold=steer_right:0.4 \
         --tap=cycle_camera@5 \
    && tools/screenshot.sh $game build/screenshots/camera-helmet.png 200 \
         --set=level_path=$levels/track/track.tscn --hold=throttle:0.7 --hold=steer_right:0.4 \
         --tap=cycle_camera@5 --tap=cycle_camera@8 \
    && tools/screenshot.sh $game build/screenshots/replay.png 330 \
         --set=level_path=$levels/track/track.tscn --hold=throttle:0.6 --hold=rider_back:0.4 \
         --tap=pause@200 --tap=ui_down@205 --tap=ui_down@208 --tap=ui_accept@212 \
    && tools/screenshot.sh $game build/screenshots/rider-foot-down.png 400 \
         --set=level_path=$levels/skate_park/skate_park.tscn --hold=throttle:0.5@0-100 \
         --hold=brake:0.6@100- --hold=camera_left:0.5@150-175 \
    && tools/screenshot.sh $game build/screenshots/ghost-race.png 190 \
         --set=level_path=$levels/track/track.tscn --hold=throttle:0.6 \
         "--copy=res://build/ghosts/track.ghost>user://test-ghosts/track.ghost" \
    && tools/screenshot.sh $game build/screenshots/sandbox-trajectories.png 200 \
         --set=level_path=$levels/track/track.tscn --setting=controller=combined \
         --setting=show_trajectories=true --setting=telemetry=true --hold=throttle:0.7 \
         --hold=steer_right:0.5@120- \
    && bike_gallery \
    && rider_stances
}

# Each bike a player chooses, leaning into the track's first bend (the README's gallery).
bike_gallery() {
  local bike
  for bike in street_390 dirt_125 sport_600; do
    tools/screenshot.sh res://scenes/game/game.tscn build/screenshots/bike-$bike.png 200 \
      --set=level_path=res://scenes/levels/track/track.tscn --setting=bike=$bike \
      --hold=throttle:0.7 --hold=steer_right:0.4 --tap=cycle_camera@5 || return 1
  done
}


# Each bike a player chooses, leaning into the track's first bend (the README's gallery).
bike_gallery() {
  local bike
  for bike in street_390 dirt_125 sport_600; do
    tools/screenshot.sh res://scenes/game/game.tscn $shots/bike-$bike.png 200 \
      --set=level_path=res://scenes/levels/track/track.tscn --setting=bike=$bike \
      --hold=throttle:0.7 --hold=steer_right:0.4 --tap=cycle_camera@5 || return 1
  done
}

# The riders' stances and kits: the sport 600's rider hanging off past 30 degrees of lean
# (the chase camera, a right bend), the dirt 125's standing on the pegs off the skate
# park's kicker, and the road and motocross kits from the side.
rider_stances() {
  local game=res://scenes/game/game.tscn levels=res://scenes/levels
  tools/screenshot.sh $game $shots/rider-hang-off.png 230 \
      --set=level_path=$levels/track/track.tscn --setting=bike=sport_600 \
      --hold=throttle --hold=steer_right@110-230 \
    && tools/screenshot.sh $game $shots/rider-standing.png 200 \
      --set=level_path=$levels/skate_park/skate_park.tscn --setting=bike=dirt_125 \
      --setting=camera=low_side --hold=throttle \
    && tools/screenshot.sh $game $shots/rider-road-kit.png 230 \
      --set=level_path=$levels/track/track.tscn --setting=bike=street_390 \
      --setting=camera=low_side --hold=throttle --hold=steer_right@110-230 \
    && tools/screenshot.sh $game $shots/rider-motocross-kit.png 230 \
      --set=level_path=$levels/track/track.tscn --setting=bike=dirt_125 \
      --setting=camera=low_side --hold=throttle --hold=steer_right@110-230
}

# The galleries tools/picture_compose.py lays out of the screenshots, by the name each has
# in docs/images/.
GALLERIES=(bikes.png riders.png)

# Fails on a picture in docs/images/ that nothing draws: neither a screenshot above, nor a
# gallery, nor another tool's.
check_recipes() {
  local picture name
  for picture in docs/images/*.png; do
    name=$(basename "$picture")
    [[ -f $shots/$name || -n ${MADE_ELSEWHERE[$name]:-} || " ${GALLERIES[*]} " == *" $name "* ]] \
      || die "docs/images/$name: nothing draws it (add its recipe to tools/pictures.sh)"
  done
}

# Puts the pictures in docs/images/: each screenshot the docs show, and the galleries.
to_docs() {
  local compose=(.venv/bin/python tools/picture_compose.py) picture name
  for picture in docs/images/*.png; do
    name=$(basename "$picture")
    [[ -f $shots/$name ]] && cp "$shots/$name" "$picture"
  done
  "${compose[@]}" docs/images/bikes.png --height=360 \
    $shots/bike-street_390.png $shots/bike-dirt_125.png $shots/bike-sport_600.png \
    && "${compose[@]}" docs/images/riders.png --height=400 \
      "$shots/rider-hang-off.png@420,280,240,200" "$shots/rider-standing.png@480,200,240,240" \
      "$shots/rider-road-kit.png@360,220,340,230" "$shots/rider-motocross-kit.png@360,220,340,230" \
    || die "laying out the galleries failed"
  log "docs/images/ redrawn from the game; look at them before committing"
}

draw_screenshots || die "a picture failed"
check_recipes
[[ ${1:-} == --docs ]] && to_docs
exit 0
