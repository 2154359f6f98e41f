class_name GhostRace
extends Node3D
## Racing the ghost of your best lap on a track: every lap is recorded as the bike's and
## rider's poses at the control rate; a new best lap becomes the ghost (saved under
## `user://ghosts/` by `GhostFile`), which rides beside you, see-through, from the start
## of each lap, and the HUD shows how far ahead or behind you are at each checkpoint.

## A ghost was loaded, set aside, or replaced; `text` is for the player.
signal announced(text: String)
## At a checkpoint: seconds behind the ghost (negative: ahead).
signal split_measured(checkpoint: int, behind: float)

var _bike: BikeSimulation
var _track: Track
var _view: VisualBikeView
## The lap being recorded (null when no lap is under way), and the ghost raced.
var _recording: RideRecording
var _ghost: RideRecording
var _last_step := -1


## Starts racing on `track` with `bike` (at rest at its spawn point, so the ghost's
## drawing can take the bike's shapes as they rest).
func setup(bike: BikeSimulation, track: Track) -> void:
	_bike = bike
	_track = track
	_view = VisualBikeView.new()
	_view.name = "GhostBike"
	_view.ghost = true
	_view.posed_by_recording = true
	_view.simulation_path = bike.get_path()
	add_child(_view)
	_view.visible = false
	track.lap_started.connect(_on_lap_started)
	track.checkpoint_passed.connect(_on_checkpoint_passed)
	track.lap_finished.connect(_on_lap_finished)
	track.lap_abandoned.connect(_on_lap_abandoned)
	var loaded := GhostFile.load_ghost(_path(), track.record_key, bike.get_body_count())
	_ghost = loaded.recording
	if not (loaded.problem as String).is_empty():
		announced.emit.call_deferred(
			"Your ghost could not be read (%s); it was set aside" % loaded.problem
		)


## The ghost being raced (null: none yet).
func ghost() -> RideRecording:
	return _ghost


## Whether the lap under way is being recorded (a ghost can be made of it).
func is_recording() -> bool:
	return _recording != null


## Whether the ghost is drawn now, and its drawing.
func is_ghost_shown() -> bool:
	return _view.visible


func ghost_view() -> VisualBikeView:
	return _view


func _physics_process(_delta: float) -> void:
	if _recording == null or _bike == null:
		return
	var step := _bike.get_step_count()
	if step != _last_step:
		_last_step = step
		_recording.add(_bike.get_pose_frame())


func _process(_delta: float) -> void:
	show_ghost()


## Shows the ghost where it was at this point of its lap (once a frame, by itself); hides
## it when there is no ghost to race or it has finished its lap.
func show_ghost() -> void:
	if _ghost == null or _recording == null:
		_view.visible = false
		return
	var seconds := _track.lap_time()
	_view.visible = seconds <= _ghost.duration()
	if _view.visible:
		_view.show_pose(_ghost.poses_at(seconds))


func _on_lap_started() -> void:
	_recording = RideRecording.new(1.0 / _bike.get_control_dt())
	_last_step = _bike.get_step_count()
	_recording.add(_bike.get_pose_frame())


func _on_checkpoint_passed(checkpoint: int, lap_time: float) -> void:
	if _recording == null:
		return
	_recording.splits.append(lap_time)
	if _ghost != null and checkpoint <= _ghost.splits.size():
		split_measured.emit(checkpoint, lap_time - _ghost.splits[checkpoint - 1])


func _on_lap_finished(lap_time: float, best: bool) -> void:
	if _recording == null or not best:
		return
	_recording.lap_time = lap_time
	_ghost = _recording
	_recording = null
	GhostFile.save(_ghost, _track.record_key, _path())


func _on_lap_abandoned() -> void:
	_recording = null


func _path() -> String:
	return Settings.ghost_path(_track.record_key)
