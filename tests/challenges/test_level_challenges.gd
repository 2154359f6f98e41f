extends TestCase
## The levels' challenges ridden by the bot through a gamepad's events on the game's bike
## with the game's controller (ChallengeBot): each earns gold, and each judge fails a ride
## that misses its goal (a checkpoint missed, a ride too slow, a jump never taken).

var _bot: ChallengeBot


func before_each() -> void:
	SettingsSandbox.enter()
	_bot = ChallengeBot.new(self)


func after_each() -> void:
	_bot.free_all()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_a_time_trial_lap_of_the_track_at_30_kmh_for_gold() -> void:
	var result := await _bot.track_time_trial()
	_assert_medal(result, Challenge.Medal.GOLD)
	# The Track's own rules ran too: the lap is the best.
	assert_almost_eq(Settings.best_lap("track"), result.score if result else NAN, 1e-6)


func test_the_time_trial_fails_a_lap_that_skips_its_checkpoints() -> void:
	_bot.ride = await LessonRide.start(
		self, ChallengeBot.LEVELS + "track_time_trial.tres", "combined", "", 12.0
	)
	# Over the start line, round a loop on the grass and over it again.
	var loop := BotStart.straight(Vector3(0, 0, 6), Vector3(0, 0, -8))
	for point: Vector3 in [
		Vector3(-8, 0, -14),
		Vector3(-16, 0, -6),
		Vector3(-16, 0, 10),
		Vector3(-8, 0, 18),
		Vector3(0, 0, 10),
		Vector3(0, 0, -20)
	]:
		loop.curve.add_point(point)
	_bot.ride.follow(self, loop)
	_assert_failed(await _bot.ride.until_judged(self, 60.0), "you missed checkpoint 1")


func test_the_skate_parks_gates_at_20_kmh_for_gold() -> void:
	_assert_medal(await _bot.park_gates(), Challenge.Medal.GOLD)


func test_the_skate_parks_longest_wheelie_for_gold() -> void:
	_assert_medal(await _bot.park_wheelie(), Challenge.Medal.GOLD)


func test_air_time_off_the_funbox_at_35_kmh_for_gold() -> void:
	_assert_medal(await _bot.park_air(), Challenge.Medal.GOLD)


func test_air_time_fails_a_ride_too_slow_to_leave_the_ground() -> void:
	_assert_failed(await _bot.park_air(20.0), "you never left the ground")


func test_the_thesis_test_steered_by_the_player_at_30_kmh_for_gold() -> void:
	_assert_medal(await _bot.thesis_run(), Challenge.Medal.GOLD)
	assert_false(_bot.ride.game.is_automatic(), "the player rides it, not the level")


func test_the_thesis_test_fails_out_of_time() -> void:
	_assert_failed(await _bot.thesis_run(4.0), "out of time: this one takes at most 0:25.0")


func _assert_medal(result: ChallengeResult, medal: Challenge.Medal) -> void:
	ChallengeBot.assert_medal(self, _bot, result, medal)


func _assert_failed(result: ChallengeResult, why: String) -> void:
	ChallengeBot.assert_failed(self, _bot, result, why)
