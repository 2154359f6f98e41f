class_name ChallengeBot
extends RefCounted
## Test helper: the bot's ride of every lesson and challenge, through a gamepad's events
## (LessonRide), at the pace that earns gold on the street 390 unless told otherwise. The
## suites ride them to their medals and past their goals; the survey
## (tests/survey/challenge_survey.gd) rides the gold ones on every bike.

const LESSONS := "res://scenes/challenges/lessons/"
const LEVELS := "res://scenes/challenges/levels/"
## Cubic Bézier handles of a quarter circle, per metre of radius.
const QUARTER := 0.5523
## The counter-steering S's radius, the 45° bend's, and where the wheelie lesson's log lies.
const S_RADIUS := 15.0
const BEND_RADIUS := 30.0
const LOG_Z := -30.0

## The ride under way (null before the first).
var ride: LessonRide

var _test: TestCase
var _bike := ""
var _controller := "combined"


## Rides under `test` on bike `bike` (a `Bikes` key; the settings' default when empty) with
## `controller`.
func _init(test: TestCase, bike := "", controller := "combined") -> void:
	_test = test
	_bike = bike
	_controller = controller


## The gold ride of the lesson or challenge with file name `key` (null, with an error, for
## one the bot cannot ride).
func gold_ride(key: String) -> ChallengeResult:
	var rides := {
		"ride_off": ride_off,
		"counter_steer": counter_steer,
		"slalom": slalom,
		"full_brake": full_brake,
		"wheelie_log": wheelie_log,
		"hill_start": hill_start,
		"kicker": kicker,
		"bend_45": bend_45,
		"track_time_trial": track_time_trial,
		"park_gates": park_gates,
		"park_wheelie": park_wheelie,
		"park_air": park_air,
		"thesis_run": thesis_run,
	}
	if not rides.has(key):
		push_error("ChallengeBot: no ride for %s" % key)
		return null
	return await (rides[key] as Callable).call()


## Ride off at 20 km/h, braking `brake_at` m along the lane (INF: never, at 32 km/h).
func ride_off(brake_at := 62.0) -> ChallengeResult:
	var kmh := 20.0 if is_finite(brake_at) else 32.0
	await _start(LESSONS + "ride_off.tres", kmh)
	_follow(BotStart.straight(Vector3(0, 0, 2), Vector3(0, 0, -90)))
	ride.bot.speed_along = func(offset: float) -> float: return kmh if offset < brake_at else 0.0
	return await ride.until_judged(_test, 40.0)


## The S at `kmh`.
func counter_steer(kmh := 35.0) -> ChallengeResult:
	await _start(LESSONS + "counter_steer.tres", kmh)
	_follow(s_bend())
	return await ride.until_judged(_test, 60.0)


## The slalom at `kmh`, swinging `swing` m either side of the lane (0: past every gate).
func slalom(kmh := 25.0, swing := 1.6) -> ChallengeResult:
	await _start(LESSONS + "slalom.tres", kmh)
	_follow(slalom_line(swing))
	return await ride.until_judged(_test, 60.0)


## A full brake from `kmh`, braking `brake_at` m along the lane.
func full_brake(kmh := 60.0, brake_at := 145.0) -> ChallengeResult:
	await _start(LESSONS + "full_brake.tres", kmh)
	_follow(BotStart.straight(Vector3(-40, 0, 2), Vector3(-40, 0, -230)))
	ride.bot.speed_along = func(offset: float) -> float: return kmh if offset < brake_at else 0.0
	return await ride.until_judged(_test, 60.0)


## The log at 10 km/h, the weight back from the front wheel at z `lift` (−INF: never)
## until it is past the log.
func wheelie_log(lift := -22.0) -> ChallengeResult:
	await _start(LESSONS + "wheelie_log.tres", 10.0)
	_follow(BotStart.straight(Vector3(-80, 0, 2), Vector3(-80, 0, -60)))
	for _i in 40 * Engine.physics_ticks_per_second:
		await _test.wait_physics_frames(1)
		var front := ride.game.bike.get_body_transform(BikeSimulation.FRONT_WHEEL).origin
		ride.bot.wheelie = front.z < lift and front.z > LOG_Z - 1.0
		if ride.game.challenge_run.result != null:
			break
	ride.bot.wheelie = false
	return await ride.until_judged(_test, 0.0)


