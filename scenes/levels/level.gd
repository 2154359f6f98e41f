@tool
class_name Level
extends Node3D
## Base of every level: static collision shapes anywhere below it form the terrain, and
## SpawnPoints mark where the bike starts. Levels with rules (a goal, a lap) override
## `begin_attempt` and `judge`. In the editor the level warns about anything the bike
## simulation cannot use.

## Something worth telling the player (a lap time, a result), shown as a banner.
signal announced(text: String)
## The level's shapes changed (an attempt laid new bumps): whoever simulates on them reads
## the terrain again (`BikeSimulation.rebuild_terrain`).
signal terrain_changed

## Outcomes `judge` returns: still riding, reached the goal, crashed, out of time.
const RIDING := ""
const GOAL := "goal"
const FELL := "fell"
const TIMEOUT := "timeout"
## Below this height the bike has left the level.
const FLOOR_Y := -20.0

## Name shown in menus and the HUD.
@export var title := "Level"
## Forces auto-accelerate on and ignores the turn command (the automatic test level).
@export var automatic := false

## Seconds since the current attempt began.
var elapsed := 0.0


## Makes `bike` read the terrain again whenever this level's shapes change (once per
## bike, however often it is called).
func attach(bike: BikeSimulation) -> void:
	if not terrain_changed.is_connected(bike.rebuild_terrain):
		terrain_changed.connect(bike.rebuild_terrain)


## The level's spawn points, in tree order.
func spawn_points() -> Array[SpawnPoint]:
	var found: Array[SpawnPoint] = []
	_collect_spawn_points(self, found)
	return found


## The level's ChallengeAreas, in tree order.
func challenge_areas() -> Array[ChallengeArea]:
	var areas: Array[ChallengeArea] = []
	for found in find_children("*", "Node3D", true, false):
		if found is ChallengeArea:
			areas.append(found as ChallengeArea)
	return areas


## Starts an attempt (the bike was just placed at a spawn point). `seed_value` varies what
## a level randomises; a level whose shapes change emits `terrain_changed`.
func begin_attempt(_bike: BikeSimulation, _seed_value: int) -> void:
	elapsed = 0.0


## Advances the level's clock by `delta` and says how the attempt stands: RIDING, GOAL,
## FELL or TIMEOUT. Levels without an end only report falls and leaving the level.
func judge(bike: BikeSimulation, delta: float) -> String:
	elapsed += delta
	if bike.is_crashed() or bike.get_center_of_mass().y < FLOOR_Y:
		return FELL
	return RIDING


## The game judged the attempt (`outcome`, not RIDING) and shows its result until the next
## `begin_attempt`: a level may open what only a finished attempt reaches (the test level's
## run-off past its goal). The experiment never calls it, so its attempts ride the level
## exactly as it judges them.
func finish_attempt(_outcome: String) -> void:
	pass


## The ride was put back `seconds` (a rewind, in a free ride): the level's clock goes back
## with it. A level whose records a rewind would falsify (a lap) says so and sets them
## aside.
func rewound(_bike: BikeSimulation, seconds: float) -> void:
	elapsed = maxf(elapsed - seconds, 0.0)


## One line for the HUD about the attempt (timer, lap, best).
func status_line() -> String:
	return "time %s" % format_time(elapsed)


## `seconds` as m:ss.s.
static func format_time(seconds: float) -> String:
	if not is_finite(seconds):
		return "–:––.–"
	return "%d:%04.1f" % [int(seconds) / 60, fmod(seconds, 60.0)]


func _get_configuration_warnings() -> PackedStringArray:
	var warnings := PackedStringArray()
	if spawn_points().is_empty():
		warnings.append("Add at least one SpawnPoint: the bike has nowhere to start.")
	if ClassDB.class_exists(&"TerrainCheck"):
		for problem in TerrainCheck.problems(self):
			warnings.append("The bike simulation cannot use: %s" % problem)
	return warnings


func _collect_spawn_points(node: Node, found: Array[SpawnPoint]) -> void:
	for child in node.get_children():
		if child is SpawnPoint:
			found.append(child)
		_collect_spawn_points(child, found)
