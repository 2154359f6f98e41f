class_name LessonRide
extends RefCounted
## Test helper: a lesson or challenge ridden by a BotRider whose hands are a gamepad's
## (PadHands), as repeatable as the bot rides (the game waits for every plan).

const GAME := preload("res://scenes/game/game.tscn")

var game: Game
var bot: BotRider


## Starts the challenge at `path` under `test` with `controller` on bike `bike` (a `Bikes`
## key; the settings' default when empty), with a bot that follows `path_3d` (added to
## the tree) at `kmh`.
static func start(
	test: TestCase, path: String, controller: String, bike := "", kmh := 20.0
) -> LessonRide:
	for action: StringName in InputMap.get_actions():
		Input.action_release(action)
	Settings.set_value(&"controller", controller)
	if not bike.is_empty():
		Settings.set_value(&"bike", bike)
	var ride := LessonRide.new()
	ride.game = GAME.instantiate() as Game
	ride.game.challenge_path = path
	test.add_child(ride.game)
	ride.game.bike.wait_for_every_plan = true
	await test.wait_physics_frames(2)
	ride.bot = BotRider.new()
	ride.bot.bike = ride.game.bike
	ride.bot.through_pad = true
	ride.bot.steady_at_speed = true
	ride.bot.speed_kmh = kmh
	test.add_child(ride.bot)
	return ride


## Follows `path` (added under `test`) from now on.
func follow(test: TestCase, path: Path3D) -> void:
	test.add_child(path)
	bot.path = path


## Rides until the attempt is judged (at most `seconds` of riding); returns its result
## (null: none in time). The bot lets go once it is judged.
func until_judged(test: TestCase, seconds: float) -> ChallengeResult:
	var run := game.challenge_run
	for _i in roundi(seconds * Engine.physics_ticks_per_second):
		await test.wait_physics_frames(1)
		if run.result != null:
			break
	bot.release()
	bot.path = null
	return run.result


## Frees the game and the bot.
func free_all() -> void:
	if bot != null:
		bot.release()
		bot.queue_free()
	if game != null:
		game.queue_free()
