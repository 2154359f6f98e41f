extends TestCase
## The learned controller rides the track as a player does: the trigger at 60 % towards
## the 40 km/h setting down the start straight, over the kicker, the hill and the rollers,
## then the far bend with the stick 0.4 left, which asks for the bike's lean limit
## (`max_lean_deg`), held for 6 s.
## The network is the game's bike's own, from `make train BIKE=…/street_390.tres`
## (models/policy-street_390.safetensors): a model that cannot ride the game's own lap
## fails here.

const GAME := preload("res://scenes/game/game.tscn")
const TRACK := "res://scenes/levels/track/track.tscn"
## Where the far bend starts: past the last roller (z = -81), short of the gate (-110).
const BEND_Z := -95.0

var _game: Game


func before_each() -> void:
	SettingsSandbox.enter()
	Settings.set_value(&"controller", "learned")
	_game = GAME.instantiate()
	_game.level_path = TRACK
	add_child(_game)
	await wait_physics_frames(2)


func after_each() -> void:
	for action: StringName in [&"throttle", &"steer_left"]:
		Input.action_release(action)
	_game.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_learned_rides_the_straight_and_holds_the_far_bend_at_the_limit() -> void:
	var bike := _game.bike
	assert_eq(bike.get_controller_name(), "learned")
	assert_eq(bike.get_controller_failure(), "", "the model loaded")
	Input.action_press(&"throttle", 0.6)
	var frames := 0
	while bike.get_center_of_mass().z > BEND_Z and frames < 900:
		await wait_physics_frames(1)
		frames += 1
	assert_false(bike.is_crashed(), "over the kicker, the hill and the rollers")
	assert_gt(bike.get_speed() * 3.6, 35.0, "at speed into the bend")
	Input.action_press(&"steer_left", 0.4)
	await wait_physics_frames(120)
	var worst := 0.0
	for frame in 360:
		await wait_physics_frames(1)
		worst = maxf(worst, absf(bike.get_lean() - bike.get_desired_lean()))
	assert_false(bike.is_crashed(), "round the far bend")
	assert_almost_eq(bike.get_desired_lean(), -bike.get_max_lean(), 0.01, "the limit asked")
	assert_lt(rad_to_deg(worst), 3.0, "lean within 3° of the limit for 6 s")
