extends TestCase
## The BikeSimulation node: signals, reset, pause, and bad input handled without a crash.

var _level: Node3D
var _bike: BikeSimulation


func before_each() -> void:
	_level = FlatLevel.create()
	add_child(_level)


func after_each() -> void:
	get_tree().paused = false
	_level.queue_free()


func test_a_drop_lands_once() -> void:
	await _spawn(Transform3D(Basis(), Vector3(0, 1.2, 0)))
	var landings: Array[int] = [0]
	_bike.landed.connect(func() -> void: landings[0] += 1)
	await wait_physics_frames(90)
	assert_eq(landings[0], 1)
	assert_true(_bike.is_rear_wheel_grounded() and _bike.is_front_wheel_grounded())


func test_a_bike_laid_on_its_side_crashes() -> void:
	# Rolled 80° about its forward axis (−z): it falls and something but a wheel hits.
	await _spawn(Transform3D(Basis(Vector3.FORWARD, deg_to_rad(80)), Vector3(0, 0.9, 0)))
	var causes: Array[String] = []
	_bike.crashed.connect(func(cause: String) -> void: causes.append(cause))
	await wait_physics_frames(90)
	assert_eq(causes.size(), 1, "crashed once: %s" % [causes])
	assert_true(_bike.is_crashed())
	assert_true(
		causes[0].ends_with("hit the ground") or causes[0].begins_with("leaned over"), causes[0]
	)
	assert_false(_bike.is_rider_on(), "the rider fell off")
	_bike.lift_upright()
	assert_false(_bike.is_crashed(), "lifting clears the crash")
	assert_true(_bike.is_rider_on(), "and puts the rider back on")


func test_throttle_drives_forward_and_reset_returns_to_the_spawn() -> void:
	var spawn := Transform3D(Basis(), Vector3(0, 0.02, 0))
	await _spawn(spawn)
	_bike.set_drive(1.0, 0.0)
	await wait_physics_frames(60)
	assert_gt(_bike.get_speed(), 2.0, "speed after 1 s of throttle")
	assert_lt(_bike.get_center_of_mass().z, -1.0, "moved along −z, the way it faces")
	_bike.reset_to(spawn)
	assert_almost_eq(_bike.get_speed(), 0.0, 1e-6)
	assert_almost_eq(
		_bike.get_body_transform(BikeSimulation.FRAME).origin, Vector3(0, 0.57, 0.05), 0.01
	)


func test_pausing_the_tree_pauses_the_simulation() -> void:
	await _spawn(Transform3D(Basis(), Vector3(0, 0.5, 0)))
	get_tree().paused = true
	var before := _bike.get_body_transform(0)
	await wait_physics_frames(20)
	assert_eq(_bike.get_body_transform(0), before)
	get_tree().paused = false
	await wait_physics_frames(20)
	assert_ne(_bike.get_body_transform(0), before)


func test_bad_input_is_rejected_or_clamped_without_a_crash() -> void:
	await _spawn(Transform3D(Basis(), Vector3(0, 0.02, 0)))
	_bike.set_drive(NAN, INF)
	_bike.set_steer_rate(-INF)
	_bike.set_rider_position(NAN, 0.5)
	assert_eq(_bike.get_rider_position_asked(), Vector2(0.5, 0), "a non-finite axis is released")
	_bike.set_rider_position(-7.0, 3.0)
	assert_eq(_bike.get_rider_position_asked(), Vector2(1, -1), "clamped to the stick's range")
	expect_error("expected 18 values, got 3")
	assert_false(_bike.set_controls(PackedFloat64Array([1, 2, 3])))
	var wild := PackedFloat64Array()
	for i: int in 18:
		wild.append([NAN, INF, -1e30, 5.0][i % 4])
	assert_true(_bike.set_controls(wild), "out-of-range values are clamped, not refused")
	assert_eq(_bike.get_body_transform(99), Transform3D.IDENTITY)
	assert_eq(_bike.get_body_name(-1), "")
	_bike.horizon = NAN
	_bike.plan_wait_ms = NAN
	_bike.trajectories = -5
	_bike.lean_tolerance_deg = INF
	await wait_physics_frames(30)
	assert_true(_bike.get_body_transform(0).origin.is_finite())


func test_a_top_speed_set_after_the_throttle_still_applies() -> void:
	await _spawn(Transform3D(Basis(), Vector3(0, 0.02, 0)))
	_bike.set_drive(1.0, 0.0)
	_bike.max_speed_kmh = 6.0
	await wait_physics_frames(300)
	assert_between(_bike.get_speed(), 1.0, 6.0 / 3.6 + 0.3, "held near 6 km/h, not the 25 before")


