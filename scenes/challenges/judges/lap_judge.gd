@tool
class_name LapJudge
extends ChallengeJudge
## A time trial on a track: one lap from the start line round every checkpoint in order
## and back over the line (the Track's own rules, which also keep the best lap and its
## ghost). The score is the lap time (s); over the line again with a checkpoint missed
## fails.

var _track: Track
var _lap := NAN
var _checkpoints := 0
var _laps_started := 0
var _missed := 0


func _begin() -> void:
	_track = level() as Track
	if _track == null:
		problem = "the area %s is not on a track" % area.name
		push_error("Challenge: " + problem)
		return
	_lap = NAN
	_checkpoints = 0
	_laps_started = 0
	_missed = 0
	if not _track.lap_finished.is_connected(_on_lap_finished):
		_track.lap_finished.connect(_on_lap_finished)
		_track.checkpoint_passed.connect(_on_checkpoint_passed)
		_track.lap_started.connect(_on_lap_started)


func end() -> void:
	if _track != null and _track.lap_finished.is_connected(_on_lap_finished):
		_track.lap_finished.disconnect(_on_lap_finished)
		_track.checkpoint_passed.disconnect(_on_checkpoint_passed)
		_track.lap_started.disconnect(_on_lap_started)


func progress_text() -> String:
	if _track == null:
		return ""
	if _track.lap_time() <= 0.0:
		return "over the start line"
	return (
		"checkpoint %d of %d   ·   lap %s"
		% [_checkpoints, _track.checkpoint_count(), Level.format_time(_track.lap_time())]
	)


func _judge(_delta: float) -> ChallengeResult:
	if _track == null:
		return failed("this challenge is broken: " + problem)
	if _missed > 0:
		return failed("you missed checkpoint %d: the lap does not count" % _missed)
	if is_nan(_lap):
		return null
	return passed_with(_lap, ["a lap in %s" % Level.format_time(_lap)])


func _on_lap_finished(lap_time: float, _best: bool) -> void:
	_lap = lap_time


## Over the start line: the lap begins, or begins again with a checkpoint missed (a
## finished lap is `lap_finished`, which comes first).
func _on_lap_started() -> void:
	_laps_started += 1
	if _laps_started > 1 and is_nan(_lap):
		_missed = _checkpoints + 1
	_checkpoints = 0


func _on_checkpoint_passed(checkpoint: int, _lap_time: float) -> void:
	_checkpoints = checkpoint
