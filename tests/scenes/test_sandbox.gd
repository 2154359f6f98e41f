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
