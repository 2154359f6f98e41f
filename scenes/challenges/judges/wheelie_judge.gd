@tool
class_name WheelieJudge
extends ChallengeJudge
## The rider's weight: lift the front wheel before a log and keep it up until it is past,
## then ride on through the finish. The score is the longest wheelie (m ridden on the rear
## wheel alone); a front wheel that touches down at the log fails. Without a log (an empty
## `log_line`) it is a wheelie for distance.

## The line across the log (the log itself is the level's; empty: none), and the line to
## ride through.
@export var log_line := NodePath("LogLine")
@export var finish_line := NodePath("Finish")
## Radius of the log (m): the front tyre touches it when its centre is nearer than the
## wheel's and the log's radii together.
@export_range(0.02, 0.5, 0.01, "suffix:m") var log_radius := 0.1

var _log: MarkLine
var _finish: MarkLine
var _longest := 0.0
var _wheelie := 0.0
var _cleared := false
var _previous := Vector3.ZERO


func _begin() -> void:
	_log = marker(log_line, MarkLine) as MarkLine if not log_line.is_empty() else null
	_finish = marker(finish_line, MarkLine) as MarkLine
	_longest = 0.0
	_wheelie = 0.0
	_cleared = false
	_previous = bike.get_center_of_mass()


func progress_text() -> String:
	if _log == null:
		return "weight back and throttle   ·   longest wheelie %.1f m" % _longest
	if _cleared:
		return "over the log: ride through the finish   ·   longest wheelie %.1f m" % _longest
	return "weight back and throttle before the log"


func _judge(_delta: float) -> ChallengeResult:
	if not problem.is_empty():
		return failed("this lesson is broken: " + problem)
	var centre := bike.get_center_of_mass()
	var moved := Vector2(centre.x - _previous.x, centre.z - _previous.z).length()
	_previous = centre
	var front_up := not bike.is_front_wheel_grounded()
	if front_up and bike.is_rear_wheel_grounded():
		_wheelie += moved
		_longest = maxf(_longest, _wheelie)
	elif not front_up:
		_wheelie = 0.0
	if _log != null and _hit_the_log(not front_up):
		return failed("the front wheel hit the log: lean back and open the throttle before it")
	if _finish.distance_past(centre) < 0.0:
		return null
	return passed_with(_longest, ["the longest wheelie: %.1f m" % _longest])


## Whether the front wheel, `down` on the ground, is at the log (it hit it); notes once it
## is past.
func _hit_the_log(down: bool) -> bool:
	var front := bike.get_body_transform(BikeSimulation.FRONT_WHEEL).origin
	var reach := bike.get_wheel_radius() + log_radius
	if not _cleared and absf(_log.distance_past(front)) < reach and down:
		return true
	_cleared = _cleared or _log.distance_past(front) >= reach
	return false
