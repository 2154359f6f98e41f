@tool
class_name LandingJudge
extends ChallengeJudge
## A jump: off the kicker, both wheels in the air, and down on both wheels, not on the
## front one, then on through the finish. In the air the rider's weight pitches the bike
## (nose up or down). The score is how far the bike was pitched from level where it
## touched down (degrees), or with `score_air_time` the time in the air (s); the air time
## and distance are told either way.

## Wheels touching down within this long (s) of each other landed together.
const TOGETHER := 0.05

## The line to ride through after the landing.
@export var finish_line := NodePath("Finish")
## The front wheel landing this long (s) before the rear, or more, is a landing on it.
@export_range(0.02, 1.0, 0.01, "suffix:s") var front_first_limit := 0.12
## Touching down with the nose further down than this (degrees) lands on the front wheel,
## however soon the rear follows.
@export_range(1.0, 45.0, 0.5, "suffix:°") var nose_down_limit := 15.0
## Score the time in the air instead of the landing's pitch.
@export var score_air_time := false
## Both wheels off the ground this long (s) is a jump (a bump is not).
@export_range(0.02, 1.0, 0.01, "suffix:s") var least_air := 0.15

var _finish: MarkLine
var _air := 0.0
var _took_off := Vector3.ZERO
## Set once landed: the time in the air, where, the pitch (degrees, nose up +) at the
## first touch, which wheel touched first, and how long the other wheel waited since.
var _flight := NAN
var _flown := 0.0
var _pitch := 0.0
var _front_first := false
var _other_waited := 0.0
var _both_down := false


func _begin() -> void:
	_finish = marker(finish_line, MarkLine) as MarkLine
	_air = 0.0
	_flight = NAN
	_both_down = false


func progress_text() -> String:
	if is_nan(_flight):
		return "over the kicker: weight back to lift the nose, forward to drop it"
	return "landed: ride through the finish"


func _judge(delta: float) -> ChallengeResult:
	if _finish == null:
		return failed("this lesson is broken: " + problem)
	var front := bike.is_front_wheel_grounded()
	var rear := bike.is_rear_wheel_grounded()
	if is_nan(_flight):
		if not front and not rear:
			if _air == 0.0:
				_took_off = bike.get_center_of_mass()
			_air += delta
		elif _air >= least_air:
			_landed(front, rear)
			if _pitch < -nose_down_limit:
				return failed(_front_first_text(), _facts())
		else:
			_air = 0.0
	elif not _both_down:
		_both_down = front and rear
		if not _both_down:
			_other_waited += delta
			if _front_first and _other_waited >= front_first_limit:
				return failed("the front wheel landed first: lean back in the air", _facts())
	if _finish.distance_past(bike.get_center_of_mass()) < 0.0:
		return null
	if is_nan(_flight):
		return failed("you never left the ground: ride over the kicker, and fast")
	return passed_with(_flight if score_air_time else absf(_pitch), _facts())


func _landed(front: bool, rear: bool) -> void:
	_flight = _air
	var at := bike.get_center_of_mass()
	_flown = Vector2(at.x - _took_off.x, at.z - _took_off.z).length()
	var heading := bike.get_body_transform(BikeSimulation.FRAME).basis.x.normalized()
	_pitch = rad_to_deg(asin(clampf(heading.y, -1.0, 1.0)))
	_front_first = front and not rear
	_both_down = front and rear
	_other_waited = 0.0


func _front_first_text() -> String:
	return "the front wheel landed first: in the air, pull the rider's weight back"


func _facts() -> PackedStringArray:
	if is_nan(_flight):
		return PackedStringArray()
	var nose := "the nose %.0f° %s" % [absf(_pitch), "up" if _pitch >= 0.0 else "down"]
	var landing := "landed on both wheels"
	if _other_waited > TOGETHER:
		landing = (
			"landed %s wheel first, the other %.2f s later"
			% ["front" if _front_first else "rear", _other_waited]
		)
	return PackedStringArray(
		["in the air %.2f s over %.1f m" % [_flight, _flown], "%s, %s" % [landing, nose]]
	)
