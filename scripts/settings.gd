extends Node
## The player's settings and records (autoload `Settings`). Every change is saved at once,
## atomically, to `user://settings.cfg`, and best laps to `user://records.cfg` (their
## ghosts under `user://ghosts/`), so a crash or a kill loses nothing.

## A setting changed (by a menu or by a key); `key` is its name.
signal changed(key: StringName)
## Every setting was read again from the files (`reload`).
signal reloaded

const SECTION := "game"
## Settings files saved before controllers were named hold BikeSimulation's old integers.
const LEGACY_CONTROLLERS: Array[String] = ["arcade", "manual", "optimizer", "combined"]

## The player's own files: settings, best laps, and the folder of ghosts of best laps
## (one file a level, `GhostFile`).
const PLAYER_SETTINGS := "user://settings.cfg"
const PLAYER_RECORDS := "user://records.cfg"
const PLAYER_GHOSTS := "user://ghosts"

## The settings kept in the player's file: the native schema's entries players see
## (`SettingsSchema.entries()`), by name. Each entry's default is also its type: a loaded
## value of another type is ignored.
var entries := {}
## Each player setting's default, by name: the entry's `player_default` where the game
## starts elsewhere than the tools do (the learned cost-to-go), its `default` else.
var defaults := {}

var settings_path := PLAYER_SETTINGS
var records_path := PLAYER_RECORDS
var ghosts_dir := PLAYER_GHOSTS

var _values := {}
var _records := ConfigFile.new()


func _ready() -> void:
	reload()


## Reads the schema and both files again (used at start, by tests that point the paths
## elsewhere, and after the schema was extended).
func reload() -> void:
	entries = {}
	defaults = {}
	for entry in SettingsSchema.entries():
		if entry.player:
			entries[entry.name] = entry
			defaults[entry.name] = entry.get("player_default", entry.default)
	_values = defaults.duplicate()
	var config := ConfigStore.load_or_empty(settings_path)
	for key: StringName in defaults:
		var value: Variant = config.get_value(SECTION, key, defaults[key])
		if key == &"controller":
			value = _controller_name(value)
		var fitted: Variant = _fitted(key, value)
		if fitted == null:
			push_warning("settings: ignoring %s = %s (%s)" % [key, value, _refusal(key, value)])
		else:
			_values[key] = fitted
	_records = ConfigStore.load_or_empty(records_path)
	_apply_master_volume()
	_apply_ui_scale()
	reloaded.emit()


## A saved controller as a name players can pick: old integers become names, anything
## else unknown the default.
static func _controller_name(saved: Variant) -> String:
	if typeof(saved) == TYPE_INT and saved >= 0 and saved < LEGACY_CONTROLLERS.size():
		saved = LEGACY_CONTROLLERS[saved]
	if typeof(saved) == TYPE_STRING and NativeModule.controller_names().has(saved):
		return saved
	push_warning("settings: controller %s is not one players pick; using the default" % saved)
	return schema_entry(&"controller").default


## The schema's entry of setting `key` (empty for none).
static func schema_entry(key: StringName) -> Dictionary:
	for entry in SettingsSchema.entries():
		if entry.name == key:
			return entry
	return {}


## The values menus offer for setting `key`, as whole numbers.
static func offered(key: StringName) -> Array[int]:
	var values: Array[int] = []
	for value: float in schema_entry(key).get("offered", PackedFloat64Array()):
		values.append(roundi(value))
	return values


## `value` as setting `key` holds it (a whole number for a number setting is taken), or
## null when the setting may not hold it.
func _fitted(key: StringName, value: Variant) -> Variant:
	var entry: Dictionary = entries[key]
	var default: Variant = entry.default
	if typeof(default) == TYPE_FLOAT and typeof(value) == TYPE_INT:
		value = float(value)
	if typeof(value) != typeof(default):
		return null
	if entry.has("min") and not (value >= entry.min and value <= entry.max):
		return null
	if key == &"controller" and not NativeModule.controller_names().has(value):
		return null
	if not entry.choices.is_empty() and not entry.choices.has(value):
		return null
	return value


