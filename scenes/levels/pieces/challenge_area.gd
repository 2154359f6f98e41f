@tool
class_name ChallengeArea
extends Node3D
## The part of a level a lesson or challenge is ridden in: the spawn point it starts from
## (the first SpawnPoint below it) and the markers its judge reads by name (gates, lines,
## boxes). Its markers show only while its own lesson or challenge is ridden, so a level
## with many areas shows the player the one in play and a free ride shows none.
## Put only markers here: level geometry stays where every ride meets it. (The level lists
## its areas, `Level.challenge_areas`: a script that names its own class stays loaded past
## an export's exit in Godot 4.6.)

## A spawn point of the level to start from (the track's start, say); empty: the first
## SpawnPoint below this area.
@export var start := NodePath()


## The spawn point the challenge starts from (null: none).
func spawn_point() -> SpawnPoint:
	if not start.is_empty():
		return get_node_or_null(start) as SpawnPoint
	for found in find_children("*", "Marker3D", true, false):
		if found is SpawnPoint:
			return found as SpawnPoint
	return null


## The marker at `path` from this area (below it, or elsewhere in the level as "../Goal"),
## or null.
func marker(path: NodePath) -> Node3D:
	return get_node_or_null(path) as Node3D


func _get_configuration_warnings() -> PackedStringArray:
	if spawn_point() == null:
		return PackedStringArray(
			["Add a SpawnPoint or name one in start: the challenge starts there."]
		)
	return PackedStringArray()
