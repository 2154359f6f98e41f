@tool
class_name BrakeJudge
extends ChallengeJudge
## A full brake to a line: be at speed by the marker, then stop with the front tyre short
## of the line. The score is how far short (m); the stop is told in metres and g.

## Within this much (m/s) of its top speed the bike has not begun to brake.
const AT_TOP := 0.1

## The line to be at speed by (cones either side), and the speed (km/h).
@export var marker_line := NodePath("BrakeMarker")
@export_range(1.0, 90.0, 1.0, "suffix:km/h") var min_kmh := 55.0
## The line to stop short of.
@export var stop_line := NodePath("StopLine")

var _marker: MarkLine
var _line: MarkLine
var _at_marker := NAN
## The top speed past the marker, and the last place the bike still rode at it (within
## AT_TOP): where the braking began.
var _top_speed := 0.0
var _top_at := Vector3.ZERO


func _begin() -> void:
	_marker = marker(marker_line, MarkLine) as MarkLine
	_line = marker(stop_line, MarkLine) as MarkLine
	_at_marker = NAN
	_top_speed = 0.0


func progress_text() -> String:
	if is_nan(_at_marker):
		return "reach %d km/h by the cones" % min_kmh
	return "stop before the line"


func _judge(_delta: float) -> ChallengeResult:
	if _marker == null or _line == null:
		return failed("this lesson is broken: " + problem)
	var centre := bike.get_center_of_mass()
	if is_nan(_at_marker):
		if _marker.distance_past(front_tyre()) < 0.0:
			return null
		_at_marker = speed_kmh()
		if _at_marker < min_kmh:
			return failed(
				(
					"you reached the cones at %d km/h: be at %d km/h or more there"
					% [floori(_at_marker), min_kmh]
				)
			)
	var speed := absf(bike.get_speed())
	_top_speed = maxf(_top_speed, speed)
	if speed >= _top_speed - AT_TOP:
		_top_at = centre
	if not stopped():
		return null
	var braked := (centre - _top_at) * Vector3(1, 0, 1)
	var facts := PackedStringArray()
	if braked.length() > 0.5:
		var g := _top_speed * _top_speed / (2.0 * braked.length()) / bike.get_gravity()
		facts.append(
			"braked from %d km/h in %.1f m: %.2f g" % [roundi(_top_speed * 3.6), braked.length(), g]
		)
	var short := -_line.distance_past(front_tyre())
	if short < 0.0:
		return failed("you braked too late: stopped %.1f m past the line" % -short, facts)
	return passed_with(short, facts)
