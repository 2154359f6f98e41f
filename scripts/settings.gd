extends Node
## The player's settings and records (autoload `Settings`). Every change is saved at once,
## atomically, to `user://settings.cfg`, and best laps to `user://records.cfg` (their
## ghosts under `user://ghosts/`), so a crash or a kill loses nothing.

## A setting changed (by a menu or by a key); `key` is its name.
signal changed(key: StringName)

## Trajectory counts the menus offer, after "auto" (the planner's N follows the machine).
const TRAJECTORY_CHOICES: Array[int] = [5, 10, 15, 32, 64, 128]
## Speeds auto-accelerate offers (km/h): the thesis tested 10, 15, 20 and 25.
const AUTO_SPEEDS: Array[int] = [10, 15, 20, 25]

## Default value of every setting; also their types: a loaded value of another type is
## ignored.
const DEFAULTS := {
	&"level": "test_level",
	&"trajectories": 15,
	&"auto_trajectories": true,
	&"controller": "combined",
	&"show_trajectories": true,
	&"physical_model": false,
	&"motor_force": 0.6,
	&"max_speed_kmh": 40.0,
	&"auto_speed_kmh": 15,
	&"auto_accelerate": false,
	&"camera": "chase",
	&"master_volume": 0.8,
	&"engine_volume": 1.0,
}
const SECTION := "game"
## Settings files saved before controllers were named hold BikeSimulation's old integers.
const LEGACY_CONTROLLERS: Array[String] = ["arcade", "manual", "optimizer", "combined"]

## The player's own files: settings, best laps, and the folder of ghosts of best laps
## (one file a level, `GhostFile`).
const PLAYER_SETTINGS := "user://settings.cfg"
const PLAYER_RECORDS := "user://records.cfg"
const PLAYER_GHOSTS := "user://ghosts"

var settings_path := PLAYER_SETTINGS
var records_path := PLAYER_RECORDS
var ghosts_dir := PLAYER_GHOSTS

var _values := {}
var _records := ConfigFile.new()


func _ready() -> void:
	reload()


## Reads both files again (used at start and by tests that point the paths elsewhere).
func reload() -> void:
	_values = DEFAULTS.duplicate()
	var config := ConfigStore.load_or_empty(settings_path)
	for key: StringName in DEFAULTS:
		var value: Variant = config.get_value(SECTION, key, DEFAULTS[key])
		if key == &"controller":
			value = _controller_name(value)
		elif key == &"camera" and not FollowCamera.MODES.has(value):
			push_warning("settings: no camera mode is called %s; using the default" % value)
			value = DEFAULTS[key]
		if typeof(value) == typeof(DEFAULTS[key]):
			_values[key] = value
		elif typeof(DEFAULTS[key]) == TYPE_FLOAT and typeof(value) == TYPE_INT:
			_values[key] = float(value)
		else:
			push_warning("settings: ignoring %s = %s (wrong type)" % [key, value])
	_records = ConfigStore.load_or_empty(records_path)
	_apply_master_volume()


## A saved controller as a name players can pick: old integers become names, anything
## else unknown the default.
static func _controller_name(saved: Variant) -> String:
	if typeof(saved) == TYPE_INT and saved >= 0 and saved < LEGACY_CONTROLLERS.size():
		saved = LEGACY_CONTROLLERS[saved]
	if typeof(saved) == TYPE_STRING and NativeModule.controller_names().has(saved):
		return saved
	push_warning("settings: controller %s is not one players pick; using the default" % saved)
	return DEFAULTS[&"controller"]


## The value of setting `key`.
func get_value(key: StringName) -> Variant:
	assert(DEFAULTS.has(key), "unknown setting %s" % key)
	return _values.get(key, DEFAULTS.get(key))


## Sets and saves setting `key`; an unknown key or a value of the wrong type is refused.
func set_value(key: StringName, value: Variant) -> void:
	if not DEFAULTS.has(key):
		push_error("settings: unknown setting %s" % key)
		return
	if typeof(value) != typeof(DEFAULTS[key]):
		push_error(
			"settings: %s must be %s, not %s" % [key, type_string(typeof(DEFAULTS[key])), value]
		)
		return
	if key == &"controller" and not NativeModule.controller_names().has(value):
		push_error("settings: no controller is called '%s'" % value)
		return
	if key == &"camera" and not FollowCamera.MODES.has(value):
		push_error("settings: no camera mode is called '%s'" % value)
		return
	if _values[key] == value:
		return
	_values[key] = value
	var config := ConfigFile.new()
	for k: StringName in _values:
		config.set_value(SECTION, k, _values[k])
	ConfigStore.save(config, settings_path)
	if key == &"master_volume":
		_apply_master_volume()
	changed.emit(key)


## What the menus' trajectory list shows: "auto", then each fixed count.
static func trajectory_labels() -> PackedStringArray:
	var limits := BikeSimulation.auto_trajectory_limits()
	var labels := PackedStringArray(["auto trajectories (%d–%d)" % [limits.x, limits.y]])
	for count in TRAJECTORY_CHOICES:
		labels.append("%d trajectories" % count)
	return labels


## The entry of `trajectory_labels()` the settings hold (a fixed count no menu offers
## shows as the nearest offered).
func trajectory_choice() -> int:
	if get_value(&"auto_trajectories"):
		return 0
	var count: int = get_value(&"trajectories")
	var nearest := 0
	for i in TRAJECTORY_CHOICES.size():
		if absi(TRAJECTORY_CHOICES[i] - count) < absi(TRAJECTORY_CHOICES[nearest] - count):
			nearest = i
	return nearest + 1


## Picks entry `index` of `trajectory_labels()`: auto, or a fixed count.
func choose_trajectories(index: int) -> void:
	if index <= 0:
		set_value(&"auto_trajectories", true)
		return
	set_value(&"trajectories", TRAJECTORY_CHOICES[mini(index, TRAJECTORY_CHOICES.size()) - 1])
	set_value(&"auto_trajectories", false)


## The master bus plays at the player's volume (silent at 0).
func _apply_master_volume() -> void:
	var volume := clampf(get_value(&"master_volume"), 0.0, 1.0)
	AudioServer.set_bus_mute(0, volume <= 0.0)
	AudioServer.set_bus_volume_db(0, linear_to_db(maxf(volume, 1e-4)))


## The file the ghost of the best lap on `level` is kept in.
func ghost_path(level: String) -> String:
	return ghosts_dir.path_join(level.validate_filename() + ".ghost")


## Best lap time (s) on `level`, or INF when there is none.
func best_lap(level: String) -> float:
	return float(_records.get_value("best_laps", level, INF))


## Records `seconds` as a lap of `level`; returns true when it is a new best (then saved).
func record_lap(level: String, seconds: float) -> bool:
	if not (is_finite(seconds) and seconds > 0.0) or seconds >= best_lap(level):
		return false
	_records.set_value("best_laps", level, seconds)
	ConfigStore.save(_records, records_path)
	return true
