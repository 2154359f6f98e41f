class_name Levels
extends RefCounted
## The levels the game offers: the choices of the native `level` setting, each a scene of
## that name in a folder of that name under scenes/levels/ (`track` is
## scenes/levels/track/track.tscn), named in menus by its Level's `title`. Adding a level is
## its scene and one choice in the schema (native/cpbp-core/src/settings/entries.rs).

const FOLDER := "res://scenes/levels"
## What the menus add to the name of a level whose bike rides itself (Level.automatic).
const RIDES_ITSELF := " (rides itself)"


## The levels' keys, in the order menus offer them.
static func keys() -> Array[String]:
	var keys: Array[String] = []
	for key: String in Settings.schema_entry(&"level").get("choices", PackedStringArray()):
		keys.append(key)
	return keys


## Path of the level scene for `key`, or "" for a key that is not one of the levels.
static func path_of(key: String) -> String:
	if not keys().has(key):
		return ""
	return FOLDER.path_join(key).path_join(key + ".tscn")


## The key of the level scene at `path` (empty: not one of the game's levels).
static func key_of(path: String) -> String:
	for key in keys():
		if path_of(key) == path:
			return key
	return ""


## The level's name in menus: its scene's title, and whether it rides itself; the key,
## with a warning, for a scene that cannot be read.
static func name_of(key: String) -> String:
	var path := path_of(key)
	var scene := load(path) as PackedScene if ResourceLoader.exists(path) else null
	if scene == null:
		push_warning("Levels: cannot read the level %s at '%s'" % [key, path])
		return key.capitalize()
	var state := scene.get_state()
	var title := key.capitalize()
	var automatic := false
	for property in state.get_node_property_count(0):
		match state.get_node_property_name(0, property):
			&"title":
				title = str(state.get_node_property_value(0, property))
			&"automatic":
				automatic = bool(state.get_node_property_value(0, property))
	return title + (RIDES_ITSELF if automatic else "")