func test_the_baseline_planners_plan_with_their_settings_and_survive_bad_ones() -> void:
	await _spawn(Transform3D(Basis(), Vector3(0, 0.02, 0)))
	_bike.controller = "mppi"
	_bike.auto_trajectories = false
	_bike.trajectories = 6
	_bike.plan_wait_ms = 1000.0
	_bike.baseline_knots = 4
	_bike.baseline_noise = NAN
	_bike.mppi_temperature = -3.0
	_bike.set_drive(1.0, 0.0)
	await wait_physics_frames(60)
	assert_eq(_bike.get_trajectory_paths().size(), 6, "one path per candidate")
	var named := _bike.get_plan_diagnostics()
	assert_between(named.get("effective samples", 0.0), 1.0, 6.0, "MPPI's weights: %s" % named)
	assert_true(named.get("improvement", -1.0) >= 0.0, "the best is never worse than the nominal")
	_bike.controller = "sampling"
	_bike.baseline_steering_only = false
	await wait_physics_frames(30)
	assert_eq(_bike.get_controller_name(), "sampling")
	assert_eq(_bike.get_trajectory_paths().size(), 6)
	named = _bike.get_plan_diagnostics()
	assert_eq(named.keys(), ["improvement"], "predictive sampling weighs nothing")
	assert_true(_bike.get_body_transform(0).origin.is_finite(), "bad settings were clamped")


func test_the_optimizer_settings_shape_its_plans() -> void:
	await _spawn(Transform3D(Basis(), Vector3(0, 0.02, 0)))
	_bike.controller = "combined"
	_bike.auto_trajectories = false
	_bike.trajectories = 4
	_bike.horizon = 0.6
	_bike.plan_wait_ms = 1000.0
	_bike.set_drive(1.0, 0.0)
	await wait_physics_frames(60)
	var paths := _bike.get_trajectory_paths()
	assert_eq(paths.size(), 4)
	assert_eq(paths[0].size(), 18, "0.6 s at 30 planning steps a second")
	assert_eq(_bike.get_warm_trajectory(), 1, "combined: the arcade rollout")
	assert_eq(
		_bike.get_plan_diagnostics().keys(),
		["resamples", "fallen steps", "disagreement"],
		"C-PBP's own numbers"
	)
	var stats := _bike.get_handover_stats()
	assert_gt(stats.boundaries, 20)
	assert_eq(stats.late, 0, "waiting up to a second, every plan is on time")
	_bike.trajectories = 1
	await wait_physics_frames(30)
	assert_eq(_bike.get_trajectory_paths().size(), 1, "a single trajectory plans too")
	assert_false(_bike.is_crashed())


func test_late_plans_are_counted_and_none_come_when_waiting_for_every_plan() -> void:
	var start := Transform3D(Basis(), Vector3(0, 0.02, 0))
	await _spawn(start)
	_bike.set_physics_process(false)
	_bike.controller = "combined"
	_bike.trajectories = 8
	_bike.plan_wait_ms = 0.0
	_bike.set_drive(1.0, 0.0)
	_bike.advance(20)
	assert_gt(_bike.get_late_plan_count(), 10, "not waiting at all, plans come late")
	_bike.reset_to(start)
	assert_eq(_bike.get_late_plan_count(), 0, "a new ride counts anew")
	_bike.wait_for_every_plan = true
	_bike.advance(20)
	assert_eq(_bike.get_late_plan_count(), 0, "every step waited for its plan")


func test_the_automatic_count_moves_n_only_where_plans_may_come_late() -> void:
	var start := Transform3D(Basis(), Vector3(0, 0.02, 0))
	await _spawn(start)
	_bike.set_physics_process(false)
	_bike.controller = "combined"
	assert_eq(_bike.get_trajectories_in_use(), 0, "no planner has run yet")
	_bike.auto_trajectories = true
	_bike.trajectories = 200
	_bike.plan_wait_ms = 0.0
	_bike.set_drive(1.0, 0.0)
	_bike.advance(20)
	var limits := BikeSimulation.auto_trajectory_limits()
	var n := _bike.get_trajectories_in_use()
	assert_between(n, limits.x, limits.y - 1, "200 asked, clamped to the range, then lowered")
	# Waiting for every plan, no plan is late and a ride must repeat: N is the setting's.
	_bike.wait_for_every_plan = true
	_bike.trajectories = 6
	_bike.advance(3)
	assert_eq(_bike.get_trajectories_in_use(), 6)
	_bike.controller = "arcade"
	_bike.advance(1)
	assert_eq(_bike.get_trajectories_in_use(), 0, "the arcade controller plans nothing")