## Up the hill at 10 km/h, braking `stop_at` m along the lane, 5 s standing, then on.
func hill_start(stop_at := 25.0) -> ChallengeResult:
	await _start(LESSONS + "hill_start.tres", 10.0)
	_follow(BotStart.straight(Vector3(-110, 0, 2), Vector3(-110, 0, -60)))
	var stood := 5.0 * Engine.physics_ticks_per_second
	var braked_at := [-1]
	ride.bot.speed_along = func(offset: float) -> float:
		if braked_at[0] < 0 and offset > stop_at:
			braked_at[0] = Engine.get_physics_frames()
		var standing: bool = (
			braked_at[0] >= 0 and Engine.get_physics_frames() - braked_at[0] < stood
		)
		return 0.0 if standing else 10.0
	return await ride.until_judged(_test, 60.0)


## The kicker at `kmh`, the weight bringing the bike to `pitch` degrees in the air, the
## line `aside` m right of the kicker's middle.
func kicker(kmh := 35.0, pitch := 0.0, aside := 0.0) -> ChallengeResult:
	await _start(LESSONS + "kicker.tres", kmh)
	ride.bot.level_in_air = true
	ride.bot.air_pitch = pitch
	_follow(BotStart.straight(Vector3(130 + aside, 0, 2), Vector3(130 + aside, 0, -70)))
	return await ride.until_judged(_test, 40.0)


## The 45° bend at `kmh` on its half circle, or `straight` on past it.
func bend_45(kmh := 60.0, straight := false) -> ChallengeResult:
	await _start(LESSONS + "bend_45.tres", kmh)
	if straight:
		_follow(BotStart.straight(Vector3(160, 0, 2), Vector3(160, 0, -200)))
	else:
		_follow(half_circle(BEND_RADIUS))
	return await ride.until_judged(_test, 40.0)


## A lap of the track on its own line at `kmh`.
func track_time_trial(kmh := 30.0) -> ChallengeResult:
	await _start(LEVELS + "track_time_trial.tres", kmh)
	ride.bot.path = ride.game.level.get_node("Lap")
	return await ride.until_judged(_test, 120.0)


## The skate park's gates at `kmh`.
func park_gates(kmh := 20.0) -> ChallengeResult:
	await _start(LEVELS + "park_gates.tres", kmh)
	_follow(round_the_kicker())
	return await ride.until_judged(_test, 60.0)


## The skate park's wheelie lane at `kmh`, the weight back from a second in.
func park_wheelie(kmh := 8.0) -> ChallengeResult:
	await _start(LEVELS + "park_wheelie.tres", kmh)
	_follow(BotStart.straight(Vector3(-5, 0, 28), Vector3(-5, 0, -25)))
	await _test.wait_physics_frames(Engine.physics_ticks_per_second)
	ride.bot.wheelie = true
	return await ride.until_judged(_test, 40.0)


## Off the skate park's funbox at `kmh`, levelled in the air.
func park_air(kmh := 35.0) -> ChallengeResult:
	await _start(LEVELS + "park_air.tres", kmh)
	ride.bot.level_in_air = true
	_follow(BotStart.straight(Vector3(12, 0, 16), Vector3(12, 0, -25)))
	return await ride.until_judged(_test, 40.0)


## Straight through the test level's logs at `kmh`.
func thesis_run(kmh := 30.0) -> ChallengeResult:
	await _start(LEVELS + "thesis_run.tres", kmh)
	_follow(BotStart.straight(Vector3(0, 0, 2), Vector3(0, 0, -60)))
	return await ride.until_judged(_test, 30.0)


## Asserts under `test` that `result`, the last ride of `bot`, passed with `medal`, and
## prints its score (the suites' logs keep what the bot scored).
static func assert_medal(
	test: TestCase, bot: ChallengeBot, result: ChallengeResult, medal: Challenge.Medal
) -> void:
	test.assert_not_null(result, "judged in time")
	if result == null:
		return
	var challenge := bot.ride.game.challenge_run.challenge
	test.assert_true(result.passed, "passed (%s)" % result.why)
	var scored := "%s: %s" % [challenge.title, challenge.format(result.score)]
	test.assert_eq(challenge.medal_for(result.score), medal, scored)
	print("bot on %s, %s" % [scored, "; ".join(result.facts)])


