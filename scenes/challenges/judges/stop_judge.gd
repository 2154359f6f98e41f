@tool
class_name StopJudge
extends ChallengeJudge
## Ride off, hold a speed between two lines, then stop with the bike inside a box. The
## score is how far from the box's middle (m, along the way) the bike came to rest.

## The lines the speed is held between, and the speeds allowed there (km/h).
@export var hold_from := NodePath("HoldFrom")
@export var hold_to := NodePath("HoldTo")
@export_range(0.0, 90.0, 1.0, "suffix:km/h") var hold_min_kmh := 15.0
@export_range(0.0, 90.0, 1.0, "suffix:km/h") var hold_max_kmh := 25.0
## The box to stop in (a GoalArea, its length along the way).
@export var box := NodePath("StopBox")
## How far past the box (m) a bike still rolling has ridden through it.
@export_range(1.0, 50.0, 0.5, "suffix:m") var overrun := 8.0

var _from: MarkLine
var _to: MarkLine
var _box: GoalArea
var _slowest := INF
var _fastest := 0.0


func _begin() -> void:
	_from = marker(hold_from, MarkLine) as MarkLine
	_to = marker(hold_to, MarkLine) as MarkLine
	_box = marker(box, GoalArea) as GoalArea
	_slowest = INF
	_fastest = 0.0


func progress_text() -> String:
	if _to == null:
		return ""
	if _from.distance_past(bike.get_center_of_mass()) < 0.0:
		return "reach %d–%d km/h by the first line" % [hold_min_kmh, hold_max_kmh]
	if _to.distance_past(bike.get_center_of_mass()) < 0.0:
		return "hold %d–%d km/h to the second line" % [hold_min_kmh, hold_max_kmh]
	return "stop in the box"


func _judge(_delta: float) -> ChallengeResult:
	if _box == null or _from == null or _to == null:
		return failed("this lesson is broken: " + problem)
	var centre := bike.get_center_of_mass()
	var held := _held_speed(centre)
	if held != null:
		return held
	var facts := PackedStringArray()
	if is_finite(_slowest):
		facts.append("held %d–%d km/h between the lines" % [floori(_slowest), ceili(_fastest)])
	var past_middle := _box_middle_line_distance(centre)
	if past_middle > _box.size.z / 2.0 + overrun:
		return failed("you rode through the box without stopping", facts)
	if not stopped():
		return null
	if _to.distance_past(centre) < 0.0:
		return failed("you stopped before the second line", facts)
	var side := "past" if past_middle > 0.0 else "short of"
	facts.append("stopped %.2f m %s the box's middle" % [absf(past_middle), side])
	return _stop_verdict(centre, past_middle, facts)


## Between the lines: a fail once the speed left the band (null while it keeps to it).
func _held_speed(centre: Vector3) -> ChallengeResult:
	if _from.distance_past(centre) < 0.0 or _to.distance_past(centre) >= 0.0:
		return null
	_slowest = minf(_slowest, speed_kmh())
	_fastest = maxf(_fastest, speed_kmh())
	var band := "keep to %d–%d km/h" % [hold_min_kmh, hold_max_kmh]
	if _slowest < hold_min_kmh:
		return failed("you slowed to %d km/h between the lines: %s" % [floori(_slowest), band])
	if _fastest > hold_max_kmh:
		return failed("you rode %d km/h between the lines: %s" % [ceili(_fastest), band])
	return null


## Stopped `past_middle` m past the box's middle (negative: short of it): in the box or not.
func _stop_verdict(
	centre: Vector3, past_middle: float, facts: PackedStringArray
) -> ChallengeResult:
	if _box.contains(centre):
		return passed_with(absf(past_middle), facts)
	var outside := absf(past_middle) - _box.size.z / 2.0
	if outside <= 0.0:
		return failed("you stopped beside the box, not in it", facts)
	if past_middle < 0.0:
		return failed("you stopped %.1f m before the box" % outside, facts)
	return failed("you stopped %.1f m past the box" % outside, facts)


## How far (m) `point` lies past the box's middle along the way (its −z).
func _box_middle_line_distance(point: Vector3) -> float:
	return -_box.to_local(point).z
