class_name BotStart
extends RefCounted
## Test helper: the game on a level ridden by a BotRider, the ride repeatable (it waits
## for every plan), and straight paths for the bot to follow.

const GAME := preload("res://scenes/game/game.tscn")


## Starts `level_path` under `test` with `controller` and bike `bike` (a `Bikes` key; the
## settings' default when empty), lets it run two physics frames and puts a bot on the
## level's lap path (if it has one). Returns [game, bot].
static func start(test: TestCase, level_path: String, controller: String, bike := "") -> Array:
	Settings.set_value(&"controller", controller)
	if not bike.is_empty():
		Settings.set_value(&"bike", bike)
	var game := GAME.instantiate() as Game
	game.level_path = level_path
	test.add_child(game)
	# Before the first step: a ride that waits for every plan repeats exactly.
	game.bike.wait_for_every_plan = true
	await test.wait_physics_frames(2)
	var bot := BotRider.new()
	bot.bike = game.bike
	bot.path = game.level.get_node_or_null("Lap")
	test.add_child(bot)
	return [game, bot]


## A straight Path3D from `from` to `to` (for a bot's `path`, once in the tree).
static func straight(from: Vector3, to: Vector3) -> Path3D:
	var path := Path3D.new()
	path.curve = Curve3D.new()
	path.curve.add_point(from)
	path.curve.add_point(to)
	return path