## Why setting `key` may not hold `value`.
func _refusal(key: StringName, value: Variant) -> String:
	if not entries.has(key):
		return "no player setting is called %s" % key
	var entry: Dictionary = entries[key]
	if (
		typeof(value) != typeof(entry.default)
		and not (typeof(entry.default) == TYPE_FLOAT and typeof(value) == TYPE_INT)
	):
		return "it takes %s" % type_string(typeof(entry.default))
	if entry.has("min"):
		return (
			"it is within %s–%s %s" % [number_text(entry.min), number_text(entry.max), entry.unit]
		)
	if not entry.choices.is_empty():
		return "it is one of %s" % ", ".join(entry.choices)
	return "no %s is called %s" % [key, value]


## `x` as menus and messages write it: whole numbers without a decimal point.
static func number_text(x: float) -> String:
	return "%d" % x if x == roundf(x) else str(x)


## The value of setting `key`.
func get_value(key: StringName) -> Variant:
	assert(defaults.has(key), "unknown setting %s" % key)
	return _values.get(key, defaults.get(key))


## Sets and saves setting `key`; an unknown key, a value of the wrong type or out of the
## setting's range, or a name that is not one of its choices (or no controller's), is refused.
func set_value(key: StringName, value: Variant) -> void:
	var fitted: Variant = _fitted(key, value) if defaults.has(key) else null
	if fitted == null or fitted != value:
		push_error("settings: %s = %s refused (%s)" % [key, value, _refusal(key, value)])
		return
	if _values[key] == fitted:
		return
	_values[key] = fitted
	var config := ConfigFile.new()
	for k: StringName in _values:
		config.set_value(SECTION, k, _values[k])
	ConfigStore.save(config, settings_path)
	if key == &"master_volume":
		_apply_master_volume()
	elif key == &"ui_scale":
		_apply_ui_scale()
	changed.emit(key)
	if key == &"assist":
		# A level stands for a set of settings: choosing one sets them.
		Assists.apply(fitted)


## What the menus' trajectory list shows: "auto", then each fixed count.
static func trajectory_labels() -> PackedStringArray:
	var limits := BikeSimulation.auto_trajectory_limits()
	var labels := PackedStringArray(["auto trajectories (%d–%d)" % [limits.x, limits.y]])
	for count in offered(&"trajectories"):
		labels.append("%d trajectories" % count)
	return labels


## The entry of `trajectory_labels()` the settings hold (a fixed count no menu offers
## shows as the nearest offered).
func trajectory_choice() -> int:
	if get_value(&"auto_trajectories"):
		return 0
	var count: int = get_value(&"trajectories")
	var choices := offered(&"trajectories")
	var nearest := 0
	for i in choices.size():
		if absi(choices[i] - count) < absi(choices[nearest] - count):
			nearest = i
	return nearest + 1


## Picks entry `index` of `trajectory_labels()`: auto, or a fixed count.
func choose_trajectories(index: int) -> void:
	if index <= 0:
		set_value(&"auto_trajectories", true)
		return
	var choices := offered(&"trajectories")
	set_value(&"trajectories", choices[mini(index, choices.size()) - 1])
	set_value(&"auto_trajectories", false)


## The master bus plays at the player's volume (silent at 0).
func _apply_master_volume() -> void:
	var volume := clampf(get_value(&"master_volume"), 0.0, 1.0)
	AudioServer.set_bus_mute(0, volume <= 0.0)
	AudioServer.set_bus_volume_db(0, linear_to_db(maxf(volume, 1e-4)))


## Menus and the HUD are drawn at the player's size: the window's canvas (1280 × 720 at
## 100 %, stretched to the window) shrinks as they grow.
func _apply_ui_scale() -> void:
	if is_inside_tree():
		get_tree().root.content_scale_factor = float(get_value(&"ui_scale")) / 100.0


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
