extends TestCase
## The native module loads in Godot, describes itself, and its ODE behaves as physics says.

const G := 9.81


func test_extension_is_loaded_with_a_version() -> void:
	assert_true(NativeModule.is_loaded(), "NativeInfo class registered")
	var semver := RegEx.create_from_string("^\\d+\\.\\d+\\.\\d+$")
	assert_not_null(semver.search(NativeModule.version()), "version %s" % NativeModule.version())


func test_ode_is_double_precision_with_thread_local_collision() -> void:
	var config := NativeModule.ode_configuration()
	assert_has(config, "ODE_double_precision")
	# ODE 0.16 reports an OU build with thread-local storage as ODE_EXT_mt_collisions.
	assert_has(config, "ODE_EXT_mt_collisions")
	assert_true(NativeModule.ode_is_suitable())


func test_a_dropped_body_falls_half_g_t_squared() -> void:
	var world := OdeWorld.new()
	var ball := world.add_sphere_body(1.0, 0.1, Vector3(0, 20, 0))
	var dt := 1.0 / 60.0
	var steps := 90
	for _i: int in steps:
		world.step(dt)
	var t := dt * steps
	var fallen := 20.0 - world.body_position(ball).y
	# Semi-implicit Euler overshoots ½gt² by ½g·t·dt.
	assert_almost_eq(fallen, 0.5 * G * t * t, 0.5 * G * t * dt + 1e-3)
	assert_almost_eq(world.body_linear_velocity(ball).y, -G * t, 1e-3)


func test_a_sphere_rests_on_the_ground() -> void:
	var world := OdeWorld.new()
	world.add_ground_plane(0.0)
	var ball := world.add_sphere_body(2.0, 0.3, Vector3(0, 1.5, 0))
	for _i: int in 300:
		world.step(1.0 / 60.0)
	assert_almost_eq(world.body_position(ball).y, 0.3, 0.01)


func test_invalid_input_is_rejected_with_an_error_not_a_crash() -> void:
	var world := OdeWorld.new()
	expect_error("mass > 0")
	assert_eq(world.add_sphere_body(NAN, 0.1, Vector3.ZERO), -1)
	expect_error("dt must be in (0, 1]")
	world.step(INF)
	expect_error("no body 7")
	assert_eq(world.body_position(7), Vector3.ZERO)
	expect_error("gravity must be finite")
	world.set_gravity(Vector3(0, NAN, 0))
	assert_eq(world.body_count(), 0)


func test_the_library_named_to_players_is_the_one_this_platform_loads() -> void:
	assert_eq(NativeModule.library_file(), "libcpbp.so", "Linux loads the .so beside the game")
