class_name Replay
extends CanvasLayer
## Watching the last run (from the pause menu): play and pause, scrub, slow motion,
## follow / orbit / free cameras, the player's triggers and sticks drawn as in Trials'
## replays, and the planner's trajectories as they were. The live bike is hidden while the
## recorded one rides; the game stays paused underneath.

## The player left the replay: whoever opened it shows the live bike's views again.
signal closed

const SPEEDS: Array[float] = [0.25, 0.5, 1.0, 2.0]
## Scrubbing speed with the turn stick held (replay seconds per second).
const SCRUB_SPEED := 4.0

var _bike: BikeSimulation
var _view: VisualBikeView
var _paths: TrajectoryView
var _live_camera: Camera3D
var _recording: RideRecording
var _frames: Array[Dictionary] = []
var _time := 0.0
var _playing := true
var _speed := 2
var _show_paths := true
var _syncing := false

@onready var _camera: ReplayCamera = $Camera
@onready var _status: Label = %Status
@onready var _scrub: HSlider = %Scrub
@onready var _inputs: InputDisplay = %Inputs
@onready var _readout: Label = %Readout


func _ready() -> void:
	visible = false
	_scrub.value_changed.connect(_on_scrubbed)


## Builds the recorded bike's drawing from `bike` at rest (so call it before the ride).
func setup(bike: BikeSimulation) -> void:
	_bike = bike
	_view = VisualBikeView.new()
	_view.name = "ReplayBike"
	_view.posed_by_recording = true
	_view.simulation_path = bike.get_path()
	add_child(_view)
	_view.visible = false
	_paths = TrajectoryView.new()
	_paths.follows_simulation = false
	add_child(_paths)


## Plays `frames` (ReplayRecorder.run(), recorded at `rate` a second) from the start.
## Returns false, showing nothing, when there is nothing to watch.
func open(frames: Array[Dictionary], rate: float) -> bool:
	if frames.size() < 2:
		return false
	_frames = frames
	_recording = RideRecording.new(rate)
	for frame: Dictionary in frames:
		_recording.add(frame.poses)
	_time = 0.0
	_playing = true
	_live_camera = get_viewport().get_camera_3d()
	_camera.current = true
	for view: NodePath in [^"VisualBikeView", ^"PhysicalBikeView", ^"TrajectoryView"]:
		(_bike.get_node(view) as Node3D).visible = false
	_view.visible = true
	_paths.visible = true
	visible = true
	_show(0.0)
	return true


## Back to the pause menu.
func close() -> void:
	visible = false
	_view.visible = false
	_paths.visible = false
	if _live_camera != null:
		_live_camera.current = true
	closed.emit()


## Seconds into the replay, and its length.
func time() -> float:
	return _time


func duration() -> float:
	return _recording.duration() if _recording != null else 0.0


func is_playing() -> bool:
	return _playing


func _process(delta: float) -> void:
	if not visible:
		return
	var scrub := Input.get_axis(&"steer_left", &"steer_right")
	if scrub != 0.0:
		_time += scrub * SCRUB_SPEED * delta
	elif _playing:
		_time += SPEEDS[_speed] * delta
		_playing = _time < duration()
	_time = clampf(_time, 0.0, duration())
	_show(delta)


func _unhandled_input(event: InputEvent) -> void:
	if not visible:
		return
	var handled := true
	if event.is_action_pressed(&"pause") or event.is_action_pressed(&"ui_cancel"):
		close()
	elif event.is_action_pressed(&"ui_accept"):
		_playing = not _playing
		if _playing and _time >= duration():
			_time = 0.0
	elif event.is_action_pressed(&"next_spawn"):
		_speed = mini(_speed + 1, SPEEDS.size() - 1)
	elif event.is_action_pressed(&"previous_spawn"):
		_speed = maxi(_speed - 1, 0)
	elif event.is_action_pressed(&"cycle_camera"):
		_camera.cycle_mode()
	elif event.is_action_pressed(&"toggle_trajectories"):
		_show_paths = not _show_paths
	elif event.is_action_pressed(&"reset_bike"):
		_time = 0.0
	else:
		handled = false
	if handled:
		get_viewport().set_input_as_handled()


func _show(delta: float) -> void:
	var bodies := _recording.poses_at(_time)
	var frame := _frames[clampi(int(_time * _recording.rate), 0, _frames.size() - 1)]
	_view.show_pose(bodies, frame.feet)
	_camera.frame_bike(bodies[BikeSimulation.FRAME], delta)
	var inputs: PackedFloat32Array = frame.inputs
	_inputs.throttle = inputs[ReplayRecorder.Channel.THROTTLE]
	_inputs.brake = inputs[ReplayRecorder.Channel.BRAKE]
	_inputs.turn = inputs[ReplayRecorder.Channel.TURN]
	_inputs.rider = Vector2(
		inputs[ReplayRecorder.Channel.RIDER_X], inputs[ReplayRecorder.Channel.RIDER_Y]
	)
	_readout.text = (
		"%d km/h   lean %+.0f°   wanted %+.0f°"
		% [
			roundi(absf(inputs[ReplayRecorder.Channel.SPEED]) * 3.6),
			rad_to_deg(inputs[ReplayRecorder.Channel.LEAN]),
			rad_to_deg(inputs[ReplayRecorder.Channel.WANTED_LEAN]),
		]
	)
	var no_paths: Array[PackedVector3Array] = []
	_paths.draw_paths(frame.paths if _show_paths else no_paths, frame.best, frame.warm)
	_status.text = (
		"Replay  %s  %s / %s   ×%s   camera: %s%s"
		% [
			"▶" if _playing else "❚❚",
			Level.format_time(_time),
			Level.format_time(duration()),
			str(SPEEDS[_speed]),
			_camera.mode,
			"" if _show_paths else "   (trajectories hidden)",
		]
	)
	_syncing = true
	_scrub.max_value = duration()
	_scrub.value = _time
	_syncing = false


func _on_scrubbed(value: float) -> void:
	if not _syncing:
		_time = value
