extends TestCase
## The game driven through its input actions, as a player would: throttle, the rider's
## weight on the right stick, respawn, lift, spawn points, controller cycling,
## auto-accelerate, pause, and the pause menu with a gamepad alone.

const GAME := preload("res://scenes/game/game.tscn")
const TRACK := "res://scenes/levels/track/track.tscn"

var _game: Game


func before_each() -> void:
	SettingsSandbox.enter()
	Settings.set_value(&"controller", "arcade")
	_game = GAME.instantiate()
	_game.level_path = TRACK
	add_child(_game)
	# Before the first step: the planners' rides (controller cycling) wait for every plan,
	# so they ride the same however busy the machine is.
	_game.bike.wait_for_every_plan = true
	await wait_physics_frames(2)


func after_each() -> void:
	for action: StringName in [&"throttle", &"brake", &"steer_left", &"steer_right", &"rider_back"]:
		Input.action_release(action)
	for axis: JoyAxis in [JOY_AXIS_RIGHT_X, JOY_AXIS_RIGHT_Y]:
		SimulatedInput.move_joypad_axis(axis, 0.0)
	get_tree().paused = false
	_game.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_every_game_and_display_setting_reaches_its_target_by_name() -> void:
	# The level is chosen before the game is built (the start menu, then _ready).
	var read_when_built: Array[StringName] = [&"level"]
	# Followed for every scene, the menus' too, by an autoload (tested with it).
	var followed_by_an_autoload: Array[StringName] = [&"graphics_quality", &"ui_scale", &"assist"]
	for key: StringName in Settings.entries:
		var owner: String = Settings.entries[key].owner
		if owner not in ["game", "display"] or key in read_when_built + followed_by_an_autoload:
			continue
		var targets := _game.setting_targets().filter(func(t: Object) -> bool: return key in t)
		assert_false(targets.is_empty(), "%s reaches nothing" % key)
	Settings.set_value(&"physical_model", true)
	assert_true(_game.bike.get_node(^"PhysicalBikeView").visible, "the physical view shows")
	assert_false(_game.bike.get_node(^"VisualBikeView").visible, "instead of the visual one")
	Settings.set_value(&"show_trajectories", false)
	assert_false(_game.bike.get_node(^"TrajectoryView").visible)
	Settings.set_value(&"camera", "helmet")
	assert_eq((_game.get_node(^"Camera") as FollowCamera).mode, "helmet")
	Settings.set_value(&"max_speed_kmh", 55.0)
	assert_eq((_game.get_node(^"Driver") as BikeDriver).max_speed_kmh, 55.0)


func test_throttle_drives_the_bike_forward() -> void:
	var start := _game.bike.get_center_of_mass()
	Input.action_press(&"throttle")
	await wait_physics_frames(90)
	var forward := -_game.level.spawn_points()[0].global_basis.z
	assert_gt(_game.bike.get_speed(), 2.0, "speed after 1.5 s")
	assert_gt((_game.bike.get_center_of_mass() - start).dot(forward), 1.5, "moved forward")


func test_the_stick_turns_the_bike_through_its_lean() -> void:
	Input.action_press(&"throttle", 0.5)
	await wait_physics_frames(150)
	var heading_before := _frame_heading()
	Input.action_press(&"steer_left", 0.6)
	await wait_physics_frames(90)
	assert_lt(_game.bike.get_lean(), deg_to_rad(-5.0), "leans into a left turn")
	Input.action_release(&"steer_left")
	await wait_physics_frames(60)
	assert_false(_game.bike.is_crashed())
	var turned := heading_before.signed_angle_to(_frame_heading(), Vector3.UP)
	assert_gt(turned, deg_to_rad(20.0), "turned left (anticlockwise seen from above)")


func test_the_right_stick_moves_the_riders_weight_and_the_hud_shows_it() -> void:
	# At a steady speed: accelerating throws the rider back by itself.
	await SimulatedInput.tap_action(&"toggle_auto_accelerate")
	await wait_physics_frames(180)
	var pad: RiderPad = _game.find_child("RiderPad", true, false)
	# Pushed up: forward, over the tank.
	SimulatedInput.move_joypad_axis(JOY_AXIS_RIGHT_Y, -1.0)
	await wait_physics_frames(60)
	assert_almost_eq(_game.bike.get_rider_position_asked(), Vector2(0, 1), Vector2(0.01, 0.01))
	assert_gt(_game.bike.get_rider_position().y, 0.7, "the weight went forward")
	await wait_frames(1)
	assert_almost_eq(pad.asked, Vector2(0, 1), Vector2(0.01, 0.01), "the HUD shows what is asked")
	assert_almost_eq(
		pad.actual, _game.bike.get_rider_position(), Vector2(0.1, 0.1), "and where it is"
	)
	# Pushed right.
	SimulatedInput.move_joypad_axis(JOY_AXIS_RIGHT_Y, 0.0)
	SimulatedInput.move_joypad_axis(JOY_AXIS_RIGHT_X, 1.0)
	await wait_physics_frames(60)
	assert_gt(_game.bike.get_rider_position().x, 0.7, "the weight went right")
	assert_lt(absf(_game.bike.get_rider_position().y), 0.3)
	# Released: back to the riding pose.
	SimulatedInput.move_joypad_axis(JOY_AXIS_RIGHT_X, 0.0)
	await wait_physics_frames(60)
	assert_eq(_game.bike.get_rider_position_asked(), Vector2.ZERO)
	assert_lt(_game.bike.get_rider_position().length(), 0.15, "back in the riding pose")
	# The keyboard's K: back, over the rear wheel.
	Input.action_press(&"rider_back")
	await wait_physics_frames(60)
	assert_lt(_game.bike.get_rider_position().y, -0.7, "the weight went back")
	assert_false(_game.bike.is_crashed())


