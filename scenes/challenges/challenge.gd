@tool
class_name Challenge
extends Resource
## One lesson or challenge, as data: where it is ridden, what the player is told, how the
## ride is judged and the medals' thresholds, each named. A designer adds one as a file
## listed in the catalogue (scenes/challenges/catalogue.tres; docs/levels.md says how).

enum Medal { NONE, BRONZE, SILVER, GOLD }

const MEDAL_NAMES: Array[String] = ["no medal", "bronze", "silver", "gold"]

## Its name in menus.
@export var title := ""
## What to do, in one line, shown before the ride starts.
@export_multiline var brief := ""
## The level scene it is ridden on.
@export_file("*.tscn") var level := ""
## The level's ChallengeArea it is ridden in: its spawn point and markers.
@export var area := NodePath()
## How the ride is judged.
@export var judge: ChallengeJudge
## What the score measures, for people ("distance from the box's middle"), and its unit.
@export var score_name := ""
@export var unit := "m"
## Whether a smaller score is better (a time, a distance short) or a larger one (a lean).
@export var lower_is_better := true
## The score each medal needs.
@export var bronze := 0.0
@export var silver := 0.0
@export var gold := 0.0
## Where the thresholds come from: the bot's measured scores and the margin given.
@export_multiline var thresholds_note := ""
## Seconds the ride may take from the first throttle.
@export_range(5.0, 600.0, 1.0, "suffix:s") var time_limit := 60.0
## The controls that matter here, shown before and during the ride: any of throttle,
## brake, turn, weight.
@export var inputs := PackedStringArray(["throttle", "brake"])
## Top speed (km/h) full throttle asks for here; 0 keeps the player's setting.
@export_range(0.0, 90.0, 1.0, "suffix:km/h") var top_speed_kmh := 0.0


## The key its medals are saved under: its file's name.
func key() -> String:
	return resource_path.get_file().get_basename()


## The medal `score` earns (NONE for a score that is not a number).
func medal_for(score: float) -> Medal:
	if not is_finite(score):
		return Medal.NONE
	for medal: Medal in [Medal.GOLD, Medal.SILVER, Medal.BRONZE]:
		if reaches(score, threshold(medal)):
			return medal
	return Medal.NONE


## Whether `score` is as good as `bar` or better.
func reaches(score: float, bar: float) -> bool:
	return score <= bar if lower_is_better else score >= bar


## The score `medal` needs.
func threshold(medal: Medal) -> float:
	return [INF, bronze, silver, gold][medal]


## "gold ≤ 0.30 m · silver ≤ 0.70 m · bronze ≤ 1.50 m", for the briefing.
func thresholds_text() -> String:
	var parts := PackedStringArray()
	for medal: Medal in [Medal.GOLD, Medal.SILVER, Medal.BRONZE]:
		parts.append(
			(
				"%s %s %s"
				% [MEDAL_NAMES[medal], "≤" if lower_is_better else "≥", format(threshold(medal))]
			)
		)
	return " · ".join(parts)


## What the score measures, as a label begins ("Distance short of the line").
func score_label() -> String:
	return score_name.left(1).to_upper() + score_name.substr(1)


## `score` as the player reads it, in the challenge's unit.
func format(score: float) -> String:
	if not is_finite(score):
		return "–"
	match unit:
		"s":
			return "%.2f s" % score
		"°":
			return "%.1f°" % score
		"km/h":
			return "%d km/h" % roundi(score)
	return "%.2f %s" % [score, unit]


## What keeps it from being ridden, for the menu ("its level … is missing"); empty: nothing.
func problem() -> String:
	if level.is_empty() or not ResourceLoader.exists(level, "PackedScene"):
		return "its level %s is missing" % level
	if judge == null:
		return "it has no judge"
	if area.is_empty():
		return "it names no area of its level"
	return ""
