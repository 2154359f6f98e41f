extends TestCase
## Every lesson of the School ridden by a bot whose hands are a gamepad's (pad axis events
## through the InputMap, as a player's pad sends them), on the game's bike with the game's
## controller, earns gold from the simulation's judge; and each judge fails a ride that
## misses its goal, saying why in a player's words.

const LESSONS := "res://scenes/challenges/lessons/"
## The S of the counter-steering lesson: two quarter circles of 15 m (Bézier handles).
const S_RADIUS := 15.0
const QUARTER := 0.5523

var _ride: LessonRide


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	if _ride != null:
		_ride.free_all()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_ride_off_and_stop_in_the_box_for_gold_then_the_next_lesson() -> void:
	var result := await _ride_off(62.0)
	_assert_medal(result, Challenge.Medal.GOLD)
	assert_has(result.facts, "held 19–21 km/h between the lines")
	# Saved at once, per bike, where the next launch reads it.
	Progress.reload()
	assert_eq(Progress.medal("ride_off", "street_390"), Challenge.Medal.GOLD, "saved")
	assert_eq(Progress.medal("ride_off", "dirt_125"), Challenge.Medal.NONE, "per bike")
	var card := _ride.game.challenge_card
	assert_true(card.is_result_shown())
	assert_has(card.result_text(), "GOLD")
	var asked: Array[bool] = []
	card.next_requested.connect(func() -> void: asked.append(true))
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	assert_eq(asked, [true] as Array[bool], "A on the pad: the next lesson")


func test_ride_off_fails_a_stop_before_the_box_and_a_ride_too_fast() -> void:
	var early := await _ride_off(56.0)
	_assert_failed(early, "you stopped")
	assert_has(early.why if early != null else "", "before the box")
	_ride.free_all()
	_ride = await LessonRide.start(self, LESSONS + "ride_off.tres", "combined", "", 32.0)
	_ride.follow(self, BotStart.straight(Vector3(0, 0, 2), Vector3(0, 0, -90)))
	_assert_failed(await _ride.until_judged(self, 30.0), "between the lines: keep to 15–25 km/h")


func test_counter_steer_at_35_kmh_for_gold_telling_the_bar_turned_the_wrong_way() -> void:
	_ride = await LessonRide.start(self, LESSONS + "counter_steer.tres", "combined", "", 35.0)
	_ride.follow(self, _s_bend())
	var result := await _ride.until_judged(self, 60.0)
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
	_ride = await LessonRide.start(self, LESSONS + "slalom.tres", "combined", "", 25.0)
	_ride.follow(self, _slalom_line(1.6))
	_assert_medal(await _ride.until_judged(self, 60.0), Challenge.Medal.GOLD)


func test_slalom_fails_a_ride_straight_past_the_gates() -> void:
	_ride = await LessonRide.start(self, LESSONS + "slalom.tres", "combined", "", 20.0)
	_ride.follow(self, _slalom_line(0.0))
	_assert_failed(await _ride.until_judged(self, 30.0), "you missed gate 1")


func test_full_brake_from_60_kmh_for_gold_in_metres_and_g() -> void:
	var result := await _full_brake(60.0, 145.0)
	_assert_medal(result, Challenge.Medal.GOLD)
	if result != null and not result.facts.is_empty():
		# The street 390's full brake: 0.91 g (docs/bike-model.md).
		assert_has(result.facts[0], "braked from 60 km/h in 15.")
		assert_has(result.facts[0], ": 0.9")


func test_full_brake_fails_a_stop_past_the_line_and_a_slow_run_up() -> void:
	_assert_failed(await _full_brake(60.0, 150.0), "you braked too late: stopped ")
	_ride.free_all()
	_assert_failed(await _full_brake(45.0, 150.0), "you reached the cones at 4")


