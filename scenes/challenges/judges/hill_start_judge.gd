@tool
class_name HillStartJudge
extends ChallengeJudge
## A hill start: stop in the box on the way up, stand there on a foot for a while, then
## pull away uphill through the finish. The score is how far the bike rolled back pulling
## away (m, from where it stood).

## The box to stop in (on the slope) and the line over the top.
@export var box := NodePath("StopBox")
@export var finish_line := NodePath("Finish")
## Seconds to stand still in the box before pulling away.
@export_range(0.5, 30.0, 0.5, "suffix:s") var stand_seconds := 3.0

var _box: GoalArea
var _finish: MarkLine
## Where the bike stood, how long it has, and the furthest back it came after (m along
## the way up from there).
var _stood_at := Vector3.INF
var _stood_for := 0.0
var _rolled_back := 0.0


func _begin() -> void:
	_box = marker(box, GoalArea) as GoalArea
	_finish = marker(finish_line, MarkLine) as MarkLine
	_stood_at = Vector3.INF
	_stood_for = 0.0
	_rolled_back = 0.0


func progress_text() -> String:
	if _stood_for <= 0.0:
		return "stop in the box on the hill"
	if _stood_for < stand_seconds:
		return "stand still: %.1f s of %.0f" % [_stood_for, stand_seconds]
	return "pull away uphill"


func _judge(delta: float) -> ChallengeResult:
	if _box == null or _finish == null:
		return failed("this lesson is broken: " + problem)
	var centre := bike.get_center_of_mass()
	var standing := _stood_for >= stand_seconds
	if not standing:
		if stopped() and _box.contains(centre):
			_stood_at = centre if _stood_for <= 0.0 else _stood_at
			_stood_for += delta
		elif _stood_for > 0.0:
			return failed(
				(
					"you stood %.1f s: stand still %.0f s before pulling away"
					% [_stood_for, stand_seconds]
				)
			)
		elif _finish.distance_past(centre) >= 0.0:
			return failed("you rode up without stopping in the box")
		return null
	var uphill := -_finish.global_basis.z
	_rolled_back = maxf(_rolled_back, -(centre - _stood_at).dot(uphill))
	if _finish.distance_past(centre) < 0.0:
		return null
	var facts := PackedStringArray(
		["stood %.1f s, rolled back %.2f m" % [_stood_for, _rolled_back]]
	)
	return passed_with(_rolled_back, facts)
