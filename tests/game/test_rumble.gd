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
