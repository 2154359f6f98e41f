#!/usr/bin/env bash
# `make train`: the learned controller from nothing (docs/learned-controller.md).
#  1. The planner rides EPISODES seeded episodes as the expert (cpbp-learn generate),
#     LOG_EPISODES of the test level's ride (straight over logs), CARVING_EPISODES of
#     long hard turns at speed, BRAKING_EPISODES of full brakes from up to 90 km/h and
#     WHEELIE_EPISODES of wheelies, mostly onto platforms.
#  2. A network is trained on them (cpbp-learn train, candle).
#  3. DAgger, ROUNDS times: the latest network rides DAGGER_EPISODES new episodes,
#     DAGGER_LOG_EPISODES over logs, DAGGER_CARVING_EPISODES of carving,
#     DAGGER_BRAKING_EPISODES of braking and DAGGER_WHEELIE_EPISODES of wheelies while the
#     planner labels the states it visits, and a network is trained on everything so far.
#  4. The last network becomes the bike's model (models/policy-<bike>.safetensors, <bike>
#     the bike file's name: street_350, the reference, without BIKE) and the
#     training report is written (docs/learned/training.md, losses.png).
#     Every round's expert also recorded its plans for the planners' learned cost-to-go
#     (issue 59; `generate --values`): it is trained on all of them (cpbp-learn
#     train-value), then VALUE_ROUNDS (1) DAgger rounds of its own where the planner
#     drives on the short horizon it ends (DAGGER_EPISODES mixed, DAGGER_CARVING_EPISODES
#     carving and DAGGER_WHEELIE_EPISODES wheelies, seeds from (ROUNDS + R)*100000 + 1), into
#     models/value-<bike>.safetensors. VALUES=0 leaves it out. POLICY=0 trains the
#     cost-to-go alone, for a bike whose network landed before it did: the expert's round
#     only (ROUNDS=0), recorded, then the cost-to-go's rounds; the shipped policy and its
#     report stay, and the report's cost-to-go section is written anew.
#  5. Unless EVALUATE=0: learned and guided ride the test-level experiment and the
#     scenarios beside arcade and combined, paired on the same seeds, and those reports
#     are written again (docs/experiment, docs/scenarios).
# Seeds: round R (0 = the expert's) rides mixed episodes from R*100000 + 1, log
# episodes from R*100000 + 50001, carving from R*100000 + 70001, braking from
# R*100000 + 90001 and wheelies from R*100000 + 30001, so no two episodes of a run share
# a seed.
# EPOCHS and SEED override the trainer's defaults (cpbp-learn train --help).
# BIKE=all trains every bike's (below). BIKE=FILE (a bike file) trains a network of that
# bike: its episodes, checkpoints and report go to a folder and a model of the bike's own
# (models/policy-<name>.safetensors,
# docs/learned/<name>, <name> the bike file's, which the game and the tools load for that
# bike), and the game's evaluation, which rides the reference bike, is left out. A game's
# bike rides the game's speeds, up to 90 km/h: its run adds braking episodes (24 s each,
# the time to reach such speeds), which the reference's, ridden at the thesis's speeds up
# to 40 km/h, leaves out (BRAKING_EPISODES=0), so its model is made again as committed.
# Wheelies likewise: a game's bike rides them (the cost-to-go that the game's planner ends
# its plans with must know what a wheelie asked for costs: issue 59), the reference does
# not (WHEELIE_EPISODES=0).
# Every step resumes: episodes already saved are not ridden again, a finished round's
# model is kept, and the experiment and scenario runs resume. Data and checkpoints live
# in the cache (LEARN_DATA), never in git; `make clean` leaves them, `make clean-learn`
# removes them.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"

