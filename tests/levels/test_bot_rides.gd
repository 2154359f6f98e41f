extends TestCase
## The levels are rideable as designed, shown by a bot that rides them through the
## player's own input actions (BotRider: throttle, brake and turn, as a gamepad would).

const GAME := preload("res://scenes/game/game.tscn")
const TRACK := "res://scenes/levels/track/track.tscn"

var _game: Game
var _bot: BotRider


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	if _bot != null:
		_bot.release()
		_bot.queue_free()
	if _game != null:
		_game.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_a_lap_of_the_track_with_the_games_controller() -> void:
	# The game's controller and N, waiting for every plan so the ride repeats. At 25 km/h
	# it lands the long hill leaning and falls (issue 14's closing note); 20 km/h it rides.
	await _ride_a_lap("combined", 20.0)


func test_a_lap_of_the_track_at_25_kmh_with_the_arcade_controller() -> void:
	await _ride_a_lap("arcade", 25.0)


## A lap of the track at `kmh` with `controller`: no fall, over the hills and the table,
## and the lap counted and printed (docs/results.md quotes it).
func _ride_a_lap(controller: String, kmh: float) -> void:
	await _start(TRACK, controller)
	_bot.speed_kmh = kmh
	var laps: Array[String] = []
	_game.level.announced.connect(func(text: String) -> void: laps.append(text))
	var highest := 0.0
	var distance := 0.0
	while laps.is_empty() and _game.level.elapsed < 90.0 and not _game.bike.is_crashed():
		await wait_physics_frames(1)
		highest = maxf(highest, _game.bike.get_center_of_mass().y)
		distance += _game.bike.get_speed() / Engine.physics_ticks_per_second
	assert_false(_game.bike.is_crashed(), "fell %.0f m along the lap" % _bot.offset)
	assert_eq(laps.size(), 1, "one lap within 90 s")
	# Over the 1.4 m hill, not around it (the centre of mass rides about 0.7 m up).
	assert_gt(highest, 1.9, "rode over the hills")
	if not laps.is_empty():
		assert_true(laps[0].begins_with("New best lap: "), laps[0])
		var seconds := _game.level.elapsed
		print(
			(
				"bot lap on the track (%s at %.0f km/h): %s, mean speed %.1f km/h"
				% [controller, kmh, laps[0], distance / seconds * 3.6]
			)
		)


func _start(level_path: String, controller: String) -> void:
	Settings.set_value(&"controller", controller)
	_game = GAME.instantiate()
	_game.level_path = level_path
	add_child(_game)
	await wait_physics_frames(2)
	_game.bike.wait_for_every_plan = true
	_bot = BotRider.new()
	_bot.bike = _game.bike
	_bot.path = _game.level.get_node("Lap")
	add_child(_bot)
