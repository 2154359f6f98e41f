@tool
class_name TestLevel
extends Level
## The thesis's automatic test (§4.1.2, Figure 4.3): the bike rides straight with no turn
## command at a set speed across seeded random bumps, between walls for the first 25 m,
## and must reach the goal within the time limit without falling. The game and the
## headless experiment both use this level.

## Seconds to reach the goal.
@export_range(1.0, 120.0, 1.0, "suffix:s") var time_limit := 25.0

var _start := Vector3.ZERO

@onready var _bumps: BumpField = $Bumps
@onready var _goal: GoalArea = $Goal


func begin_attempt(bike: BikeSimulation, seed_value: int) -> void:
	super(bike, seed_value)
	_start = bike.get_center_of_mass()
	_bumps.regenerate(seed_value)
	terrain_changed.emit()


func judge(bike: BikeSimulation, delta: float) -> String:
	var outcome := super(bike, delta)
	if outcome != RIDING:
		return outcome
	if _goal.contains(bike.get_center_of_mass()):
		return GOAL
	if elapsed >= time_limit:
		return TIMEOUT
	return RIDING


## Metres the bike has come towards the goal since the attempt began.
func distance(bike: BikeSimulation) -> float:
	var towards_goal := _goal.global_position - _start
	towards_goal.y = 0.0
	return (bike.get_center_of_mass() - _start).dot(towards_goal.normalized())


func status_line() -> String:
	return "time %s / %s" % [format_time(elapsed), format_time(time_limit)]
