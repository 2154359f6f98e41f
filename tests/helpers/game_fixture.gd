class_name GameFixture
extends RefCounted
## Test helper: the game on a level with nothing held over from another suite (no action
## pressed, scratch settings), and the ways tests make its bike fall.

const GAME := preload("res://scenes/game/game.tscn")
const TRACK := "res://scenes/levels/track/track.tscn"


## Starts the game on `level_path` under `test` and lets it run two physics frames.
static func start(test: TestCase, level_path := TRACK) -> Game:
	for action: StringName in InputMap.get_actions():
		Input.action_release(action)
	SettingsSandbox.enter()
	var game := GAME.instantiate() as Game
	game.level_path = level_path
	test.add_child(game)
	await test.wait_physics_frames(2)
	return game


## Rides off with nobody balancing (the manual controller) and nudges the bar: an
## upright bike nobody balances stays up only while nothing disturbs it (the exact
## physics has no solver noise to tip it). Leaves the throttle held.
static func ride_unbalanced_and_nudge(test: TestCase, game: Game) -> void:
	game.bike.controller = "manual"
	Input.action_press(&"throttle")
	await test.wait_physics_frames(60)
	Input.action_press(&"steer_left", 0.5)
	await test.wait_physics_frames(10)
	Input.action_release(&"steer_left")
