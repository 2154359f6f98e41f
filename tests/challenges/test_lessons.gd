extends TestCase
## Every lesson of the School ridden by a bot whose hands are a gamepad's (pad axis events
## through the InputMap, as a player's pad sends them), on the game's bike with the game's
## controller, earns gold from the simulation's judge; and each judge fails a ride that
## misses its goal, saying why in a player's words.

const LESSONS := "res://scenes/challenges/lessons/"
## The S of the counter-steering lesson: two quarter circles of 15 m (Bézier handles).
const S_RADIUS := 15.0
const QUARTER := 0.5523
## The 45° bend's radius, and where the wheelie lesson's log lies.
const BEND_RADIUS := 30.0
const LOG_Z := -30.0

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


func test_a_wheelie_over_the_log_for_gold() -> void:
	var result := await _wheelie(-22.0)
	_assert_medal(result, Challenge.Medal.GOLD)


func test_the_wheelie_fails_when_the_front_wheel_meets_the_log() -> void:
	_assert_failed(await _wheelie(-INF), "the front wheel hit the log")


func test_a_hill_start_for_gold() -> void:
	var result := await _hill_start(25.0)
	_assert_medal(result, Challenge.Medal.GOLD)
	assert_has(
		result.facts if result != null else PackedStringArray(), "stood 3.0 s, rolled back 0.00 m"
	)


func test_the_hill_start_fails_a_stop_short_of_the_box() -> void:
	_assert_failed(await _hill_start(23.0), "you rode up without stopping in the box")


func test_the_kicker_levelled_with_the_riders_weight_for_gold() -> void:
	var result := await _kicker(35.0, 0.0)
	_assert_medal(result, Challenge.Medal.GOLD)
	assert_has(result.facts[-1] if result != null else "", "landed on both wheels")


func test_the_kicker_fails_a_landing_on_the_front_wheel_and_a_ride_past_it() -> void:
	_assert_failed(await _kicker(35.0, -35.0), "the front wheel landed first")
	_ride.free_all()
	_assert_failed(await _kicker(35.0, 0.0, 4.0), "you never left the ground")


func test_the_45_degree_bend_at_60_kmh_for_gold() -> void:
	_ride = await LessonRide.start(self, LESSONS + "bend_45.tres", "combined", "", 60.0)
	_ride.follow(self, _half_circle(BEND_RADIUS))
	_assert_medal(await _ride.until_judged(self, 40.0), Challenge.Medal.GOLD)


func test_the_bend_fails_a_ride_that_runs_wide() -> void:
	_ride = await LessonRide.start(self, LESSONS + "bend_45.tres", "combined", "", 60.0)
	_ride.follow(self, BotStart.straight(Vector3(160, 0, 2), Vector3(160, 0, -200)))
	_assert_failed(await _ride.until_judged(self, 30.0), "you missed gate 2")


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


## The wheelie lesson at 10 km/h, the bot's weight back from its front wheel at z
## `lift` (−INF: never) until the front wheel is past the log.
func _wheelie(lift: float) -> ChallengeResult:
	_ride = await LessonRide.start(self, LESSONS + "wheelie_log.tres", "combined", "", 10.0)
	_ride.follow(self, BotStart.straight(Vector3(-80, 0, 2), Vector3(-80, 0, -60)))
	var run := _ride.game.challenge_run
	for _i in 40 * Engine.physics_ticks_per_second:
		await wait_physics_frames(1)
		var front := _ride.game.bike.get_body_transform(BikeSimulation.FRONT_WHEEL).origin
		_ride.bot.wheelie = front.z < lift and front.z > LOG_Z - 1.0
		if run.result != null:
			break
	_ride.bot.wheelie = false
	return await _ride.until_judged(self, 0.0)


## The hill start at 10 km/h: the bot brakes `stop_at` m along its line, stands 5 s, and
## rides on.
func _hill_start(stop_at: float) -> ChallengeResult:
	_ride = await LessonRide.start(self, LESSONS + "hill_start.tres", "combined", "", 10.0)
	_ride.follow(self, BotStart.straight(Vector3(-110, 0, 2), Vector3(-110, 0, -60)))
	var stood := 5.0 * Engine.physics_ticks_per_second
	var braked_at := [-1]
	_ride.bot.speed_along = func(offset: float) -> float:
		if braked_at[0] < 0 and offset > stop_at:
			braked_at[0] = Engine.get_physics_frames()
		var standing: bool = (
			braked_at[0] >= 0 and Engine.get_physics_frames() - braked_at[0] < stood
		)
		return 0.0 if standing else 10.0
	return await _ride.until_judged(self, 60.0)


## The kicker at `kmh`, the bot's weight bringing the bike to `pitch` degrees in the air,
## its line `aside` m to the right of the kicker's middle.
func _kicker(kmh: float, pitch: float, aside := 0.0) -> ChallengeResult:
	_ride = await LessonRide.start(self, LESSONS + "kicker.tres", "combined", "", kmh)
	_ride.bot.level_in_air = true
	_ride.bot.air_pitch = pitch
	_ride.follow(self, BotStart.straight(Vector3(130 + aside, 0, 2), Vector3(130 + aside, 0, -70)))
	return await _ride.until_judged(self, 40.0)


## The 45° bend's line: on to a right half circle of `radius` and back.
static func _half_circle(radius: float) -> Path3D:
	var k := QUARTER * radius
	var path := Path3D.new()
	path.curve = Curve3D.new()
	path.curve.add_point(Vector3(160, 0, 2))
	path.curve.add_point(Vector3(160, 0, -60), Vector3.ZERO, Vector3(0, 0, -k))
	path.curve.add_point(
		Vector3(160 + radius, 0, -60 - radius), Vector3(-k, 0, 0), Vector3(k, 0, 0)
	)
	path.curve.add_point(Vector3(160 + 2 * radius, 0, -60), Vector3(0, 0, -k))
	path.curve.add_point(Vector3(160 + 2 * radius, 0, 10))
	return path


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