# BIKE=all: what the game ships, every bike's network: the reference's, then each bike file
# in scenes/bike/bikes/ (the ones a player chooses), one after another, each resuming as a
# run of its own does.
if [ "${BIKE:-}" = all ]; then
  BIKE= "$0"
  for file in scenes/bike/bikes/*.tres; do
    [ "$(basename "$file" .tres)" = street_350 ] || BIKE="$file" "$0"
  done
  exit 0
fi

POLICY="${POLICY:-1}"
if [ "$POLICY" = 0 ]; then
  [ "${VALUES:-1}" != 0 ] || die "POLICY=0 trains the cost-to-go alone; VALUES=0 leaves nothing"
  [ "${ROUNDS:-0}" = 0 ] || die "POLICY=0 rides the expert's round alone, not ROUNDS=$ROUNDS"
  ROUNDS=0 EVALUATE=0
fi
EPISODES="${EPISODES:-150}"
LOG_EPISODES="${LOG_EPISODES:-60}"
ROUNDS="${ROUNDS:-3}"
DAGGER_EPISODES="${DAGGER_EPISODES:-40}"
DAGGER_LOG_EPISODES="${DAGGER_LOG_EPISODES:-20}"
CARVING_EPISODES="${CARVING_EPISODES:-40}"
DAGGER_CARVING_EPISODES="${DAGGER_CARVING_EPISODES:-20}"
EVALUATE="${EVALUATE:-1}"
VALUES="${VALUES:-1}"
VALUE_ROUNDS="${VALUE_ROUNDS:-1}"
BRAKING_SECONDS=24
LEARN_DATA="${LEARN_DATA:-$CACHE_ROOT/learn}"
MODEL=models/policy-street_350.safetensors
REPORT=docs/learned
bike=()
values=()
[ "$VALUES" != 0 ] && values=(--values)
if [ -n "${BIKE:-}" ]; then
  [ -f "$BIKE" ] || die "BIKE=$BIKE: no such bike file"
  name=$(basename "$BIKE" .tres)
  bike=(--bike "$BIKE")
  LEARN_DATA="$LEARN_DATA-$name" MODEL="models/policy-$name.safetensors" REPORT="$REPORT/$name"
  EVALUATE=0
  BRAKING_EPISODES="${BRAKING_EPISODES:-30}"
  DAGGER_BRAKING_EPISODES="${DAGGER_BRAKING_EPISODES:-10}"
  WHEELIE_EPISODES="${WHEELIE_EPISODES:-30}"
  DAGGER_WHEELIE_EPISODES="${DAGGER_WHEELIE_EPISODES:-10}"
fi
# The cost-to-go beside the policy: models/value-<bike>.safetensors.
VALUE_MODEL="models/value-${name:-street_350}.safetensors"
BRAKING_EPISODES="${BRAKING_EPISODES:-0}"
DAGGER_BRAKING_EPISODES="${DAGGER_BRAKING_EPISODES:-0}"
WHEELIE_EPISODES="${WHEELIE_EPISODES:-0}"
DAGGER_WHEELIE_EPISODES="${DAGGER_WHEELIE_EPISODES:-0}"
learn=native/target/release/cpbp-learn

started=$(date +%s)
tools/cargo build --release --quiet -p cpbp-learn
mkdir -p "$LEARN_DATA" "$REPORT" models

# Trains round $1's network on the folders in $2 (comma-separated), unless it exists.
train_round() {
  local model="$LEARN_DATA/round-$1.safetensors"
  [ -f "$model" ] && { echo "round $1's network is already trained: $model"; return; }
  "$learn" train --data "$2" --model "$model" --losses "$LEARN_DATA/round-$1.losses.csv" \
    ${EPOCHS:+--epochs "$EPOCHS"} ${SEED:+--seed "$SEED"}
}

# Rides round $1's episodes into $2 (mixed), $2-logs, $2-carving, $2-braking and
# $2-wheelies: $3, $4, $5, $6 and $7 of them (none of the last two, no folder); $8 is the
# learner for DAgger (none for the expert's round).
ride_round() {
  local base=$(($1 * 100000)) learner=()
  [ -n "${8:-}" ] && learner=(--learner "$8")
  "$learn" generate --out "$2" --episodes "$((base + 1))-$((base + $3))" "${learner[@]}" \
    "${bike[@]}" "${values[@]}"
  "$learn" generate --out "$2-logs" --family logs \
    --episodes "$((base + 50001))-$((base + 50000 + $4))" "${learner[@]}" "${bike[@]}" \
    "${values[@]}"
  "$learn" generate --out "$2-carving" --family carving \
    --episodes "$((base + 70001))-$((base + 70000 + $5))" "${learner[@]}" "${bike[@]}" \
    "${values[@]}"
  [ "$6" -gt 0 ] && "$learn" generate --out "$2-braking" --family braking \
    --seconds "$BRAKING_SECONDS" --episodes "$((base + 90001))-$((base + 90000 + $6))" \
    "${learner[@]}" "${bike[@]}" "${values[@]}"
  [ "$7" -gt 0 ] || return 0
  "$learn" generate --out "$2-wheelies" --family wheelies \
    --episodes "$((base + 30001))-$((base + 30000 + $7))" "${learner[@]}" "${bike[@]}" \
    "${values[@]}"
}

# Round $1's folders (the expert's or a DAgger round's, $2), comma-separated.
round_folders() {
  local folders="$2,$2-logs,$2-carving" braking=$DAGGER_BRAKING_EPISODES
  local wheelies=$DAGGER_WHEELIE_EPISODES
  [ "$1" -eq 0 ] && braking=$BRAKING_EPISODES wheelies=$WHEELIE_EPISODES
  [ "$braking" -gt 0 ] && folders="$folders,$2-braking"
  [ "$wheelies" -gt 0 ] && folders="$folders,$2-wheelies"
  echo "$folders"
}

ride_round 0 "$LEARN_DATA/expert" "$EPISODES" "$LOG_EPISODES" "$CARVING_EPISODES" \
  "$BRAKING_EPISODES" "$WHEELIE_EPISODES"
folders=$(round_folders 0 "$LEARN_DATA/expert")
[ "$POLICY" = 0 ] || train_round 0 "$folders"
for round in $(seq 1 "$ROUNDS"); do
  ride_round "$round" "$LEARN_DATA/dagger-$round" "$DAGGER_EPISODES" "$DAGGER_LOG_EPISODES" \
    "$DAGGER_CARVING_EPISODES" "$DAGGER_BRAKING_EPISODES" "$DAGGER_WHEELIE_EPISODES" \
    "$LEARN_DATA/round-$((round - 1)).safetensors"
  folders="$folders,$(round_folders "$round" "$LEARN_DATA/dagger-$round")"
  train_round "$round" "$folders"
done

if [ "$POLICY" != 0 ]; then
  cp "$LEARN_DATA/round-$ROUNDS.safetensors" "$MODEL.partial"
  mv "$MODEL.partial" "$MODEL"
fi
# The cost-to-go: trained on every round's recorded plans (value-0), then VALUE_ROUNDS
# DAgger rounds of its own, where the game's planner drives on the short horizon that the
# latest cost-to-go ends (the states its own short plans lead to) while the full-horizon
# expert records its plans; the last is the bike's. Each network trained is kept.
if [ "$VALUES" != 0 ]; then
  value_folders=$folders
  for round in $(seq 0 "$VALUE_ROUNDS"); do
    if [ "$round" -gt 0 ]; then
      base=$(((ROUNDS + round) * 100000))
      short=(--short-planner "$LEARN_DATA/value-$((round - 1)).safetensors")
      "$learn" generate --out "$LEARN_DATA/short-$round" --values "${short[@]}" "${bike[@]}" \
        --episodes "$((base + 1))-$((base + DAGGER_EPISODES))"
      "$learn" generate --out "$LEARN_DATA/short-$round-carving" --family carving --values \
        "${short[@]}" "${bike[@]}" \
        --episodes "$((base + 70001))-$((base + 70000 + DAGGER_CARVING_EPISODES))"
      value_folders="$value_folders,$LEARN_DATA/short-$round,$LEARN_DATA/short-$round-carving"
      if [ "$DAGGER_WHEELIE_EPISODES" -gt 0 ]; then
        "$learn" generate --out "$LEARN_DATA/short-$round-wheelies" --family wheelies \
          --values "${short[@]}" "${bike[@]}" \
          --episodes "$((base + 30001))-$((base + 30000 + DAGGER_WHEELIE_EPISODES))"
        value_folders="$value_folders,$LEARN_DATA/short-$round-wheelies"
      fi
    fi
    value="$LEARN_DATA/value-$round.safetensors"
    [ -f "$value" ] || "$learn" train-value --data "$value_folders" --model "$value" \
      --losses "$LEARN_DATA/value-$round.losses.csv" ${EPOCHS:+--epochs "$EPOCHS"} \
      ${SEED:+--seed "$SEED"}
  done
  cp "$value" "$VALUE_MODEL.partial"
  mv "$VALUE_MODEL.partial" "$VALUE_MODEL"
fi
minutes=$(( ($(date +%s) - started + 59) / 60 ))

report() {
  if [ "$POLICY" = 0 ]; then
    .venv/bin/learned-report --value-only --data "$LEARN_DATA" --rounds 0 --model "$MODEL" \
      --out "$REPORT" --minutes "$minutes" --value-model "$VALUE_MODEL"
    return
  fi
  .venv/bin/learned-report --data "$LEARN_DATA" --rounds "$ROUNDS" \
    --model "$MODEL" --out "$REPORT" --minutes "$minutes" ${name:+--bike "$name"} \
    $([ "$VALUES" != 0 ] && echo --value-model "$VALUE_MODEL")
}
report

if [ "$EVALUATE" != 0 ]; then
  tools/build.sh
  # Rows of learned and guided ridden with an earlier model step aside (superseded/).
  .venv/bin/learned-evaluation --model "$MODEL"
  tools/experiment run --out docs/experiment --tries 30 --allow-mixed \
    --controllers arcade:exact,learned:exact,guided-4:exact,guided-5:exact,combined-5:exact,combined-15:exact
  tools/experiment report --out docs/experiment
  scenarios=turn,carve,slalom,push,walk,stop40,slope10
  tools/planner-scenarios run --out docs/scenarios --controllers learned,arcade --counts 5 \
    --scenarios "$scenarios"
  tools/planner-scenarios run --out docs/scenarios --controllers guided --counts 4,5 \
    --scenarios "$scenarios"
  tools/planner-scenarios run --out docs/scenarios --controllers combined --counts 5,15 \
    --scenarios "$scenarios"
  tools/planner-scenarios report --out docs/scenarios
  report
fi
[ "$POLICY" = 0 ] && MODEL=$VALUE_MODEL
echo "make train: done in $(( ($(date +%s) - started + 59) / 60 )) min; the model is $MODEL"
