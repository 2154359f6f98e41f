extends TestCase
## The dirt 125 and the sport 600 ride the levels as the street bike does (test_bot_rides.gd
## rides that one), with no controller tuned for them: a lap of the track and the skate
## park's steps at walking pace with arcade, and a full brake from the top speed with the
## game's controller. (The game's controller on the steps at 10 km/h, which the street bike
## climbs, is not yet: each of these fell on the 0.22 m step in some runs.)

const TRACK := "res://scenes/levels/track/track.tscn"
const SKATE_PARK := "res://scenes/levels/skate_park/skate_park.tscn"
const OTHER_BIKES: Array[String] = ["dirt_125", "sport_600"]

var _game: Game
var _bot: BotRider
## How the last fall happened (the crash's cause), for the failure's message.
var _crash := ""


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	await _leave()
	SettingsSandbox.leave()


func _leave() -> void:
	if _bot != null:
		_bot.release()
		_bot.queue_free()
		_bot = null
	if _game != null:
		_game.queue_free()
		_game = null
	await wait_frames(1)


func _ride(level: String, controller: String, bike: String) -> void:
	await _leave()
	var started: Array = await BotStart.start(self, level, controller, bike)
	_game = started[0]
	_bot = started[1]
	_crash = ""
	_game.bike.crashed.connect(func(cause: String) -> void: _crash = cause)


## Steps until `done` says so or `seconds` of the level pass; false (with the failure)
## when the bike fell on the way.
func _until(done: Callable, seconds: float, what: String) -> bool:
	while not done.call() and _game.level.elapsed < seconds:
		await wait_physics_frames(1)
		if _game.bike.is_crashed():
			var at := _game.bike.get_center_of_mass()
			fail_test("%s fell %s at %s: %s" % [_game.bike_name(), what, at, _crash])
			return false
	return true


func test_a_lap_of_the_track_at_25_kmh_with_arcade_on_each_bike() -> void:
	for bike: String in OTHER_BIKES:
		await _ride(TRACK, "arcade", bike)
		_bot.speed_kmh = 25.0
		var laps: Array[String] = []
		_game.level.announced.connect(func(text: String) -> void: laps.append(text))
		if not await _until(func() -> bool: return not laps.is_empty(), 90.0, "on the lap"):
			return
		assert_eq(laps.size(), 1, "%s: one lap within 90 s" % bike)
		assert_eq((_game.level as Track).record_key, "track@" + bike, "its own best lap")
		print("bot lap on the %s (arcade at 25 km/h): %s" % [_game.bike_name(), laps])


func test_the_skate_parks_steps_at_walking_pace_with_arcade_on_each_bike() -> void:
	for bike: String in OTHER_BIKES:
		await _ride(SKATE_PARK, "arcade", bike)
		_game.cycle_spawn(2)
		await wait_physics_frames(2)
		var lane := BotStart.straight(Vector3(-12, 0, 8), Vector3(-12, 0, -24))
		add_child(lane)
		_bot.path = lane
		_bot.speed_kmh = 8.0
		var rear_on_high_step := [0.0]
		var over := func() -> bool:
			var rear := _game.bike.get_body_transform(BikeSimulation.REAR_WHEEL).origin
			if rear.z < -14.3 and rear.z > -16.8:
				rear_on_high_step[0] = maxf(rear_on_high_step[0], rear.y)
			return _game.bike.get_center_of_mass().z < -18.0
		if not await _until(over, 20.0, "on the steps"):
			return
		assert_true(over.call(), "%s: over both steps within 20 s" % bike)
		# The wheel's centre its radius above the 0.22 m step's top.
		var on_top := 0.22 + _game.bike.get_wheel_radius()
		assert_almost_eq(rear_on_high_step[0], on_top, 0.03, "%s rode the high step" % bike)
		lane.queue_free()


func test_a_full_brake_from_the_top_speed_on_each_bike() -> void:
	for bike: String in OTHER_BIKES:
		await _ride(TRACK, "combined", bike)
		var straight := BotStart.straight(Vector3(0, 0, 6), Vector3(0, 0, -40))
		add_child(straight)
		_bot.path = straight
		_bot.speed_kmh = 40.0
		var fastest := [0.0]
		var down_the_straight := func() -> bool:
			fastest[0] = maxf(fastest[0], _game.bike.get_speed())
			return _game.bike.get_center_of_mass().z < -10.0
		if not await _until(down_the_straight, 10.0, "speeding up"):
			return
		_bot.speed_kmh = 0.0
		var braked_at := _game.bike.get_center_of_mass().z
		var braked_from := _game.bike.get_speed()
		var stopped := func() -> bool: return absf(_game.bike.get_speed()) < 0.05
		if not await _until(stopped, _game.level.elapsed + 6.0, "braking"):
			return
		var distance := braked_at - _game.bike.get_center_of_mass().z
		var mean_g := braked_from * braked_from / (2.0 * distance) / 9.81
		var grip: float = _game.bike.bike.figures().tyre_friction
		assert_gt(fastest[0] * 3.6, 30.0, "%s braked from over 30 km/h" % bike)
		assert_true(stopped.call(), "%s stands still" % bike)
		# The street bike brakes at about 0.9 of its tyres' grip; knobblies grip less.
		assert_gt(mean_g, 0.75 * grip, "%s: a full brake's mean deceleration (g)" % bike)
		await wait_physics_frames(60)
		assert_false(_game.bike.is_crashed(), "%s stands after the stop" % bike)
		print(
			(
				"bot full brake on the %s from %.0f km/h: %.1f m (%.2f g; tyres μ %.2f)"
				% [_game.bike_name(), fastest[0] * 3.6, distance, mean_g, grip]
			)
		)
		straight.queue_free()
