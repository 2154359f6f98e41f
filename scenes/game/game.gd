class_name Game
extends Node3D
## One ride on one level: builds the level and the bike at its first spawn point, applies
## the player's settings, runs the level's rules and handles the game buttons (respawn,
## lift, spawn points, controller, trajectories, pause). The level comes from the
## settings unless `level_path` names one, and so is the bike (`Bikes`) unless `bike_path`
## names a file (the thesis's reference bike, street_350.tres, rides the experiment and
## the tools). Best laps and ghosts are kept per bike.

const BIKE := preload("res://scenes/bike/bike.tscn")
const REPLAY := preload("res://scenes/replay/replay.tscn")
const START_MENU := "res://scenes/ui/start_menu.tscn"
## Seconds a result stays on screen before an automatic level starts the next attempt.
const RESULT_PAUSE := 2.5
## Seconds of the ride kept to rewind into, and how far a press of rewind goes back.
const REWIND_KEPT := 10.0
const REWIND_STEP := 3.0

## Level scene to ride; empty: the one chosen in the settings.
@export_file("*.tscn") var level_path := ""
## Bike to ride (a BikeDescription file); empty: the one chosen in the settings.
@export_file("*.tres") var bike_path := ""
## A lesson or challenge to ride (a Challenge file); empty: a free ride on the level. Its
## level replaces `level_path`.
@export_file("*.tres") var challenge_path := ""

## The bike ridden, by its file's name (its key in `Bikes` for a bike players choose).
var bike_key := ""

var level: Level
var bike: BikeSimulation
## The ghost of the best lap, on levels with laps (null elsewhere).
var ghost_race: GhostRace
## The lesson or challenge ridden (null: a free ride), and what the player reads of it
## (its briefing and result).
var challenge_run: ChallengeRun
var challenge_card: ChallengeCard
## The last run, kept for the replay, and the replay's player.
var recorder: ReplayRecorder
var replay: Replay
## Attempts finished, and how many reached the goal, on this level.
var attempts := 0
var successes := 0
var falls := 0

var _spawn_index := 0
var _rumble: Rumble
var _attempt_seed := 1
var _finished_for := -1.0
## What the last crash was (for the player): "the rider's head or body hit the ground".
var _crash_cause := ""

@onready var _driver: BikeDriver = $Driver
@onready var _camera: FollowCamera = $Camera
@onready var _hud: Hud = $Hud
@onready var _pause_menu: PauseMenu = $PauseMenu


func _ready() -> void:
	var challenge := ChallengeCatalogue.load_rideable(challenge_path)
	if challenge != null:
		level_path = challenge.level
	var path := (
		level_path if not level_path.is_empty() else Levels.path_of(Settings.get_value(&"level"))
	)
	var packed := load(path) as PackedScene if ResourceLoader.exists(path) else null
	var instance := packed.instantiate() if packed != null else null
	if not instance is Level:
		push_error("Game: %s is not a level scene; riding the test level" % path)
		if instance != null:
			instance.free()
		instance = (load(Levels.path_of("test_level")) as PackedScene).instantiate()
	level = instance as Level
	level.name = "Level"
	add_child(level)
	var spawns := level.spawn_points()
	bike = BIKE.instantiate() as BikeSimulation
	bike.terrain_root = ^"../Level"
	bike.wait_for_throttle = true
	bike.rewind_seconds = REWIND_KEPT
	var bike_file := bike_path if not bike_path.is_empty() else Bikes.chosen_path()
	if not bike_file.is_empty():
		bike.bike = Bikes.load_description(bike_file)
	bike_key = bike_file.get_file().get_basename()
	if level is Track:
		var track := level as Track
		track.record_key = Bikes.record_key(track.record_key, bike_key)
	if not spawns.is_empty():
		bike.transform = spawns[0].spawn_transform()
	add_child(bike)
	_driver.bike = bike
	_driver.automatic = level.automatic
	_driver.announced.connect(_hud.announce)
	_camera.target = bike
	_hud.bind(self)
	_pause_menu.restart_requested.connect(restart)
	_pause_menu.replay_requested.connect(watch_replay)
	_pause_menu.rewind_requested.connect(rewind)
	_pause_menu.opened.connect(
		func() -> void: _pause_menu.offer_rewind(REWIND_STEP, rewind_refusal())
	)
	# The pause menu stands over the ride with nothing of the HUD showing through.
	_pause_menu.opened.connect(_show_overlays.bind(false))
	_pause_menu.closed.connect(_show_overlays.bind(true))
	_rumble = Rumble.new()
	_rumble.name = "Rumble"
	add_child(_rumble)
	_rumble.follow(bike)
	# The effects that answer the bike's contact with the ground, each named as its class.
	for effect: Node3D in [TyreMarks.new(), Sparks.new(), Dust.new()]:
		effect.name = effect.get_script().get_global_name()
		effect.set(&"bike", bike)
		add_child(effect)
	recorder = ReplayRecorder.new()
	recorder.name = "ReplayRecorder"
	add_child(recorder)
	recorder.setup(bike, _driver)
	replay = REPLAY.instantiate() as Replay
	add_child(replay)
	replay.setup(bike)
	replay.closed.connect(_on_replay_closed)
	_pause_menu.quit_requested.connect(quit_to_menu)
	_pause_menu.show_bike(Bikes.summary_text(bike.bike))
	level.attach(bike)
	level.announced.connect(_hud.announce)
	if level is Track:
		ghost_race = GhostRace.new()
		ghost_race.name = "GhostRace"
		add_child(ghost_race)
		ghost_race.announced.connect(_hud.announce)
		ghost_race.split_measured.connect(_hud.show_split)
		ghost_race.setup(bike, level as Track)
	bike.crashed.connect(_on_crashed)
	bike.controller_failed.connect(_on_controller_failed)
	Settings.changed.connect(_apply_setting)
	for key: StringName in Settings.defaults:
		_apply_setting(key)
	_start_challenge(challenge)
	restart()


