extends TestCase
## The levels' challenges ridden by the bot through a gamepad's events on the game's bike
## with the game's controller: each earns gold, and each judge fails a ride that misses
## its goal (a checkpoint missed, a ride too slow, a jump never taken).

const LEVELS := "res://scenes/challenges/levels/"

var _ride: LessonRide


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	if _ride != null:
		_ride.free_all()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_a_time_trial_lap_of_the_track_at_30_kmh_for_gold() -> void:
	_ride = await LessonRide.start(self, LEVELS + "track_time_trial.tres", "combined", "", 30.0)
	_ride.bot.path = _ride.game.level.get_node("Lap")
	var result := await _ride.until_judged(self, 120.0)
	_assert_medal(result, Challenge.Medal.GOLD)
	# The Track's own rules ran too: the lap is the best, with its ghost.
	assert_almost_eq(Settings.best_lap("track"), result.score if result else NAN, 1e-6)


func test_the_time_trial_fails_a_lap_that_skips_its_checkpoints() -> void:
	_ride = await LessonRide.start(self, LEVELS + "track_time_trial.tres", "combined", "", 12.0)
	# Over the start line, round a loop on the grass and over it again.
	var path := Path3D.new()
	path.curve = Curve3D.new()
	for point: Vector3 in [
		Vector3(0, 0, 6),
		Vector3(0, 0, -8),
		Vector3(-8, 0, -14),
		Vector3(-16, 0, -6),
		Vector3(-16, 0, 10),
		Vector3(-8, 0, 18),
		Vector3(0, 0, 10),
		Vector3(0, 0, -20)
	]:
		path.curve.add_point(point)
	_ride.follow(self, path)
	_assert_failed(await _ride.until_judged(self, 60.0), "you missed checkpoint 1")


func test_the_skate_parks_gates_at_20_kmh_for_gold() -> void:
	_ride = await LessonRide.start(self, LEVELS + "park_gates.tres", "combined", "", 20.0)
	_ride.follow(self, _round_the_kicker())
	_assert_medal(await _ride.until_judged(self, 60.0), Challenge.Medal.GOLD)


func test_the_skate_parks_longest_wheelie_for_gold() -> void:
	_ride = await LessonRide.start(self, LEVELS + "park_wheelie.tres", "combined", "", 8.0)
	_ride.follow(self, BotStart.straight(Vector3(-5, 0, 28), Vector3(-5, 0, -25)))
	await wait_physics_frames(Engine.physics_ticks_per_second)
	_ride.bot.wheelie = true
	_assert_medal(await _ride.until_judged(self, 40.0), Challenge.Medal.GOLD)


func test_air_time_off_the_funbox_at_35_kmh_for_gold() -> void:
	var result := await _funbox(35.0)
	_assert_medal(result, Challenge.Medal.GOLD)


func test_air_time_fails_a_ride_too_slow_to_leave_the_ground() -> void:
	_assert_failed(await _funbox(20.0), "you never left the ground")


func test_the_thesis_test_steered_by_the_player_at_30_kmh_for_gold() -> void:
	var result := await _thesis_run(30.0)
	_assert_medal(result, Challenge.Medal.GOLD)
	assert_false(_ride.game.is_automatic(), "the player rides it, not the level")


func test_the_thesis_test_fails_out_of_time() -> void:
	_assert_failed(await _thesis_run(4.0), "out of time: this one takes at most 0:25.0")


func _funbox(kmh: float) -> ChallengeResult:
	_ride = await LessonRide.start(self, LEVELS + "park_air.tres", "combined", "", kmh)
	_ride.bot.level_in_air = true
	_ride.follow(self, BotStart.straight(Vector3(12, 0, 16), Vector3(12, 0, -25)))
	return await _ride.until_judged(self, 40.0)


func _thesis_run(kmh: float) -> ChallengeResult:
	_ride = await LessonRide.start(self, LEVELS + "thesis_run.tres", "combined", "", kmh)
	_ride.follow(self, BotStart.straight(Vector3(0, 0, 2), Vector3(0, 0, -60)))
	return await _ride.until_judged(self, 30.0)


## Left of the skate park's kicker, round behind it on a 5 m circle and back up its right.
static func _round_the_kicker() -> Path3D:
	var k := 0.5523 * 5.0
	var path := Path3D.new()
	path.curve = Curve3D.new()
	path.curve.add_point(Vector3(0, 0, 14))
	path.curve.add_point(Vector3(0, 0, 4), Vector3.ZERO, Vector3(0, 0, -3))
	path.curve.add_point(Vector3(-5, 0, -4), Vector3(0, 0, 3), Vector3(0, 0, -2))
	path.curve.add_point(Vector3(-5, 0, -8), Vector3.ZERO, Vector3(0, 0, -k))
	path.curve.add_point(Vector3(0, 0, -13), Vector3(-k, 0, 0), Vector3(k, 0, 0))
	path.curve.add_point(Vector3(5, 0, -8), Vector3(0, 0, -k))
	path.curve.add_point(Vector3(5, 0, 6))
	return path


func _assert_medal(result: ChallengeResult, medal: Challenge.Medal) -> void:
	assert_not_null(result, "judged in time")
	if result == null:
		return
	var challenge := _ride.game.challenge_run.challenge
	assert_true(result.passed, "passed (%s)" % result.why)
	var scored := "%s: %s" % [challenge.title, challenge.format(result.score)]
	assert_eq(challenge.medal_for(result.score), medal, scored)
	print("bot on %s, %s" % [scored, "; ".join(result.facts)])


func _assert_failed(result: ChallengeResult, why: String) -> void:
	assert_not_null(result, "judged in time")
	if result == null:
		return
	assert_false(result.passed, "failed")
	assert_has(result.why, why)
