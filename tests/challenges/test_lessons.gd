extends TestCase
## Every lesson of the School ridden by a bot whose hands are a gamepad's (pad axis events
## through the InputMap, as a player's pad sends them), on the game's bike with the game's
## controller, earns gold from the simulation's judge; and each judge fails a ride that
## misses its goal, saying why in a player's words. The rides are ChallengeBot's.

var _bot: ChallengeBot


func before_each() -> void:
	SettingsSandbox.enter()
	_bot = ChallengeBot.new(self)


func after_each() -> void:
	_bot.free_all()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_ride_off_and_stop_in_the_box_for_gold_then_the_next_lesson() -> void:
	var result := await _bot.ride_off()
	_assert_medal(result, Challenge.Medal.GOLD)
	assert_has(result.facts if result else PackedStringArray(), "held 19–21 km/h between the lines")
	# Saved at once, per bike, where the next launch reads it.
	Progress.reload()
	assert_eq(Progress.medal("ride_off", "street_390"), Challenge.Medal.GOLD, "saved")
	assert_eq(Progress.medal("ride_off", "dirt_125"), Challenge.Medal.NONE, "per bike")
	var card := _bot.ride.game.challenge_card
	assert_true(card.is_result_shown())
	assert_has(card.result_text(), "GOLD")
	var asked: Array[bool] = []
	card.next_requested.connect(func() -> void: asked.append(true))
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	assert_eq(asked, [true] as Array[bool], "A on the pad: the next lesson")


func test_ride_off_fails_a_stop_before_the_box_and_a_ride_too_fast() -> void:
	var early := await _bot.ride_off(56.0)
	_assert_failed(early, "you stopped")
	assert_has(early.why if early != null else "", "before the box")
	_assert_failed(await _bot.ride_off(INF), "between the lines: keep to 15–25 km/h")


func test_counter_steer_at_35_kmh_for_gold_telling_the_bar_turned_the_wrong_way() -> void:
	var result := await _bot.counter_steer()
	_assert_medal(result, Challenge.Medal.GOLD)
	if result == null:
		return
	# The S's two turns (the bot may add a correction after them).
	assert_gt(result.facts.size(), 1, "two turns at least: %s" % result.facts)
	if result.facts.size() > 1:
		assert_has(result.facts[0], "a right turn: the bar ")
		assert_has(result.facts[0], "° left first")
		assert_has(result.facts[1], "a left turn: the bar ")


func test_slalom_at_25_kmh_for_gold() -> void:
	_assert_medal(await _bot.slalom(), Challenge.Medal.GOLD)


func test_slalom_fails_a_ride_straight_past_the_gates() -> void:
	_assert_failed(await _bot.slalom(20.0, 0.0), "you missed gate 1")


func test_full_brake_from_60_kmh_for_gold_in_metres_and_g() -> void:
	var result := await _bot.full_brake()
	_assert_medal(result, Challenge.Medal.GOLD)
	if result != null and not result.facts.is_empty():
		# The street 390's full brake: 0.91 g (docs/bike-model.md).
		assert_has(result.facts[0], "braked from 60 km/h in 15.")
		assert_has(result.facts[0], ": 0.9")


func test_full_brake_fails_a_stop_past_the_line_and_a_slow_run_up() -> void:
	_assert_failed(await _bot.full_brake(60.0, 150.0), "you braked too late: stopped ")
	_assert_failed(await _bot.full_brake(45.0, 150.0), "you reached the cones at 4")


func test_a_wheelie_over_the_log_for_gold() -> void:
	_assert_medal(await _bot.wheelie_log(), Challenge.Medal.GOLD)


func test_the_wheelie_fails_when_the_front_wheel_meets_the_log() -> void:
	_assert_failed(await _bot.wheelie_log(-INF), "the front wheel hit the log")


func test_a_hill_start_for_gold() -> void:
	var result := await _bot.hill_start()
	_assert_medal(result, Challenge.Medal.GOLD)
	var facts := result.facts if result != null else PackedStringArray()
	assert_has(facts, "stood 3.0 s, rolled back 0.00 m")


func test_the_hill_start_fails_a_stop_short_of_the_box() -> void:
	_assert_failed(await _bot.hill_start(23.0), "you rode up without stopping in the box")


func test_the_kicker_levelled_with_the_riders_weight_for_gold() -> void:
	var result := await _bot.kicker()
	_assert_medal(result, Challenge.Medal.GOLD)
	assert_has(result.facts[-1] if result != null else "", "landed on both wheels")


func test_the_kicker_fails_a_landing_on_the_front_wheel_and_a_ride_past_it() -> void:
	_assert_failed(await _bot.kicker(35.0, -35.0), "the front wheel landed first")
	_assert_failed(await _bot.kicker(35.0, 0.0, 4.0), "you never left the ground")


func test_the_45_degree_bend_at_60_kmh_for_gold() -> void:
	_assert_medal(await _bot.bend_45(), Challenge.Medal.GOLD)


func test_the_bend_fails_a_ride_that_runs_wide() -> void:
	_assert_failed(await _bot.bend_45(60.0, true), "you missed gate 2")


func test_a_fall_fails_the_lesson_saying_what_hit() -> void:
	# Nobody balancing (the manual controller) and the bot asking for the S's first turn.
	_bot = ChallengeBot.new(self, "", "arcade")
	_bot.ride = await LessonRide.start(
		self, ChallengeBot.LESSONS + "counter_steer.tres", "arcade", "", 30.0
	)
	_bot.ride.game.bike.controller = "manual"
	_bot.ride.follow(self, ChallengeBot.s_bend())
	_assert_failed(await _bot.ride.until_judged(self, 30.0), "you fell: ")
	# Lifting the bike in a lesson starts the attempt again: no judging on from the fall
	# (the result's card first goes, as B or its retry button would take it).
	_bot.ride.game.challenge_card.show_briefing()
	await SimulatedInput.tap_action(&"lift_bike")
	assert_null(_bot.ride.game.challenge_run.result, "a new attempt")
	assert_false(_bot.ride.game.challenge_card.is_result_shown(), "its briefing instead")


func _assert_medal(result: ChallengeResult, medal: Challenge.Medal) -> void:
	ChallengeBot.assert_medal(self, _bot, result, medal)


func _assert_failed(result: ChallengeResult, why: String) -> void:
	ChallengeBot.assert_failed(self, _bot, result, why)