func test_the_right_stick_is_the_riders_and_the_d_pad_the_cameras() -> void:
	var bound := func(action: StringName, type: String) -> Array:
		return InputMap.action_get_events(action).filter(
			func(e: InputEvent) -> bool: return e.is_class(type)
		)
	for action: StringName in [&"rider_forward", &"rider_back", &"rider_left", &"rider_right"]:
		var axes: Array = bound.call(action, "InputEventJoypadMotion")
		assert_eq(axes.size(), 1, "%s on a stick" % action)
		assert_true(
			axes[0].axis in [JOY_AXIS_RIGHT_X, JOY_AXIS_RIGHT_Y], "%s on the right stick" % action
		)
		assert_eq(bound.call(action, "InputEventKey").size(), 1, "%s on a key" % action)
	for action: StringName in [&"camera_left", &"camera_right", &"camera_up", &"camera_down"]:
		assert_eq(
			bound.call(action, "InputEventJoypadMotion").size(), 0, "%s off the sticks" % action
		)
		var buttons: Array = bound.call(action, "InputEventJoypadButton")
		assert_eq(buttons.size(), 1, "%s on the d-pad" % action)
		assert_true(
			(
				buttons[0].button_index >= JOY_BUTTON_DPAD_UP
				and buttons[0].button_index <= JOY_BUTTON_DPAD_RIGHT
			)
		)
		assert_eq(bound.call(action, "InputEventKey").size(), 1, "%s on a key" % action)


func test_reset_puts_the_bike_back_at_the_spawn_point() -> void:
	var start := _game.bike.get_center_of_mass()
	Input.action_press(&"throttle")
	await wait_physics_frames(60)
	Input.action_release(&"throttle")
	await SimulatedInput.tap_action(&"reset_bike")
	assert_almost_eq(_game.bike.get_center_of_mass(), start, Vector3(0.05, 0.05, 0.05))
	assert_almost_eq(_game.bike.get_speed(), 0.0, 1e-6)


func test_lift_stands_a_fallen_bike_up() -> void:
	await GameFixture.ride_unbalanced_and_nudge(self, _game)
	await wait_physics_frames(230)
	assert_true(_game.bike.is_crashed(), "nobody balancing: it fell")
	Input.action_release(&"throttle")
	await SimulatedInput.tap_action(&"lift_bike")
	assert_false(_game.bike.is_crashed())
	assert_almost_eq(_game.bike.get_lean(), 0.0, deg_to_rad(2.0))


func test_spawn_buttons_cycle_through_the_spawn_points() -> void:
	var spawns := _game.level.spawn_points()
	await SimulatedInput.tap_action(&"next_spawn")
	assert_eq(_game.spawn_index(), 1)
	assert_almost_eq(
		_horizontal(_game.bike.get_center_of_mass()), _horizontal(spawns[1].global_position), 0.5
	)
	await SimulatedInput.tap_action(&"previous_spawn")
	await SimulatedInput.tap_action(&"previous_spawn")
	assert_eq(_game.spawn_index(), spawns.size() - 1, "wraps around")


