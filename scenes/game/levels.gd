class_name Levels
extends RefCounted
## The levels the game offers, by the key settings store.

const ALL := {
	"test_level": "res://scenes/levels/test_level/test_level.tscn",
	"track": "res://scenes/levels/track/track.tscn",
	"skate_park": "res://scenes/levels/skate_park/skate_park.tscn",
}
const NAMES := {
	"test_level": "Thesis test (rides itself)",
	"track": "Track",
	"skate_park": "Skate park",
}


## Path of the level scene for `key`, or "" for an unknown key.
static func path_of(key: String) -> String:
	return ALL.get(key, "")


## The key of the level scene at `path` (empty: not one of the game's levels).
static func key_of(path: String) -> String:
	for key: String in ALL:
		if ALL[key] == path:
			return key
	return ""
