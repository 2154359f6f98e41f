@tool
class_name TestLevel
extends Level
## The thesis's automatic test (§4.1.2, Figure 4.3): the bike rides straight with no turn
## command at a set speed across seeded random bumps, between walls for the first 25 m,
## and must reach the goal within the time limit without falling. The game and the
## headless experiment both use this level.

## A steady ride at a set speed needs the course's length over that speed; an attempt's
## limit leaves it this much more time (at 5 km/h the course alone takes 26 s).
const SLOW_RIDE_MARGIN := 1.5

## Seconds to reach the goal.
@export_range(1.0, 120.0, 1.0, "suffix:s") var time_limit := 25.0

## The limit of the attempt under way (0: `time_limit`); `TestRun` sets it for its speed.
var attempt_time_limit := 0.0

var _start := Vector3.ZERO

@onready var _bumps: BumpField = $Bumps
@onready var _goal: GoalArea = $Goal
## The floor past the goal, where a bike that reached it brakes to a stop. Its shape is
## off during an attempt: the course is the thesis's, its floor ending 4 m past where the
## goal begins, which the planners' rollouts see as they near the goal.
@onready var _run_off: CollisionShape3D = $RunOff/Shape


func begin_attempt(bike: BikeSimulation, seed_value: int) -> void:
	super(bike, seed_value)
	_start = bike.get_center_of_mass()
	attempt_time_limit = 0.0
	_bumps.regenerate(seed_value)
	_run_off.disabled = true
	terrain_changed.emit()


## Past the goal the floor goes on, long enough to brake to a stop from the top of
## auto-accelerate's range (60 km/h at 0.75 g: 19 m).
func finish_attempt(outcome: String) -> void:
	if outcome == GOAL:
		_run_off.disabled = false
		terrain_changed.emit()


func judge(bike: BikeSimulation, delta: float) -> String:
	var outcome := super(bike, delta)
	if outcome != RIDING:
		return outcome
	if _goal.contains(bike.get_center_of_mass()):
		return GOAL
	if elapsed >= _limit():
		return TIMEOUT
	return RIDING


## The limit of an attempt auto-accelerated at `speed_kmh`: the thesis's `time_limit`, or
## longer below about 7 km/h, where the course itself takes most of it.
func time_limit_at(speed_kmh: float) -> float:
	var course := _goal.global_position - spawn_points()[0].global_position
	course.y = 0.0
	var speed := maxf(speed_kmh / 3.6, 0.1)
	return maxf(time_limit, SLOW_RIDE_MARGIN * course.length() / speed)


## Metres the bike has come towards the goal since the attempt began.
func distance(bike: BikeSimulation) -> float:
	var towards_goal := _goal.global_position - _start
	towards_goal.y = 0.0
	return (bike.get_center_of_mass() - _start).dot(towards_goal.normalized())


func status_line() -> String:
	return "time %s / %s" % [format_time(elapsed), format_time(_limit())]


func _limit() -> float:
	return attempt_time_limit if attempt_time_limit > 0.0 else time_limit
