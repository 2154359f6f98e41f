@tool
class_name Track
extends Level
## A timed lap (§4.1.2, Figures 4.4 and 4.6): the clock starts at the start/finish line;
## a lap counts when every checkpoint was crossed in order before the line is crossed
## again. The best lap is saved with the player's records. A rewound lap runs on, its
## clock and checkpoints put back with the bike, but it is no record: it is not saved and
## no ghost is made of it.

## The clock started at the start/finish line.
signal lap_started
## Checkpoint `checkpoint` (1, 2, …) was passed in order, `lap_time` seconds into the lap.
signal checkpoint_passed(checkpoint: int, lap_time: float)
## A lap was completed in `lap_time` s; `best`: it is the new best lap.
signal lap_finished(lap_time: float, best: bool)
## The lap under way was given up (a respawn).
signal lap_abandoned

## Key the best lap is saved under.
@export var record_key := "track"

var _gates: Array[LapGate] = []
var _next_checkpoint := 0
var _lap_started := false
var _lap_time := 0.0
## The lap's clock at each checkpoint passed, in order.
var _split_times: Array[float] = []
## The lap under way was rewound.
var _lap_rewound := false
var _last_lap := INF
var _previous_centre := Vector3.ZERO


func _ready() -> void:
	for child in find_children("*", "Node3D", true, false):
		if child is LapGate:
			_gates.append(child)


func begin_attempt(bike: BikeSimulation, seed_value: int) -> void:
	super(bike, seed_value)
	if _lap_started:
		lap_abandoned.emit()
	_start_over()
	_previous_centre = bike.get_center_of_mass()


func judge(bike: BikeSimulation, delta: float) -> String:
	var outcome := super(bike, delta)
	var centre := bike.get_center_of_mass()
	if _lap_started:
		_lap_time += delta
	for gate in _gates:
		if gate.crossing(_previous_centre, centre) == 1:
			_passed(gate.checkpoint)
	_previous_centre = centre
	return outcome


func rewound(bike: BikeSimulation, seconds: float) -> void:
	super(bike, seconds)
	# The bike jumped: no gate was crossed between where it was and where it is.
	_previous_centre = bike.get_center_of_mass()
	if not _lap_started:
		return
	if seconds > _lap_time:
		# Back before the start line: the lap starts when it is crossed again.
		_start_over()
		lap_abandoned.emit()
		return
	_lap_time -= seconds
	while not _split_times.is_empty() and _split_times.back() > _lap_time:
		_split_times.pop_back()
	_next_checkpoint = _split_times.size() + 1
	if not _lap_rewound:
		_lap_rewound = true
		lap_abandoned.emit()
		announced.emit("Rewound: this lap will not count as a record")


## Whether the lap under way was rewound (it will not count).
func is_lap_rewound() -> bool:
	return _lap_started and _lap_rewound


## Seconds into the lap under way (0 before the start line is crossed).
func lap_time() -> float:
	return _lap_time if _lap_started else 0.0


## Checkpoints the lap needs, besides the start/finish line.
func checkpoint_count() -> int:
	var highest := 0
	for gate in _gates:
		highest = maxi(highest, gate.checkpoint)
	return highest


func status_line() -> String:
	# Before the start line the lap's clock reads as an empty time, as last and best do:
	# words there ran into the HUD's planner line at 1280 pixels.
	var lap := format_time(_lap_time if _lap_started else INF)
	if is_lap_rewound():
		lap += " rewound"
	return (
		"lap %s   last %s   best %s"
		% [lap, format_time(_last_lap), format_time(Settings.best_lap(record_key))]
	)


func _passed(checkpoint: int) -> void:
	if checkpoint == 0:
		if _lap_started and _next_checkpoint > checkpoint_count():
			_finish_lap()
		_start_over()
		_lap_started = true
		_next_checkpoint = 1
		lap_started.emit()
	elif _lap_started and checkpoint == _next_checkpoint:
		_next_checkpoint += 1
		_split_times.append(_lap_time)
		checkpoint_passed.emit(checkpoint, _lap_time)


func _start_over() -> void:
	_lap_started = false
	_lap_rewound = false
	_lap_time = 0.0
	_next_checkpoint = 0
	_split_times.clear()


func _finish_lap() -> void:
	if _lap_rewound:
		announced.emit("Lap: %s (rewound: not a record)" % format_time(_lap_time))
		return
	_last_lap = _lap_time
	var best := Settings.record_lap(record_key, _lap_time)
	if best:
		announced.emit("New best lap: %s" % format_time(_lap_time))
	else:
		announced.emit("Lap: %s" % format_time(_lap_time))
	lap_finished.emit(_lap_time, best)