func _physics_process(delta: float) -> void:
	if not bike.is_running():
		return
	if _finished_for >= 0.0:
		_finished_for += delta
		if is_automatic() and _finished_for >= RESULT_PAUSE:
			restart()
		return
	if bike.is_waiting_for_throttle():
		return
	var outcome := level.judge(bike, delta)
	if challenge_run != null:
		outcome = challenge_run.judge_attempt(outcome, delta)
	if outcome != Level.RIDING:
		_finish(outcome)


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"pause"):
		_pause_menu.open()
	elif event.is_action_pressed(&"reset_bike"):
		restart()
	elif event.is_action_pressed(&"rewind"):
		rewind()
	elif event.is_action_pressed(&"lift_bike") and challenge_run != null:
		# A challenge's attempt is judged whole: lifting the bike starts it again. Over a
		# result, A is the card's (its buttons), not the bike's.
		if not challenge_card.is_result_shown():
			restart()
	elif event.is_action_pressed(&"lift_bike"):
		bike.lift_upright()
		_finished_for = -1.0
		_driver.stopping = false
	elif event.is_action_pressed(&"next_spawn"):
		cycle_spawn(1)
	elif event.is_action_pressed(&"previous_spawn"):
		cycle_spawn(-1)
	elif event.is_action_pressed(&"cycle_controller"):
		var cycle := bike.get_offered_controller_names()
		var current := cycle.find(bike.controller)
		Settings.set_value(&"controller", cycle[(current + 1) % cycle.size()])
		_hud.announce("Controller: %s" % controller_name())
	elif event.is_action_pressed(&"cycle_camera"):
		Settings.set_value(&"camera", _camera.cycle_mode())
		_hud.announce("Camera: %s" % FollowCamera.MODE_LABELS[_camera.mode])
	elif event.is_action_pressed(&"toggle_trajectories"):
		Settings.set_value(&"show_trajectories", not Settings.get_value(&"show_trajectories"))
	elif event.is_action_pressed(&"toggle_auto_accelerate") and not is_automatic():
		Settings.set_value(&"auto_accelerate", not Settings.get_value(&"auto_accelerate"))
		_hud.announce("Auto-accelerate %s" % ("on" if _driver.auto_accelerate else "off"))


## Puts the bike back at the current spawn point and starts a new attempt at once.
func restart() -> void:
	var spawns := level.spawn_points()
	if spawns.is_empty():
		push_error("Game: the level has no SpawnPoint")
		return
	_spawn_index = posmod(_spawn_index, spawns.size())
	bike.reset_to(spawns[_spawn_index].spawn_transform())
	_crash_cause = ""
	if recorder != null:
		recorder.start_run()
	level.begin_attempt(bike, _attempt_seed)
	_attempt_seed += 1
	if challenge_run != null:
		challenge_run.begin()
		challenge_card.show_briefing()
	_finished_for = -1.0
	_driver.stopping = false


## Puts the ride back REWIND_STEP seconds (as far as it was kept), the level's clock and the
## replay with it, and rides on from there: a fall undone is no longer a fall.
func rewind() -> void:
	var refusal := rewind_refusal()
	var seconds := 0.0
	if refusal.is_empty():
		var result := bike.rewind(REWIND_STEP)
		seconds = result.rewound
		refusal = result.why
	if seconds <= 0.0:
		_hud.announce("No rewind: %s" % refusal)
		return
	# After a finish the level's clock stood still while the bike rode on.
	level.rewound(bike, maxf(seconds - maxf(_finished_for, 0.0), 0.0))
	recorder.rewind(seconds)
	_finished_for = -1.0
	_hud.announce("Rewound %.1f s" % seconds)


## Why this ride cannot be rewound ("": it can, as far as the bike kept it): a lesson's or
## a challenge's attempt is judged whole, the automatic test rides itself, and a ride
## keeps nothing before its first throttle.
func rewind_refusal() -> String:
	if challenge_run != null:
		return "a lesson is judged whole (%s to try again)" % Controls.prompt(&"reset_bike")
	if is_automatic():
		return "the automatic test rides itself"
	return bike.get_rewind_refusal()


