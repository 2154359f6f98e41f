extends TestCase
## The sandbox drives through the input actions, as a player would.

const SANDBOX := preload("res://scenes/sandbox.tscn")

var _sandbox: Node3D
var _bike: BikeSimulation


func before_each() -> void:
	_sandbox = SANDBOX.instantiate()
	add_child(_sandbox)
	_bike = _sandbox.get_node("Bike")
	await wait_physics_frames(2)


func after_each() -> void:
	for action: StringName in [&"throttle", &"brake", &"steer_left", &"steer_right"]:
		Input.action_release(action)
	_sandbox.queue_free()


func test_the_bike_and_its_bodies_are_shown() -> void:
	assert_true(_bike.is_running())
	var view := _sandbox.get_node("Bike/PhysicalBikeView")
	assert_eq(view.get_child_count(), _bike.get_shapes().size())


func test_the_bike_waits_upright_for_the_first_throttle() -> void:
	await wait_physics_frames(180)
	assert_true(_bike.is_waiting_for_throttle())
	assert_almost_eq(_bike.get_lean(), 0.0, 1e-6, "standing as placed")


func test_the_stick_turns_the_bike_through_its_lean() -> void:
	Input.action_press(&"throttle")
	# Past the bumps (z = −12, −17), onto the open ground before the ramp (z = −45).
	await wait_physics_frames(200)
	var heading_before := _frame_heading()
	Input.action_press(&"steer_left", 0.6)
	await wait_physics_frames(120)
	assert_lt(_bike.get_lean(), deg_to_rad(-5.0), "leans into a left turn")
	Input.action_release(&"steer_left")
	await wait_physics_frames(90)
	assert_false(_bike.is_crashed())
	var turned := heading_before.signed_angle_to(_frame_heading(), Vector3.UP)
	assert_gt(turned, deg_to_rad(20.0), "turned left (anticlockwise seen from above)")


func test_the_throttle_action_drives_and_the_brake_stops() -> void:
	Input.action_press(&"throttle")
	await wait_physics_frames(60)
	Input.action_release(&"throttle")
	var speed := _bike.get_speed()
	assert_gt(speed, 2.0, "speed after 1 s of throttle")
	Input.action_press(&"brake")
	await wait_physics_frames(60)
	# Only the rear wheel brakes (as in the thesis): about 0.3 g, so 1 s takes off ~45 %.
	assert_lt(_bike.get_speed(), speed * 0.7, "braking slows the bike")


func test_the_controller_action_cycles_optimizer_combined_arcade() -> void:
	Input.action_press(&"throttle")
	var seen: Array[String] = []
	for i: int in 3:
		var event := InputEventAction.new()
		event.action = &"cycle_controller"
		event.pressed = true
		Input.parse_input_event(event)
		await wait_physics_frames(45)
		seen.append(_bike.get_controller_name())
		if seen[-1] != "arcade":
			assert_gt(_bike.get_planning_ms(), 0.0, "%s plans" % seen[-1])
			var paths := _bike.get_trajectory_paths()
			assert_eq(paths.size(), _bike.trajectories, "one path per trajectory")
			assert_between(_bike.get_best_trajectory(), 0, paths.size() - 1)
			await get_tree().process_frame
			var view: TrajectoryView = _sandbox.get_node("Bike/TrajectoryView")
			assert_eq(view.drawn_count(), paths.size(), "every trajectory is drawn")
	assert_eq(seen, ["optimizer", "combined", "arcade"] as Array[String])
	await get_tree().process_frame
	var view: TrajectoryView = _sandbox.get_node("Bike/TrajectoryView")
	assert_eq(view.drawn_count(), 0, "no trajectories while the arcade controller drives")
	assert_false(_bike.is_crashed(), "switching controllers while riding keeps the bike up")


func _frame_heading() -> Vector3:
	var forward := _bike.get_body_transform(3).basis.x
	return Vector3(forward.x, 0.0, forward.z).normalized()


func test_the_reset_action_returns_to_the_start() -> void:
	Input.action_press(&"throttle")
	await wait_physics_frames(45)
	Input.action_release(&"throttle")
	var event := InputEventAction.new()
	event.action = &"reset_bike"
	event.pressed = true
	Input.parse_input_event(event)
	await wait_physics_frames(2)
	assert_almost_eq(_bike.get_center_of_mass().z, 0.0, 0.1)
	assert_almost_eq(_bike.get_speed(), 0.0, 0.05)
