extends TestCase
## The game plans with a bike's learned cost-to-go when the player's switch is on
## (issue 59), as it is by default: a bike with one (the dirt 125,
## models/value-dirt_125.safetensors) plans 0.6 s ahead and the HUD says so; a bike without
## one (the pit bike, a fixture with no models) plans its whole horizon with nothing
## reported as failed, and the HUD says it has none; with the switch off every bike plans
## the whole horizon.

const GAME := preload("res://scenes/game/game.tscn")
const LEVEL := "res://scenes/levels/test_level/test_level.tscn"
const DIRT := "res://scenes/bike/bikes/dirt_125.tres"
const PIT_BIKE := "res://tests/fixtures/bikes/pit_bike.tres"

var _game: Game


func before_each() -> void:
	SettingsSandbox.enter()
	Settings.set_value(&"controller", "combined")
	# terminal_value is left at the player's default: on.


func after_each() -> void:
	if _game != null:
		_game.queue_free()
		_game = null
	await wait_frames(1)
	SettingsSandbox.leave()


func _ride(bike_path: String) -> BikeSimulation:
	# How far the plans look is the telemetry overlay's to say.
	Settings.set_value(&"telemetry", true)
	_game = GAME.instantiate()
	_game.level_path = LEVEL
	_game.bike_path = bike_path
	add_child(_game)
	await wait_physics_frames(3)
	await wait_frames(2)
	return _game.bike


func _performance() -> String:
	return (_game.get_node(^"Hud/%Performance") as Label).text


func test_a_bike_with_a_cost_to_go_plans_less_far_and_the_hud_says_so() -> void:
	var bike := await _ride(DIRT)
	assert_true(bike.has_learned_cost_to_go())
	assert_true(bike.terminal_value)
	assert_eq(bike.get_controller_failure(), "")
	assert_true(bike.is_horizon_ended_by_value())
	assert_almost_eq(bike.get_planned_horizon(), 0.6, 1e-9)
	assert_has(_performance(), "0.6 s ahead + learned cost-to-go")


func test_a_bike_without_one_plans_its_whole_horizon_and_nothing_failed() -> void:
	var bike := await _ride(PIT_BIKE)
	assert_false(bike.has_learned_cost_to_go())
	assert_false(bike.terminal_value, "not asked of a bike that has none")
	assert_eq(bike.get_controller_failure(), "", "nothing failed")
	assert_false(bike.is_horizon_ended_by_value())
	assert_almost_eq(bike.get_planned_horizon(), 1.2, 1e-9)
	assert_has(_performance(), "1.2 s ahead (no cost-to-go for this bike)")


func test_the_players_switch_off_plans_the_whole_horizon() -> void:
	var bike := await _ride(DIRT)
	Settings.set_value(&"terminal_value", false)
	await wait_physics_frames(2)
	await wait_frames(2)
	assert_false(bike.terminal_value)
	assert_false(bike.is_horizon_ended_by_value())
	assert_almost_eq(bike.get_planned_horizon(), 1.2, 1e-9)
	assert_has(_performance(), "1.2 s ahead")
	assert_false(_performance().contains("cost-to-go"), _performance())
	Settings.set_value(&"terminal_value", true)
	await wait_physics_frames(2)
	assert_true(bike.is_horizon_ended_by_value(), "and on again")
