@tool
class_name BendJudge
extends CourseJudge
## A long bend at speed through its gates: the score is the lean held through it (the
## mean lean, degrees, from the first gate to the last), so the faster the rider takes it
## the more it scores, up to the bike's limit.

var _lean_sum := 0.0
var _lean_time := 0.0
var _kmh_sum := 0.0


func _begin() -> void:
	super()
	_lean_sum = 0.0
	_lean_time = 0.0
	_kmh_sum = 0.0


func progress_text() -> String:
	return "%s   ·   lean %d°" % [super(), roundi(rad_to_deg(absf(bike.get_lean())))]


func _judge(delta: float) -> ChallengeResult:
	if _next > 0:
		_lean_sum += absf(bike.get_lean()) * delta
		_kmh_sum += speed_kmh() * delta
		_lean_time += delta
	return super(delta)


func _score() -> float:
	return rad_to_deg(_lean_sum / _lean_time) if _lean_time > 0.0 else 0.0


func _facts() -> PackedStringArray:
	var facts := super()
	if _lean_time > 0.0:
		facts.append(
			"%.1f s in the bend at %d km/h on average" % [_lean_time, roundi(_kmh_sum / _lean_time)]
		)
	return facts