## Shows the replay of the last run (the game stays paused); back to the pause menu after.
func watch_replay() -> void:
	get_tree().paused = true
	if ghost_race != null:
		ghost_race.visible = false
	if replay.open(recorder.run(), recorder.rate()):
		_hud.visible = false
	else:
		_hud.announce("Nothing to replay yet: ride first")
		_pause_menu.open()


## Moves to the next (`step` 1) or previous (−1) spawn point and respawns there.
func cycle_spawn(step: int) -> void:
	var spawns := level.spawn_points()
	if spawns.size() == 0:
		return
	if challenge_run != null:
		_hud.announce(
			"A lesson starts where it starts: %s to try again" % Controls.prompt(&"reset_bike")
		)
		return
	_spawn_index = posmod(_spawn_index + step, spawns.size())
	restart()
	var label := spawns[_spawn_index].label
	_hud.announce(
		"Spawn point %d/%d%s" % [_spawn_index + 1, spawns.size(), (": " + label) if label else ""]
	)


## Index of the spawn point in use.
func spawn_index() -> int:
	return _spawn_index


## Whether the bike rides itself (the thesis's automatic test), as it does on an automatic
## level unless a challenge there is the player's to ride.
func is_automatic() -> bool:
	return level.automatic and challenge_run == null


## The player's hands (the driver), for the HUD's drawing of them.
func driver() -> BikeDriver:
	return _driver


## Name of the bike ridden, for people.
func bike_name() -> String:
	return Bikes.name_of(bike.bike)


## Name of the controller in use.
func controller_name() -> String:
	return bike.controller


## Leaves for the start menu.
func quit_to_menu() -> void:
	get_tree().paused = false
	get_tree().change_scene_to_file(START_MENU)


func _finish(outcome: String) -> void:
	_finished_for = 0.0
	_driver.stopping = is_automatic()
	level.finish_attempt(outcome)
	attempts += 1
	if challenge_run != null:
		successes += int(outcome == Level.GOAL)
		challenge_run.finish()
		return
	match outcome:
		Level.GOAL:
			successes += 1
			_hud.announce("Reached the goal in %s" % Level.format_time(level.elapsed))
		Level.TIMEOUT:
			_hud.announce("Out of time")
		Level.FELL:
			var fell := "Fell: %s" % _crash_cause if not _crash_cause.is_empty() else "Fell"
			_hud.announce(fell if is_automatic() else fell + "\n" + Hud.fallen_hint())


## Rides `challenge` (null: a free ride, where no challenge's markers show).
func _start_challenge(challenge: Challenge) -> void:
	if challenge == null:
		for area in level.challenge_areas():
			area.visible = false
		return
	challenge_run = ChallengeRun.new()
	challenge_run.name = "ChallengeRun"
	_driver.automatic = false
	add_child(challenge_run)
	challenge_run.setup(challenge_path, challenge, self, _driver)
	var spawn := challenge_run.spawn_point()
	_spawn_index = maxi(level.spawn_points().find(spawn), 0) if spawn != null else 0
	challenge_card = challenge_run.card
	_hud.show_inputs(true)
	challenge_card.retry_requested.connect(restart)
	challenge_card.menu_requested.connect(quit_to_menu)


## Shows or hides what is drawn over the ride: the HUD and a challenge's card.
func _show_overlays(shown: bool) -> void:
	_hud.visible = shown
	if challenge_card != null:
		challenge_card.visible = shown


func _on_replay_closed() -> void:
	_hud.visible = true
	if ghost_race != null:
		ghost_race.visible = true
	_apply_setting(&"show_trajectories")
	_apply_setting(&"physical_model")
	_pause_menu.open()


func _on_crashed(cause: String) -> void:
	falls += 1
	_crash_cause = cause


func _on_controller_failed(reason: String) -> void:
	_hud.announce(reason.left(1).to_upper() + reason.substr(1))


## Hands setting `key` to every setting target with a property of its name, and the
## ride's and the planners' to the bike node, whose own properties they are (the driver
## holds the top speed too: it drives the bike's each tick). What a setting needs beyond
## its value is its target's setter: the two bike views swap, a controller this bike does
## not offer rides as arcade.
func _apply_setting(key: StringName) -> void:
	var value: Variant = Settings.get_value(key)
	if key == &"terminal_value":
		# The player's switch asks for the bike's own cost-to-go: a bike without one
		# plans its whole horizon, nothing failed (the HUD says how far the plans look).
		value = value and bike.has_learned_cost_to_go()
	var targets := setting_targets()
	if Settings.entries[key].owner in ["ride", "planner"]:
		targets.push_front(bike)
	for target: Object in targets:
		if key in target:
			target.set(key, value)


## Where the game's and the display's settings go, by property name.
func setting_targets() -> Array[Object]:
	return [
		_driver,
		_camera,
		_hud,
		_rumble,
		bike.get_node(^"TrajectoryView"),
		bike.get_node(^"PhysicalBikeView"),
		bike.get_node(^"VisualBikeView"),
	]