func test_a_dying_planner_is_reported_once_and_the_arcade_controller_steps_in() -> void:
	var start := Transform3D(Basis(), Vector3(0, 0.02, 0))
	await _spawn(start)
	_bike.set_physics_process(false)
	_bike.controller = "combined"
	_bike.auto_trajectories = false
	_bike.trajectories = 4
	_bike.wait_for_every_plan = true
	var reasons: Array[String] = []
	_bike.controller_failed.connect(func(reason: String) -> void: reasons.append(reason))
	_bike.set_drive(1.0, 0.0)
	_bike.advance(15)
	assert_eq(_bike.get_controller_failure(), "")
	# The panic itself (godot-rust logs every panic), then the bike's report of it.
	expect_error("[panic")
	expect_error("the planner stopped (injected fault); arcade steers")
	_bike.inject_planner_fault("injected fault")
	_bike.advance(60)
	var reason := "the planner stopped (injected fault); arcade steers"
	assert_eq(reasons, [reason] as Array[String], "reported once")
	assert_eq(_bike.get_controller_failure(), reason)
	assert_eq(_bike.get_trajectory_paths().size(), 0, "no plans: arcade steers")
	assert_false(_bike.is_crashed(), "the stand-in kept the bike up")
	assert_gt(_bike.get_speed(), 3.0)
	_bike.reset_to(start)
	_bike.advance(10)
	assert_eq(_bike.get_controller_failure(), "", "a new ride has a new planner")
	assert_eq(_bike.get_trajectory_paths().size(), 4)


func test_the_controller_is_a_name_from_the_one_list() -> void:
	var bike := BikeSimulation.new()
	var listed := PackedStringArray()
	for property: Dictionary in bike.get_property_list():
		if property.name == "controller":
			assert_eq(property.hint, PROPERTY_HINT_ENUM, "the inspector offers a drop-down")
			listed = property.hint_string.split(",")
	for name: String in BikeSimulation.controller_names():
		assert_has(listed, name, "the inspector lists every controller players pick")
	assert_gt(listed.size(), BikeSimulation.controller_names().size(), "and the tools' own")
	assert_eq(bike.controller, "arcade", "the default")
	for name: String in listed:
		bike.controller = name
		assert_eq(bike.controller, name, "the property keeps the registry's name")
		assert_eq(bike.get_controller_name(), name)
		assert_ne(BikeSimulation.controller_label(name), "")
	assert_true(BikeSimulation.controller_plans("combined"))
	assert_true(BikeSimulation.controller_plans("mppi"))
	assert_false(BikeSimulation.controller_plans("arcade"))
	assert_eq(BikeSimulation.controller_label("autopilot"), "")
	expect_error('no controller is called "autopilot"')
	bike.controller = "autopilot"
	assert_eq(bike.controller, listed[-1], "an unknown name is refused, the choice kept")
	bike.free()


func test_the_physics_is_a_name_from_the_one_list_and_the_exact_model_rides_on_springs() -> void:
	assert_eq(BikeSimulation.physics_names(), PackedStringArray(["classic", "exact"]))
	var probe := BikeSimulation.new()
	assert_eq(probe.physics, "exact", "the game's physics by default")
	probe.free()
	for physics: String in BikeSimulation.physics_names():
		_bike = BikeSimulation.new()
		_bike.physics = physics
		_bike.controller = "arcade"
		_bike.transform = Transform3D(Basis(), Vector3(0, 0.02, 0))
		_level.add_child(_bike)
		await wait_physics_frames(1)
		_bike.set_drive(1.0, 0.0)
		_bike.advance(150)
		assert_false(_bike.is_crashed(), "%s: arcade rides 5 s" % physics)
		assert_gt(_bike.get_speed(), 3.0, "%s: and gathers speed" % physics)
		var sag := _bike.get_suspension_compression()
		if physics == "exact":
			assert_almost_eq(sag, Vector2(0.039, 0.039), Vector2(0.004, 0.004), "rider sag")
		else:
			assert_eq(sag, Vector2.ZERO, "classic: the thesis's rigid bike")
		_bike.queue_free()