func test_a_fall_fails_the_lesson_saying_what_hit() -> void:
	# Nobody balancing (the manual controller) and the bot asking for the S's first turn.
	_ride = await LessonRide.start(self, LESSONS + "counter_steer.tres", "arcade", "", 30.0)
	_ride.game.bike.controller = "manual"
	_ride.follow(self, _s_bend())
	_assert_failed(await _ride.until_judged(self, 30.0), "you fell: ")
	assert_false(_ride.game.challenge_card.result_text().is_empty())


## The ride-off lesson with the bot at 20 km/h braking `brake_at` m along its line.
func _ride_off(brake_at: float) -> ChallengeResult:
	_ride = await LessonRide.start(self, LESSONS + "ride_off.tres", "combined")
	_ride.follow(self, BotStart.straight(Vector3(0, 0, 2), Vector3(0, 0, -90)))
	_ride.bot.speed_along = func(offset: float) -> float: return 20.0 if offset < brake_at else 0.0
	return await _ride.until_judged(self, 40.0)


## The full-brake lesson at `kmh`, the bot braking `brake_at` m along its line.
func _full_brake(kmh: float, brake_at: float) -> ChallengeResult:
	_ride = await LessonRide.start(self, LESSONS + "full_brake.tres", "combined", "", kmh)
	_ride.follow(self, BotStart.straight(Vector3(-40, 0, 2), Vector3(-40, 0, -230)))
	_ride.bot.speed_along = func(offset: float) -> float: return kmh if offset < brake_at else 0.0
	return await _ride.until_judged(self, 60.0)


## The counter-steering lesson's S: a right quarter circle, then a left one.
static func _s_bend() -> Path3D:
	var k := QUARTER * S_RADIUS
	var path := Path3D.new()
	path.curve = Curve3D.new()
	path.curve.add_point(Vector3(30, 0, 2))
	path.curve.add_point(Vector3(30, 0, -30), Vector3.ZERO, Vector3(0, 0, -k))
	path.curve.add_point(Vector3(45, 0, -45), Vector3(-k, 0, 0), Vector3(k, 0, 0))
	path.curve.add_point(Vector3(60, 0, -60), Vector3(0, 0, k))
	path.curve.add_point(Vector3(60, 0, -95))
	return path


## A line through the slalom's gates, `swing` m either side of the lane's middle (0: down
## the middle, past every gate).
static func _slalom_line(swing: float) -> Path3D:
	var path := Path3D.new()
	path.curve = Curve3D.new()
	path.curve.add_point(Vector3(100, 0, 2))
	path.curve.add_point(Vector3(100, 0, -12), Vector3.ZERO, Vector3(0, 0, -4))
	for i in 6:
		var x := 100.0 + (swing if i % 2 == 0 else -swing)
		path.curve.add_point(Vector3(x, 0, -24 - 12 * i), Vector3(0, 0, 5), Vector3(0, 0, -5))
	path.curve.add_point(Vector3(100, 0, -96), Vector3(0, 0, 4), Vector3(0, 0, -4))
	path.curve.add_point(Vector3(100, 0, -115))
	return path


func _assert_medal(result: ChallengeResult, medal: Challenge.Medal) -> void:
	assert_not_null(result, "judged in time")
	if result == null:
		return
	var challenge := _ride.game.challenge_run.challenge
	assert_true(result.passed, "passed (%s)" % result.why)
	assert_eq(
		challenge.medal_for(result.score),
		medal,
		"%s: %s" % [challenge.title, challenge.format(result.score)]
	)
	print(
		(
			"bot on %s: %s, %s"
			% [challenge.title, challenge.format(result.score), "; ".join(result.facts)]
		)
	)


func _assert_failed(result: ChallengeResult, why: String) -> void:
	assert_not_null(result, "judged in time")
	if result == null:
		return
	assert_false(result.passed, "failed")
	assert_has(result.why, why)
	var shown := _ride.game.challenge_card.result_text()
	assert_true(shown.begins_with("Not yet\n"), shown)
	assert_has(shown, result.why.substr(1))
