extends TestCase
## A stop and a pull-away across the skate park's camber (a BankPiece falling 8° to one
## side), ridden by the bot through the player's own input: the bike stops on the bank,
## stands on the foot a rider puts down, near upright, and rides off it (issue 68). Before
## legs that reach the road, the bike stood about 9° downhill on its downhill foot and
## fell pulling away.

const SKATE_PARK := "res://scenes/levels/skate_park/skate_park.tscn"
## The camber's centre line runs along x at z = 24; fully banked from x = -4 to 4.
const LINE_Z := 24.0
const BRAKE_X := 1.5

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


func test_the_games_controller_stops_on_the_camber_falling_left_and_rides_off() -> void:
	await _stop_and_ride_off("combined", -1.0)


func test_arcade_stops_on_the_camber_falling_right_and_rides_off() -> void:
	await _stop_and_ride_off("arcade", 1.0)


## Along the camber at 10 km/h (`direction` -1: towards −x, from its "camber" spawn point,
## the road falling to the left; 1: back the other way, falling to the right), the brake
## in the middle of the bank, 3 s standing, and off again at 10 km/h.
func _stop_and_ride_off(controller: String, direction: float) -> void:
	# The skate park has no lap: the bot idles until it is given the camber's line.
	var started: Array = await BotStart.start(self, SKATE_PARK, controller)
	_game = started[0]
	_bot = started[1]
	var camber := _game.level.get_node(^"Camber") as BankPiece
	assert_not_null(camber, "the skate park has its camber")
	_game.bike.reset_to(_spawn(direction))
	await wait_physics_frames(2)
	var path := BotStart.straight(
		Vector3(-24.0 * direction, 0, LINE_Z), Vector3(24.0 * direction, 0, LINE_Z)
	)
	add_child(path)
	_bot.path = path
	_bot.speed_kmh = 10.0
	while _game.bike.get_center_of_mass().x * direction < -BRAKE_X:
		await wait_physics_frames(1)
		if _game.bike.is_crashed() or _game.level.elapsed > 20.0:
			break
	assert_false(_game.bike.is_crashed(), "rode onto the camber")
	_bot.speed_kmh = 0.0
	var feet := _game.bike.get_node(^"VisualBikeView") as VisualBikeView
	var on_a_foot := 0
	var downhill_lean := 0.0
	for frame in 5 * 60:
		await wait_physics_frames(1)
		assert_false(_game.bike.is_crashed(), "fell stopping, %.1f s in" % (frame / 60.0))
		if _game.bike.is_crashed():
			return
		if frame >= 2 * 60:
			for foot: BikeFoot in _game.bike.get_feet():
				on_a_foot += int(foot.on_ground)
	var stopped := _game.bike.get_center_of_mass()
	# Lean is positive to the right; the road falls to the right riding towards +x.
	downhill_lean = _game.bike.get_lean() * direction
	assert_lt(absf(_game.bike.get_speed()), 0.1, "standing still")
	assert_between(stopped.x, -4.0, 4.0, "stopped where the road is fully banked")
	assert_gt(on_a_foot, 0, "stood on a foot")
	assert_true(feet.is_leg_down(-1.0) or feet.is_leg_down(1.0), "a leg drawn down")
	assert_lt(rad_to_deg(absf(downhill_lean)), 5.0, "stood within 5° of upright")
	_bot.speed_kmh = 10.0
	var widest := 0.0
	for frame in 4 * 60:
		await wait_physics_frames(1)
		assert_false(_game.bike.is_crashed(), "fell pulling away, %.1f s in" % (frame / 60.0))
		if _game.bike.is_crashed():
			return
		widest = maxf(widest, absf(_game.bike.get_lean()))
	assert_gt(_game.bike.get_speed() * 3.6, 8.0, "back near 10 km/h within 4 s")
	print(
		(
			(
				"bot stop across the 8° camber (%s, falling %s): stood %.1f degrees downhill"
				+ " at x = %.1f, leaned at most %.1f riding off"
			)
			% [
				controller,
				"right" if direction > 0.0 else "left",
				rad_to_deg(downhill_lean),
				stopped.x,
				rad_to_deg(widest),
			]
		)
	)


## Where the bot starts: before the camber's end on its centre line, facing along it.
func _spawn(direction: float) -> Transform3D:
	var forward := Vector3(direction, 0.0, 0.0)
	var at := Vector3(-20.0 * direction, 0.02, LINE_Z)
	return Transform3D(Basis.looking_at(forward, Vector3.UP), at)
