class_name MenuBackdrop
extends SubViewportContainer
## The start menu's backdrop: the level the player last chose, in the game's own light
## (the shared outdoor environment and sun), seen from beside its start. Drawn once into
## its own viewport and then shown as a still, so the menu costs no 3D drawing per frame
## (a frame of the level is about 0.15 s on a software renderer).

const ENVIRONMENT := preload("res://scenes/world/outdoor_environment.tres")
const SUN := preload("res://scenes/world/sun.tscn")
## Where the camera stands relative to the level's first spawn point, in the spawn's frame
## (x right, y up, z behind), and how far ahead of the spawn it looks (m).
const CAMERA_FROM_SPAWN := Vector3(3.0, 4.0, 3.0)
const LOOK_AHEAD := 18.0

var _viewport := SubViewport.new()


func _ready() -> void:
	# Without the native module a level cannot even load (its scripts name the module's
	# classes): the start menu says what is missing over an empty backdrop.
	if not NativeModule.is_loaded():
		return
	stretch = true
	_viewport.own_world_3d = true
	_viewport.render_target_update_mode = SubViewport.UPDATE_ONCE
	add_child(_viewport)
	var environment := WorldEnvironment.new()
	environment.environment = ENVIRONMENT
	_viewport.add_child(environment)
	_viewport.add_child(SUN.instantiate())
	show_level(str(Settings.get_value(&"level")))
	resized.connect(func() -> void: _viewport.render_target_update_mode = SubViewport.UPDATE_ONCE)


## Shows level `key` (the first level for an unknown key), drawn once.
func show_level(key: String) -> void:
	for old: Node in _viewport.get_children():
		if old is Level or old is Camera3D:
			old.queue_free()
	var path := Levels.path_of(key)
	if path.is_empty():
		path = Levels.ALL.values()[0]
	var level := (load(path) as PackedScene).instantiate() as Level
	_viewport.add_child(level)
	var spawns := level.spawn_points()
	var start := spawns[0].spawn_transform() if not spawns.is_empty() else Transform3D()
	var camera := Camera3D.new()
	camera.fov = 60.0
	_viewport.add_child(camera)
	camera.global_position = start * CAMERA_FROM_SPAWN
	camera.look_at(start * Vector3(0.0, 0.5, -LOOK_AHEAD), Vector3.UP)
	camera.current = true
	_viewport.render_target_update_mode = SubViewport.UPDATE_ONCE