## Asserts under `test` that `result` failed saying `why`, and that the player read it.
static func assert_failed(
	test: TestCase, bot: ChallengeBot, result: ChallengeResult, why: String
) -> void:
	test.assert_not_null(result, "judged in time")
	if result == null:
		return
	test.assert_false(result.passed, "failed")
	test.assert_has(result.why, why)
	var shown := bot.ride.game.challenge_card.result_text()
	test.assert_true(shown.begins_with("Not yet\n"), shown)
	test.assert_has(shown, result.why.substr(1))


## Frees the ride under way.
func free_all() -> void:
	if ride != null:
		ride.free_all()
		ride = null


## The counter-steering lesson's S: a right quarter circle, then a left one.
static func s_bend() -> Path3D:
	var k := QUARTER * S_RADIUS
	var path := _path([Vector3(30, 0, 2)])
	path.curve.add_point(Vector3(30, 0, -30), Vector3.ZERO, Vector3(0, 0, -k))
	path.curve.add_point(Vector3(45, 0, -45), Vector3(-k, 0, 0), Vector3(k, 0, 0))
	path.curve.add_point(Vector3(60, 0, -60), Vector3(0, 0, k))
	path.curve.add_point(Vector3(60, 0, -95))
	return path


## A line through the slalom's gates, `swing` m either side of the lane's middle.
static func slalom_line(swing: float) -> Path3D:
	var path := _path([Vector3(100, 0, 2)])
	path.curve.add_point(Vector3(100, 0, -12), Vector3.ZERO, Vector3(0, 0, -4))
	for i in 6:
		var x := 100.0 + (swing if i % 2 == 0 else -swing)
		path.curve.add_point(Vector3(x, 0, -24 - 12 * i), Vector3(0, 0, 5), Vector3(0, 0, -5))
	path.curve.add_point(Vector3(100, 0, -96), Vector3(0, 0, 4), Vector3(0, 0, -4))
	path.curve.add_point(Vector3(100, 0, -115))
	return path


## The 45° bend's line: on to a right half circle of `radius` and back.
static func half_circle(radius: float) -> Path3D:
	var k := QUARTER * radius
	var path := _path([Vector3(160, 0, 2)])
	path.curve.add_point(Vector3(160, 0, -60), Vector3.ZERO, Vector3(0, 0, -k))
	path.curve.add_point(
		Vector3(160 + radius, 0, -60 - radius), Vector3(-k, 0, 0), Vector3(k, 0, 0)
	)
	path.curve.add_point(Vector3(160 + 2 * radius, 0, -60), Vector3(0, 0, -k))
	path.curve.add_point(Vector3(160 + 2 * radius, 0, 10))
	return path


## Left of the skate park's kicker, round behind it on a 5 m circle and back up its right.
static func round_the_kicker() -> Path3D:
	var k := QUARTER * 5.0
	var path := _path([Vector3(0, 0, 14)])
	path.curve.add_point(Vector3(0, 0, 4), Vector3.ZERO, Vector3(0, 0, -3))
	path.curve.add_point(Vector3(-5, 0, -4), Vector3(0, 0, 3), Vector3(0, 0, -2))
	path.curve.add_point(Vector3(-5, 0, -8), Vector3.ZERO, Vector3(0, 0, -k))
	path.curve.add_point(Vector3(0, 0, -13), Vector3(-k, 0, 0), Vector3(k, 0, 0))
	path.curve.add_point(Vector3(5, 0, -8), Vector3(0, 0, -k))
	path.curve.add_point(Vector3(5, 0, 6))
	return path


## A Path3D through `points` (more may be added).
static func _path(points: Array[Vector3]) -> Path3D:
	var path := Path3D.new()
	path.curve = Curve3D.new()
	for point in points:
		path.curve.add_point(point)
	return path


func _start(path: String, kmh: float) -> void:
	free_all()
	ride = await LessonRide.start(_test, path, _controller, _bike, kmh)


func _follow(path: Path3D) -> void:
	ride.follow(_test, path)
