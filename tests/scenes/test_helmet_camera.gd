extends TestCase
## The helmet view sees from the drawn rider's eyes, along the bike's heading, rolling
## with part of the lean, and turns the head with the d-pad.

const BIKE := preload("res://scenes/bike/bike.tscn")

var _level: Node3D
var _bike: BikeSimulation
var _camera: FollowCamera


func before_each() -> void:
	_level = FlatLevel.create()
	_bike = BIKE.instantiate() as BikeSimulation
	_level.add_child(_bike)
	_camera = FollowCamera.new()
	_camera.target = _bike
	_camera.mode = "helmet"
	_level.add_child(_camera)
	add_child(_level)
	await wait_physics_frames(1)


func after_each() -> void:
	_level.queue_free()


func test_it_sees_from_the_riders_eyes_along_the_heading_in_a_turn() -> void:
	_bike.max_speed_kmh = 15.0
	_bike.set_drive(1.0, 0.0)
	await wait_frames(90)
	_bike.set_turn(0.6)
	await wait_frames(90)
	var frame := _bike.get_body_transform(BikeSimulation.FRAME)
	var torso := _bike.get_body_transform(BikeSimulation.TORSO)
	var eye := _camera.global_position
	assert_gt(eye.y - torso.origin.y, 0.2, "above the torso's centre, at head height")
	assert_lt(eye.distance_to(torso.origin), 1.0, "on the rider")
	var looking := -_camera.global_basis.z
	assert_gt(looking.dot(frame.basis.x.normalized()), 0.9, "along the bike's heading")
	var lean := absf(_bike.get_lean())
	var roll := absf(asin(clampf(_camera.global_basis.x.y, -1.0, 1.0)))
	assert_gt(lean, deg_to_rad(5.0), "the bike leans into the turn")
	assert_between(roll, lean * 0.3, lean * 0.7, "the view rolls with about half the lean")


func test_the_d_pad_turns_the_head() -> void:
	await wait_frames(10)
	var ahead := -_camera.global_basis.z
	Input.action_press(&"camera_left")
	await wait_frames(20)
	Input.action_release(&"camera_left")
	var turned := -_camera.global_basis.z
	assert_lt(ahead.dot(turned), 0.9, "looking to the side")
