extends TestCase
## The pad rumbles for landings, by how fast the bike came down, and for crashes, and not
## at all with the rumble setting off.

const PAD := 3

var _rumble: Rumble


func before_each() -> void:
	_rumble = Rumble.new()
	_rumble.device = PAD
	add_child(_rumble)


func after_each() -> void:
	Input.stop_joy_vibration(PAD)
	_rumble.free()


func test_a_harder_landing_shakes_harder_and_a_crash_shakes_hardest() -> void:
	_rumble.landed(1.0)
	var soft := Input.get_joy_vibration_strength(PAD)
	_rumble.landed(3.0)
	var hard := Input.get_joy_vibration_strength(PAD)
	assert_gt(hard.y, soft.y, "a 3 m/s fall against 1 m/s")
	_rumble.crashed()
	assert_eq(Input.get_joy_vibration_strength(PAD), Vector2(1.0, 1.0))


func test_with_the_setting_off_nothing_shakes() -> void:
	_rumble.rumble = false
	_rumble.landed(4.0)
	_rumble.crashed()
	assert_eq(Input.get_joy_vibration_strength(PAD), Vector2.ZERO)


func test_the_setting_reaches_the_games_rumble() -> void:
	SettingsSandbox.enter()
	var game: Game = load("res://scenes/game/game.tscn").instantiate()
	game.level_path = "res://scenes/levels/test_level/test_level.tscn"
	add_child(game)
	var rumble := game.get_node(^"Rumble") as Rumble
	assert_true(rumble.rumble, "on by default")
	Settings.set_value(&"rumble", false)
	assert_false(rumble.rumble, "off from the menu")
	game.free()
	SettingsSandbox.leave()


func test_the_abs_at_work_is_a_slipping_grounded_tyre_in_a_hard_stop() -> void:
	var slipping: Array[Vector4] = [Vector4(0, 0, 0, 1.5), Vector4(0, 0, 0, 0.0)]
	var rolling: Array[Vector4] = [Vector4(0, 0, 0, 0.1), Vector4(0, 0, 0, 0.0)]
	var down: Array[bool] = [true, true]
	assert_true(Rumble.abs_working(slipping, down, 15.0, 8.0), "a hard stop, the rear at 10 %")
	assert_false(Rumble.abs_working(rolling, down, 15.0, 8.0), "both tyres rolling")
	assert_false(Rumble.abs_working(slipping, down, 15.0, 0.5), "not slowing: a spinning wheel")
	assert_false(Rumble.abs_working(slipping, down, 1.0, 8.0), "at walking pace")
	assert_false(Rumble.abs_working(slipping, [false, true], 15.0, 8.0), "the rear in the air")
	assert_false(Rumble.abs_working(slipping, down, NAN, 8.0), "a speed that is not a number")


func test_the_engine_buzzes_more_towards_its_limiter() -> void:
	assert_eq(Rumble.engine_buzz(0.5), 0.0, "cruising")
	assert_between(Rumble.engine_buzz(0.9), 0.01, Rumble.ENGINE_BUZZ - 0.01, "near")
	assert_almost_eq(Rumble.engine_buzz(1.0), Rumble.ENGINE_BUZZ, 1e-6, "at the limiter")
	assert_eq(Rumble.engine_buzz(NAN), 0.0)


func test_the_abs_pulses_the_light_motor_but_never_over_a_crash() -> void:
	_rumble.riding(true, 0.0)
	assert_eq(Input.get_joy_vibration_strength(PAD), Vector2(Rumble.ABS_PULSE, 0.0), "ABS")
	_rumble.crashed()
	_rumble.riding(true, 0.0)
	assert_eq(Input.get_joy_vibration_strength(PAD), Vector2(1.0, 1.0), "the crash's shake")