func test_start_cycles_the_controllers_and_remembers_the_choice() -> void:
	Settings.choose_trajectories(Settings.offered(&"trajectories").find(5) + 1)
	assert_false(_game.bike.auto_trajectories, "a fixed count turns the automatic choice off")
	Input.action_press(&"throttle", 0.5)
	var seen: Array[String] = []
	var view: TrajectoryView = _game.bike.get_node("TrajectoryView")
	# The controllers this bike offers: the registry's, learned only with the bike's model.
	var names := _game.bike.get_offered_controller_names()
	for i in names.size():
		await SimulatedInput.tap_action(&"cycle_controller")
		await wait_physics_frames(45)
		seen.append(_game.bike.controller)
		if BikeSimulation.controller_plans(_game.bike.controller):
			var paths := _game.bike.get_trajectory_paths()
			assert_eq(paths.size(), 5, "one path per trajectory")
			await get_tree().process_frame
			assert_eq(view.drawn_count(), paths.size(), "every trajectory is drawn")
	var expected: Array[String] = []
	for i in names.size():
		expected.append(names[(names.find("arcade") + 1 + i) % names.size()])
	assert_eq(seen, expected, "the registry's order from arcade, wrapping round")
	if not _game.bike.get_policy_model_path().is_empty():
		assert_has(Array(names), "learned", "offered with the bike's own model")
	await get_tree().process_frame
	assert_eq(view.drawn_count(), 0, "no trajectories while the arcade controller drives")
	assert_false(_game.bike.is_crashed(), "switching controllers while riding keeps it up")
	var saved := ConfigFile.new()
	assert_eq(saved.load(SettingsSandbox.SETTINGS), OK)
	assert_eq(saved.get_value("game", "controller"), "arcade", "saved by name")


func test_restart_in_the_pause_menu_starts_the_attempt_again() -> void:
	Input.action_press(&"throttle")
	await wait_physics_frames(30)
	assert_gt(_game.bike.get_step_count(), 0)
	await SimulatedInput.tap_action(&"pause")
	var menu: PauseMenu = _game.get_node("PauseMenu")
	var asked := [0]
	menu.restart_requested.connect(func() -> void: asked[0] += 1)
	menu.get_node("%Restart").pressed.emit()
	assert_eq(asked[0], 1, "the menu asks, the game restarts")
	assert_false(get_tree().paused)
	assert_eq(_game.bike.get_step_count(), 0, "the bike is back at the start")


func test_auto_accelerate_holds_the_chosen_speed() -> void:
	Settings.set_value(&"auto_speed_kmh", 10)
	await SimulatedInput.tap_action(&"toggle_auto_accelerate")
	await wait_physics_frames(180)
	assert_almost_eq(_game.bike.get_speed() * 3.6, 10.0, 1.5, "km/h without the throttle")


func test_pause_stops_the_simulation_and_b_resumes() -> void:
	Input.action_press(&"throttle")
	await wait_physics_frames(30)
	await SimulatedInput.tap_action(&"pause")
	assert_true(get_tree().paused)
	var menu: PauseMenu = _game.get_node("PauseMenu")
	assert_true(menu.visible)
	var steps := _game.bike.get_step_count()
	await wait_frames(30)
	assert_eq(_game.bike.get_step_count(), steps, "no steps while paused")
	await SimulatedInput.press_joypad_button(JOY_BUTTON_B)
	assert_false(get_tree().paused)
	assert_false(menu.visible)


func test_the_pause_menu_works_with_a_gamepad_alone() -> void:
	var before: bool = Settings.get_value(&"show_trajectories")
	await SimulatedInput.press_joypad_button(JOY_BUTTON_BACK)
	assert_true(get_tree().paused, "Back pauses")
	assert_false((_game.get_node("Hud") as CanvasLayer).visible, "the HUD hides behind the menu")
	var menu: PauseMenu = _game.get_node("PauseMenu")
	assert_eq(get_viewport().gui_get_focus_owner(), menu.get_node("%Resume"))
	await SimulatedInput.press_joypad_button(JOY_BUTTON_DPAD_DOWN)
	assert_eq(get_viewport().gui_get_focus_owner(), menu.get_node("%WatchReplay"))
	# The trajectory view and the physical bodies are the Lab's, a button further down.
	menu.get_node("%OpenLab").grab_focus()
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	assert_eq(get_viewport().gui_get_focus_owner(), menu.control_of(&"show_trajectories"))
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	assert_eq(Settings.get_value(&"show_trajectories"), not before, "A toggled the trajectory view")
	assert_eq(_game.bike.get_node("TrajectoryView").visible, not before)
	await SimulatedInput.press_joypad_button(JOY_BUTTON_DPAD_DOWN)
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	assert_true(Settings.get_value(&"physical_model"))
	assert_true(_game.bike.get_node("PhysicalBikeView").visible, "physical bodies shown")
	assert_false(_game.bike.get_node("VisualBikeView").visible)
	await SimulatedInput.press_joypad_button(JOY_BUTTON_BACK)
	assert_eq(
		get_viewport().gui_get_focus_owner(), menu.get_node("%OpenLab"), "Back: the Lab closes"
	)
	await SimulatedInput.press_joypad_button(JOY_BUTTON_BACK)
	assert_false(get_tree().paused, "Back resumes")
	assert_true((_game.get_node("Hud") as CanvasLayer).visible, "and the HUD is back")


func _frame_heading() -> Vector3:
	var forward := _game.bike.get_body_transform(BikeSimulation.FRAME).basis.x
	return Vector3(forward.x, 0.0, forward.z).normalized()


func _horizontal(v: Vector3) -> Vector2:
	return Vector2(v.x, v.z)
