#!/usr/bin/env bash
# Every check of the project, in order of speed; stops at the first failing step and ends
# with one line per step.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
mkdir -p build/logs
summary=()
step() {
  local name=$1; shift
  local started=$SECONDS
  printf '\n\033[1m== %s\033[0m\n' "$name"
  if "$@"; then
    summary+=("ok    $name ($((SECONDS - started)) s)")
  else
    summary+=("FAIL  $name")
    printf '\n%s\n' "${summary[@]}"
    die "step failed: $name"
  fi
}

# Every check runs Godot in a scratch data home (use_scratch_user_data); the player's own
# folder must come out of the run byte for byte as it went in: every entry's type, mode,
# size, time and path, and every file's hash.
player_data=$(player_user_data_dir)
player_data_listing() {
  [ -d "$player_data" ] || { echo "no folder"; return; }
  cd "$player_data" || return
  find . -printf '%y %m %s %T@ %p\n' | LC_ALL=C sort
  find . -type f -print0 | LC_ALL=C sort -z | xargs -0r sha256sum
}
player_data_before=$(player_data_listing)
player_data_unchanged() {
  diff <(printf '%s\n' "$player_data_before") <(player_data_listing) >&2 \
    || { echo "make test changed the player's files in $player_data (above)" >&2; return 1; }
  echo "unchanged: $player_data"
}

gdscript_files() { git ls-files -co --exclude-standard -- '*.gd'; }
godot_suites() {
  # A test that hangs (say, one that frees the runner) must fail the run, not stall CI.
  timeout 900 tools/run-suites.sh gdscript-suites 2>&1 | tee build/logs/gdscript-tests.log
  local status=${PIPESTATUS[0]}
  tools/check-godot-log build/logs/gdscript-tests.log --test-run && return "$status"
}

# README.md's "Running the tests" lists these steps from the comment above each (the doc
# check holds it equal): keep one comment per step saying what it checks.

# The preflight stops a machine whose Rust and Python are too old, naming both with how to
# install them, and builds nothing.
step "preflight self-test"  tools/preflight-selftest.sh
# The native workspace is formatted as rustfmt writes it.
step "rustfmt"              tools/cargo fmt --all --check
# Clippy finds nothing, warnings counted as errors, in every crate and test.
step "clippy"               tools/cargo clippy --workspace --all-targets --quiet -- -D warnings
# The Godot-free crates in debug: ODE's configuration and threads, bit-exact snapshots, the
# bike's physics, terrain of every shape, hostile controls, explosion recovery, the sound.
step "cargo test"           tools/cargo test --workspace --exclude cpbp-godot --exclude cpbp-learn
# In release, where minutes of planning are fast: the learned controller's pipeline (ride,
# train, the game's network equal to training's) and the controllers' ride tests. One cargo
# run for both packages: cargo resolves features per run, so two runs would build
# cpbp-core and its dependencies in release twice (about 5 minutes on CI).
step "learned pipeline and controller rides (release)" tools/cargo test --release \
  -p cpbp-learn -p cpbp-core --bin cpbp-learn --test rides
# The benchmark bicycle built from the game's bodies and tyres is the paper's bicycle.
step "bicycle benchmark"    .venv/bin/python -m unittest -v bicycle_benchmark.tests.test_bicycle_benchmark
# The experiment's statistics, results file and scheduling (no Godot needed).
step "experiment unit tests" .venv/bin/python -m unittest discover -s tools/cpbp_experiment/tests -t tools
# The sound check's pitch tracking, on made-up signals.
step "sound check unit tests" .venv/bin/python -m unittest sound_check.tests.test_sound_check
# The doc check itself, on made-up rows: a figure changed by hand fails, a missing file,
# heading or section fails.
step "doc check unit tests" .venv/bin/python -m unittest discover -s tools/doc_check/tests -t tools
# The committed docs: every marked figure equals the rows and every reference resolves.
step "docs against the rows and the tree" tools/doc-check
# The scenario tool's rows and paired statistics.
step "planner scenario unit tests" .venv/bin/python -m unittest discover -s tools/planner_scenarios/tests -t tools
# The learned controller's report tables and the upkeep of its evaluation's rows.
step "learned tools unit tests" .venv/bin/python -m unittest discover -s tools/learned_tools/tests -t tools
# Every GDScript file passes gdlint.
step "gdlint"               bash -c "$(declare -f gdscript_files); gdscript_files | xargs .venv/bin/gdlint"
# Every GDScript file is formatted as gdformat writes it.
step "gdformat"             bash -c "$(declare -f gdscript_files); gdscript_files | xargs .venv/bin/gdformat --check"
# The GDScript runner fails a deliberately failing fixture suite and counts it right.
step "test runner self-test" tools/test-runner-selftest.sh
# The GDScript suites under tests/, headless: the levels, menus, settings, medals, replay,
# ghosts, cameras, and the bot rides (a scripted rider rides a lap of the track, races its
# ghost, climbs the skate park's steps and stops on a foot through the player's own inputs,
# and earns gold in every lesson of the School and every level's challenge through a
# gamepad's events).
step "GDScript suites"      godot_suites
# Settings, records, medals, controls and a ghost saved in a loop and killed with SIGKILL
# read back whole.
step "saves survive kill -9" tools/kill-test.sh 8
# Quick mode with real workers: a run killed part-way resumes with nothing lost or doubled.
step "experiment quick run" .venv/bin/python -m unittest -v cpbp_experiment.tests.check_quick_run
# An attempt repeats exactly (fresh or after other rides, 1 or 2 threads); platforms do not
# mix unasked; verify catches a tampered row.
step "experiment reproducibility" .venv/bin/python -m unittest -v cpbp_experiment.tests.check_reproducible
# On a Dask cluster of two workers: the driver, then a worker process killed part-way;
# nothing lost or doubled, and the rows equal the local pool's.
step "experiment on a Dask cluster" .venv/bin/python -m unittest -v cpbp_experiment.tests.check_cluster
# Screenshots of the menus (the School on a first launch and with medals, a level's
# challenges), a lesson's briefing, medal and failed try, the levels, the telemetry
# overlay at 125 %, the Lab, the Controls screen, cameras, a full
# brake's tyre marks, a crash's sparks, a fall rewound, dust on the track's gravel,
# replay, ghost race, the planner's trajectories, each bike and the riders' stances and
# kits under Xvfb (tools/pictures.sh; `make pictures` puts them in docs/images/), failing
# on a blank picture or on a picture in docs/images/ that nothing draws (the ghost race
# races the lap the bot rode in the GDScript suites).
step "screenshots (Xvfb)"   tools/pictures.sh
# Each bike's engine recorded by Godot's movie writer sounds at the firing frequency of its
# layout (a four-stroke single, a two-stroke single, an inline four), rising with speed;
# a paused game is exactly silent.
step "bike sound (Xvfb)"    tools/sound-check.sh
# An export with Debian unstable's template, every resource converted afresh, started
# once: its native module loads and needs no glibc newer than 2.36 (make export-check
# rides the portable build by hand).
step "export + smoke run"   tools/export.sh
# The player's own Godot folder came out of the run exactly as it went in.
step "the player's files untouched" player_data_unchanged

printf '\n%s\n' "${summary[@]}"
