extends TestCase
## The game on an automatic level (the thesis's test level), as a player watches it: an
## attempt that reaches the goal ends with the bike braked to a stop past the goal,
## standing, not ridden on over the level's end while the result shows; the next attempt
## rides the thesis's course again.

const GAME := preload("res://scenes/game/game.tscn")
const TEST_LEVEL := "res://scenes/levels/test_level/test_level.tscn"
## The level's floor's top, 1.5 m above the ground below it.
const FLOOR_TOP := 0.0
## Faster than the thesis's speeds: braking at 0.9 g from 30 km/h takes 4 m, the floor
## an attempt rides ends 4 m past where the goal begins.
const AUTO_SPEED_KMH := 30

var _game: Game


func before_each() -> void:
	SettingsSandbox.enter()
	Settings.set_value(&"controller", "arcade")
	Settings.set_value(&"auto_speed_kmh", AUTO_SPEED_KMH)
	_game = GAME.instantiate()
	_game.level_path = TEST_LEVEL
	add_child(_game)
	await wait_physics_frames(2)


func after_each() -> void:
	_game.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_at_the_goal_the_bike_brakes_to_a_stop_and_waits_for_the_next_attempt() -> void:
	var rate := Engine.physics_ticks_per_second
	var ticks := 0
	while _game.attempts == 0 and ticks < 40 * rate:
		await wait_physics_frames(1)
		ticks += 1
	assert_eq(_game.successes, 1, "reached the goal in %.1f s" % (ticks / float(rate)))
	var driver: BikeDriver = _game.get_node("Driver")
	assert_true(driver.stopping, "the rider brakes once the attempt is over")
	var run_off: CollisionShape3D = _game.level.get_node("RunOff/Shape")
	assert_false(run_off.disabled, "the floor goes on past the goal")
	# Just before the result's pause ends and the next attempt starts.
	await wait_physics_frames(int((Game.RESULT_PAUSE - 0.2) * rate))
	assert_eq(_game.attempts, 1, "still the result's pause")
	var bike := _game.bike
	assert_false(bike.is_crashed(), "standing")
	assert_lt(bike.get_speed(), 0.3, "stopped, m/s")
	assert_gt(bike.get_center_of_mass().y, FLOOR_TOP + 0.3, "on the level's floor, not below it")
	await wait_physics_frames(int(0.5 * rate))
	assert_eq(_game.attempts, 1, "the next attempt is under way")
	assert_false(driver.stopping, "riding again")
	assert_true(run_off.disabled, "the attempt rides the thesis's course, its floor ending")
	assert_gt(bike.get_center_of_mass().z, -2.0, "back at the start (the goal is 36 m on)")
