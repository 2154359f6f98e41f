#!/usr/bin/env bash
# `make train`: the learned controller from nothing (docs/learned-controller.md).
#  1. The planner rides EPISODES seeded episodes as the expert (cpbp-learn generate).
#  2. A network is trained on them (cpbp-learn train, candle).
#  3. DAgger, ROUNDS times: the latest network rides DAGGER_EPISODES new episodes while
#     the planner labels the states it visits, and a network is trained on everything.
#  4. The last network becomes the project's model (models/policy.safetensors) and the
#     training report is written (docs/learned/training.md, losses.png).
#  5. Unless EVALUATE=0: learned and guided ride the test-level experiment and the
#     scenarios beside arcade and combined, paired on the same seeds, and those reports
#     are written again (docs/experiment, docs/scenarios).
# EPOCHS and SEED override the trainer's defaults (cpbp-learn train --help).
# Every step resumes: episodes already saved are not ridden again, a finished round's
# model is kept, and the experiment and scenario runs resume. Data and checkpoints live
# in the cache (LEARN_DATA), never in git; `make clean` leaves them, `make clean-learn`
# removes them.
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"

EPISODES="${EPISODES:-150}"
ROUNDS="${ROUNDS:-1}"
DAGGER_EPISODES="${DAGGER_EPISODES:-40}"
EVALUATE="${EVALUATE:-1}"
LEARN_DATA="${LEARN_DATA:-$CACHE_ROOT/learn}"
MODEL=models/policy.safetensors
REPORT=docs/learned
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

"$learn" generate --out "$LEARN_DATA/expert" --episodes "1-$EPISODES"
folders="$LEARN_DATA/expert"
train_round 0 "$folders"
for round in $(seq 1 "$ROUNDS"); do
  first=$((round * 100000 + 1))
  "$learn" generate --out "$LEARN_DATA/dagger-$round" \
    --episodes "$first-$((first + DAGGER_EPISODES - 1))" \
    --learner "$LEARN_DATA/round-$((round - 1)).safetensors"
  folders="$folders,$LEARN_DATA/dagger-$round"
  train_round "$round" "$folders"
done

cp "$LEARN_DATA/round-$ROUNDS.safetensors" "$MODEL.partial"
mv "$MODEL.partial" "$MODEL"
minutes=$(( ($(date +%s) - started + 59) / 60 ))

report() {
  .venv/bin/python tools/learned_report.py --data "$LEARN_DATA" --rounds "$ROUNDS" \
    --model "$MODEL" --out "$REPORT" --minutes "$minutes"
}
report

if [ "$EVALUATE" != 0 ]; then
  tools/build.sh
  tools/experiment run --out docs/experiment --tries 30 --allow-mixed \
    --controllers arcade:exact,learned:exact,guided-5:exact,combined-5:exact,combined-15:exact
  tools/experiment report --out docs/experiment
  scenarios=turn,slalom,push,walk,stop40,slope10
  tools/planner-scenarios run --out docs/scenarios --controllers learned,arcade --counts 5 \
    --scenarios "$scenarios"
  tools/planner-scenarios run --out docs/scenarios --controllers guided --counts 5 \
    --scenarios "$scenarios"
  tools/planner-scenarios run --out docs/scenarios --controllers combined --counts 5,15 \
    --scenarios "$scenarios"
  tools/planner-scenarios report --out docs/scenarios
  report
fi
echo "make train: done in $(( ($(date +%s) - started + 59) / 60 )) min; the model is $MODEL"
