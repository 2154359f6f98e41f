@tool
class_name ReachJudge
extends ChallengeJudge
## Reach a goal box (the test level's own goal, say, as "../Goal"). The score is the time
## it took (s), from the first throttle.

## The box to reach.
@export var goal := NodePath("../Goal")

var _goal: GoalArea


func _begin() -> void:
	_goal = marker(goal, GoalArea) as GoalArea


func progress_text() -> String:
	if _goal == null:
		return ""
	var to_go := _goal.global_position - bike.get_center_of_mass()
	to_go.y = 0.0
	return "%d m to the goal" % roundi(maxf(to_go.length() - _goal.size.z / 2.0, 0.0))


func _judge(_delta: float) -> ChallengeResult:
	if _goal == null:
		return failed("this challenge is broken: " + problem)
	if not _goal.contains(bike.get_center_of_mass()):
		return null
	return passed_with(elapsed, ["reached the goal in %s" % Level.format_time(elapsed)])
