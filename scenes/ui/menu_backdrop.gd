class_name MenuBackdrop
extends SubViewportContainer
## The start menu's backdrop: the level the player last chose, in the game's own light
## (the shared outdoor environment and sun), seen from beside its start, with the chosen
## bike standing there. Drawn once into its own viewport and then shown as a still, so the
## menu costs no 3D drawing per frame (a frame of the level is about 0.15 s on a software
## renderer).

const ENVIRONMENT := preload("res://scenes/world/outdoor_environment.tres")
const SUN := preload("res://scenes/world/sun.tscn")
## Where the camera stands relative to the level's first spawn point, in the spawn's frame
## (x right, y up, z behind), and the point it looks at: behind the bike standing at the
## start and to its left, looking up the level past it, so the level ahead fills the view
## and the bike stands in the lower right, clear of the menus.
const CAMERA_FROM_SPAWN := Vector3(-2.2, 1.7, 4.8)
const LOOK_AT := Vector3(-4.2, 2.4, -14.0)
const BIKE := preload("res://scenes/bike/bike.tscn")
## Physics frames the bike stands at the start before it is drawn: its drawing is built
## from the bike as it stands.
const BIKE_SETTLE_FRAMES := 2

var _viewport := SubViewport.new()
var _level: Level
var _bike_key := ""
var _bike: BikeSimulation
var _bike_settle_frames_left := 0
## Where the bike stands: the start shown.
var _start := Transform3D()


func _ready() -> void:
	# In the tree from the start, so it is freed with the menu even when left empty.
	add_child(_viewport)
	# Without the native module a level cannot even load (its scripts name the module's
	# classes): the start menu says what is missing over an empty backdrop. Asked only for
	# the module's description, the menu quits at once and needs no level.
	if not NativeModule.is_loaded() or NativeModule.info_requested():
		return
	stretch = true
	# After the bike's own step, so it stands BIKE_SETTLE_FRAMES steps before it stops.
	process_physics_priority = 1
	_viewport.own_world_3d = true
	_viewport.render_target_update_mode = SubViewport.UPDATE_ONCE
	var environment := WorldEnvironment.new()
	environment.environment = ENVIRONMENT
	_viewport.add_child(environment)
	_viewport.add_child(SUN.instantiate())
	var horizon := Horizon.new()
	horizon.name = "Horizon"
	_viewport.add_child(horizon)
	show_level(str(Settings.get_value(&"level")))
	show_bike(str(Settings.get_value(&"bike")))
	resized.connect(func() -> void: _viewport.render_target_update_mode = SubViewport.UPDATE_ONCE)


## Shows level `key` (the first level for an unknown key, the level at `key` for a scene's
## path), drawn once.
func show_level(key: String) -> void:
	var path := key if key.begins_with("res://") else Levels.path_of(key)
	show_scene(path if not path.is_empty() else Levels.path_of(Levels.keys()[0]))


## Shows the lesson or challenge at `path` where it starts, with only its markers.
func show_challenge(path: String) -> void:
	var challenge := ChallengeCatalogue.load_challenge(path)
	if challenge != null and challenge.problem().is_empty():
		show_scene(challenge.level, challenge.area)


## Shows the level scene at `path` from its first spawn point, or from the spawn point of
## its ChallengeArea `area` with that area's markers alone.
func show_scene(path: String, area := NodePath()) -> void:
	for old: Node in _viewport.get_children():
		if old is Level or old is Camera3D or old is BikeSimulation:
			old.queue_free()
	_bike = null
	var level := (load(path) as PackedScene).instantiate() as Level
	_level = level
	_viewport.add_child(level)
	var shown := level.get_node_or_null(area) as ChallengeArea if not area.is_empty() else null
	for other in level.challenge_areas():
		other.visible = other == shown
	var spawns := level.spawn_points()
	if shown != null and shown.spawn_point() != null:
		spawns = [shown.spawn_point()]
	var start := spawns[0].spawn_transform() if not spawns.is_empty() else Transform3D()
	_start = start
	var camera := Camera3D.new()
	camera.fov = 60.0
	_viewport.add_child(camera)
	camera.global_position = start * CAMERA_FROM_SPAWN
	camera.look_at(start * LOOK_AT, Vector3.UP)
	camera.current = true
	_viewport.render_target_update_mode = SubViewport.UPDATE_ONCE
	if not _bike_key.is_empty():
		show_bike(_bike_key)


## Stands bike `key` (a `Bikes` key; none for one that cannot be built) at the level's
## start, drawn once it has settled; its engine stays silent and its simulation stops then.
func show_bike(key: String) -> void:
	_bike_key = key
	if _bike != null:
		_bike.queue_free()
		_bike = null
	var description := Bikes.description(key)
	if description == null or _level == null:
		_viewport.render_target_update_mode = SubViewport.UPDATE_ONCE
		return
	var bike := BIKE.instantiate() as BikeSimulation
	bike.get_node(^"Sound").free()
	bike.bike = description
	bike.wait_for_throttle = true
	bike.transform = _start
	bike.terrain_root = NodePath("../" + _level.name)
	_bike = bike
	_viewport.add_child(bike)
	_bike_settle_frames_left = BIKE_SETTLE_FRAMES


# Counted here rather than awaited in show_bike: a coroutine still waiting for a physics
# frame when the menu goes would hold the bike's description to the end (a leak at exit).
func _physics_process(_delta: float) -> void:
	if _bike == null or _bike_settle_frames_left <= 0:
		return
	_bike_settle_frames_left -= 1
	if _bike_settle_frames_left == 0:
		_bike.process_mode = Node.PROCESS_MODE_DISABLED
		_viewport.render_target_update_mode = SubViewport.UPDATE_ONCE


## The bike standing in the backdrop (null before one is shown or when none can be).
func bike() -> BikeSimulation:
	return _bike