func test_the_drawn_fork_and_shock_compress_with_the_simulated_ones() -> void:
	var bike: BikeSimulation = load("res://scenes/bike/bike.tscn").instantiate()
	bike.controller = "arcade"
	bike.transform = Transform3D(Basis(), Vector3(0, 0.5, 0))
	_level.add_child(bike)
	await wait_physics_frames(1)
	bike.set_drive(0.6, 0.0)
	# Dropped from half a metre: in the air both ends extend to their stops.
	await wait_physics_frames(9)
	var view: VisualBikeView = bike.get_node("VisualBikeView")
	var in_the_air := bike.get_suspension_compression()
	var fork_in_the_air := view.drawn_fork_length()
	var shock_in_the_air := view.drawn_shock_length()
	assert_lt(in_the_air.x, 0.005, "topped out in the air")
	var deepest := 0.0
	for _i in 90:
		await wait_physics_frames(1)
		deepest = maxf(deepest, bike.get_suspension_compression().x)
	assert_gt(deepest, 0.06, "the landing compressed the fork past its sag")
	# Riding on: the drawing has compressed as much as the simulated fork, give or take
	# the fork's movement within one step (the drawing is interpolated between the last
	# two steps, the reading is the last step's).
	assert_false(bike.is_crashed())
	var settled := bike.get_suspension_compression()
	assert_gt(settled.x, 0.01, "the fork carries the bike")
	assert_almost_eq(
		fork_in_the_air - view.drawn_fork_length(),
		settled.x - in_the_air.x,
		0.006,
		"the drawn fork shortened with the simulated one"
	)
	assert_lt(view.drawn_shock_length(), shock_in_the_air - 0.005, "the shock's coil shortened")
	bike.queue_free()


func _spawn(where: Transform3D) -> void:
	_bike = BikeSimulation.new()
	_bike.transform = where
	_level.add_child(_bike)
	await wait_physics_frames(1)


func test_the_bike_is_data_and_the_shipped_file_is_the_reference_bike() -> void:
	await _spawn(Transform3D(Basis(), Vector3(0, 0.02, 0)))
	var reference := _bike.get_center_of_mass()
	_bike.queue_free()
	_bike = BikeSimulation.new()
	_bike.bike = load("res://scenes/bike/bikes/street_350.tres")
	_bike.transform = Transform3D(Basis(), Vector3(0, 0.02, 0))
	_level.add_child(_bike)
	await wait_physics_frames(1)
	assert_eq(_bike.get_center_of_mass(), reference, "the file describes the reference bike")
	_bike.queue_free()
	var small := BikeDescription.new()
	small.wheel_radius = 0.25
	small.wheelbase = 1.25
	_bike = BikeSimulation.new()
	_bike.bike = small
	_level.add_child(_bike)
	await wait_physics_frames(60)
	assert_eq(_bike.get_wheel_radius(), 0.25)
	var rear := _bike.get_body_transform(BikeSimulation.REAR_WHEEL).origin
	var front := _bike.get_body_transform(BikeSimulation.FRONT_WHEEL).origin
	assert_almost_eq(rear.distance_to(front), 1.25, 0.02, "wheelbase as described")
	assert_almost_eq(rear.y, 0.25, 0.02, "standing on its smaller wheels")


func test_a_bike_that_cannot_be_built_is_an_error_not_a_crash() -> void:
	var broken := BikeDescription.new()
	broken.wheelbase = NAN
	_bike = BikeSimulation.new()
	_bike.bike = broken
	expect_error("wheelbase must be within")
	_level.add_child(_bike)
	await wait_physics_frames(2)
	assert_false(_bike.is_running())


func test_an_on_off_bike_field_is_a_checkbox_and_builds_either_way() -> void:
	var description := BikeDescription.new()
	var name := &"tyre_friction_follows_wheel"
	var properties := description.get_property_list()
	var listed := properties.filter(func(p: Dictionary) -> bool: return p.name == name)
	assert_eq(listed.size(), 1, "listed once")
	assert_eq(int(listed[0].type), TYPE_BOOL, "a bool, so the inspector shows a checkbox")
	assert_false(description.get(name), "off, as on the reference bike")
	description.set(name, true)
	assert_true(description.get(name))
	_bike = BikeSimulation.new()
	_bike.bike = description
	_level.add_child(_bike)
	await wait_physics_frames(2)
	assert_true(_bike.is_running(), "a bike with the field on builds")


func test_the_turn_asks_for_no_more_lean_than_the_bike_holds() -> void:
	_bike = BikeSimulation.new()
	assert_almost_eq(_bike.get_max_lean(), deg_to_rad(30.0), 1e-9, "the reference's, unbuilt")
	var description := BikeDescription.new()
	description.set(&"max_lean_deg", 45.0)
	_bike.bike = description
	_level.add_child(_bike)
	await wait_physics_frames(2)
	assert_almost_eq(_bike.get_max_lean(), deg_to_rad(45.0), 1e-9, "the bike's own limit")
