@tool
class_name CourseJudge
extends ChallengeJudge
## Gates to ride through in order (a slalom, a line through bends). Riding past a gate
## outside its poles, or through a later one first, misses it. The score is the time from
## the first throttle to the last gate (s). With `watch_counter_steer` the result also
## tells how the bar first turned the wrong way in every turn asked.

## How far beyond a gate's poles (m) riding past it still counts as missing it; further
## off, the line crossed is not this gate's (a course through bends crosses the lines of
## gates far away).
const MISS_REACH := 6.0
## A bike further from the next gate than this many times the way there from the last
## one, plus this many metres, has left the course (ridden wide of a bend, say).
const STRAY_FACTOR := 1.5
const STRAY_SLACK := 10.0

## The gates (CourseGate or any GateLine) in the order they are ridden.
@export var gates: Array[NodePath] = []
## The least speed (km/h) allowed through each gate, in order (missing: none).
@export var gate_min_kmh := PackedFloat32Array()
## Tell the counter-steer of every turn asked (the counter-steering lesson).
@export var watch_counter_steer := false

var _gates: Array[GateLine] = []
var _next := 0
var _previous := Vector3.ZERO
var _watch: CounterSteerWatch


func _begin() -> void:
	_gates.clear()
	for path in gates:
		var gate := marker(path, GateLine) as GateLine
		if gate != null:
			_gates.append(gate)
	_next = 0
	_previous = bike.get_center_of_mass()
	_watch = CounterSteerWatch.new() if watch_counter_steer else null


func progress_text() -> String:
	return "gate %d of %d" % [mini(_next + 1, gates.size()), gates.size()]


func _judge(delta: float) -> ChallengeResult:
	if not problem.is_empty() or _gates.is_empty():
		return failed("this course is broken: " + problem)
	if _watch != null:
		_watch.watch(bike, delta)
	var centre := bike.get_center_of_mass()
	var verdict := _crossings(_previous, centre)
	_previous = centre
	if verdict == null and _strayed(centre):
		verdict = failed("you missed gate %d" % (_next + 1), _facts())
	if verdict != null or _next < _gates.size():
		return verdict
	return passed_with(_score(), _facts())


## The verdict of the ride from `from` to `to`: a gate passed moves `_next` on; riding
## past the next gate outside its poles (within MISS_REACH of them), or through a later
## one, misses it.
func _crossings(from: Vector3, to: Vector3) -> ChallengeResult:
	for i in range(_next, _gates.size()):
		var gate := _gates[i]
		var offset := gate.crossing_offset(from, to)
		if is_nan(offset) or gate.distance_past(to) < 0.0:
			continue
		var inside := absf(offset) <= gate.width / 2.0
		if i == _next and not inside and absf(offset) > gate.width / 2.0 + MISS_REACH:
			continue
		if i > _next and not inside:
			continue
		if i > _next or not inside:
			return failed("you missed gate %d" % (_next + 1), _facts())
		if i < gate_min_kmh.size() and speed_kmh() < gate_min_kmh[i]:
			return failed(
				(
					"you rode through gate %d at %d km/h: it needs %d km/h"
					% [i + 1, floori(speed_kmh()), gate_min_kmh[i]]
				),
				_facts()
			)
		_next = i + 1
	return null


## Whether the bike, past a gate, has gone so far from the next that it has left the
## course: further than STRAY_FACTOR times the way between the two gates, plus STRAY_SLACK.
func _strayed(centre: Vector3) -> bool:
	if _next == 0 or _next >= _gates.size():
		return false
	var gate := _gates[_next].global_position
	var between := gate.distance_to(_gates[_next - 1].global_position)
	return centre.distance_to(gate) > STRAY_FACTOR * between + STRAY_SLACK


## The score of a course ridden through: the time it took (s).
func _score() -> float:
	return elapsed


func _facts() -> PackedStringArray:
	return _watch.describe() if _watch != null else PackedStringArray()
