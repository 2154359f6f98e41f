#!/usr/bin/env bash
# The bot's gold rides of every lesson and challenge on every bike a player chooses
# (tests/survey/challenge_survey.tscn, ChallengeBot): what each scores and which medal,
# written anew as docs/challenges/bot-rides.csv, which docs/levels.md's table reads.
# About five minutes. Usage: tools/challenge-survey.sh [BIKE] (one bike, to a scratch file)
source "$(dirname "$0")/common.sh"
cd "$PROJECT_ROOT"
out=docs/challenges/bot-rides.csv
one=()
if [ $# -ge 1 ]; then one=(--bike="$1"); out=build/challenge-survey-$1.csv; fi
mkdir -p "$(dirname "$out")" build/logs
use_scratch_user_data challenge-survey
tools/godot --headless --path . --audio-driver Dummy --fixed-fps 60 \
  res://tests/survey/challenge_survey.tscn -- --out="$PROJECT_ROOT/$out.new" "${one[@]}" \
  >build/logs/challenge-survey.log 2>&1 \
  || { cat build/logs/challenge-survey.log >&2; die "the survey failed (build/logs/challenge-survey.log)"; }
tools/check-godot-log build/logs/challenge-survey.log
mv "$out.new" "$out"
log "wrote $out"
