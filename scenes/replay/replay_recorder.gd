class_name ReplayRecorder
extends Node
## Keeps the last run for the replay: at every control step, the bodies' poses, the feet
## the rider put down, what the player's hands gave (triggers, turn, rider stick), the
## speed and lean, and the planner's trajectories, in a ring of at most `MOST_SECONDS`.
## Memory is bounded (about 8 MB at 15 trajectories); a step costs one native call for the
## poses, one for the paths and three for the feet. A respawn starts a new run but keeps
## the one before, so a crash can still be watched after respawning.

## Where each number sits in a frame's `inputs`.
enum Channel { THROTTLE, BRAKE, TURN, RIDER_X, RIDER_Y, SPEED, LEAN, WANTED_LEAN }

## The longest replay kept (s).
const MOST_SECONDS := 40.0
## A run shorter than this (s) is not worth replaying: the one before is kept instead.
const SHORTEST_RUN := 1.0

## The longest replay kept (s); MOST_SECONDS unless a test wants a short ring.
var capacity_seconds := MOST_SECONDS

var _bike: BikeSimulation
var _driver: BikeDriver
var _rate := 30.0
## The run being recorded and the one before, each a ring of frames (Dictionary: poses,
## feet, inputs, paths, best, warm) with the index of its oldest frame.
var _frames: Array[Dictionary] = []
var _oldest := 0
var _previous: Array[Dictionary] = []
var _last_step := -1


## Records `bike` as driven by `driver`.
func setup(bike: BikeSimulation, driver: BikeDriver) -> void:
	_bike = bike
	_driver = driver
	_rate = 1.0 / bike.get_control_dt()


## Starts a new run (the bike was respawned).
func start_run() -> void:
	if _frames.size() >= SHORTEST_RUN * _rate:
		_previous = _in_order()
	_frames.clear()
	_oldest = 0
	_last_step = -1


## The ride was put back `seconds` (a rewind): the frames of the time undone are dropped,
## and the run goes on from the moment it went back to, as it will be watched.
func rewind(seconds: float) -> void:
	var kept := _in_order()
	kept.resize(maxi(kept.size() - roundi(seconds * _rate), 0))
	_frames = kept
	_oldest = 0
	_last_step = -1


## The run to replay, oldest frame first: the current one, or the one before when the
## current has barely begun.
func run() -> Array[Dictionary]:
	return _in_order() if _frames.size() >= SHORTEST_RUN * _rate else _previous


## Frames a second.
func rate() -> float:
	return _rate


func _physics_process(_delta: float) -> void:
	if _bike == null or not _bike.is_running() or _bike.is_waiting_for_throttle():
		return
	var step := _bike.get_step_count()
	if step == _last_step:
		return
	_last_step = step
	record_step()


## Records the bike and the player's inputs as they are now (once a control step, by
## itself).
func record_step() -> void:
	var frame := {
		poses = _bike.get_pose_frame(),
		inputs =
		PackedFloat32Array(
			[
				_driver.throttle,
				_driver.brake,
				_driver.turn,
				_driver.rider.x,
				_driver.rider.y,
				_bike.get_speed(),
				_bike.get_lean(),
				_bike.get_desired_lean(),
			]
		),
		feet = VisualBikeView.feet_down_of(_bike),
		paths = _bike.get_trajectory_paths(),
		best = _bike.get_best_trajectory(),
		warm = _bike.get_warm_trajectory(),
	}
	if _frames.size() < int(capacity_seconds * _rate):
		_frames.append(frame)
	else:
		_frames[_oldest] = frame
		_oldest = (_oldest + 1) % _frames.size()


func _in_order() -> Array[Dictionary]:
	var ordered: Array[Dictionary] = []
	ordered.append_array(_frames.slice(_oldest))
	ordered.append_array(_frames.slice(0, _oldest))
	return ordered
