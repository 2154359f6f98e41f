extends TestCase
## The follow camera stays with the bike through long turns, behind and above it, without
## numerical drift (any engine error raised while it runs fails the test), and never ends
## up behind a wall.

var _level: Node3D
var _bike: BikeSimulation
var _camera: FollowCamera


func before_each() -> void:
	_level = FlatLevel.create()
	_bike = BikeSimulation.new()
	_bike.name = "Bike"
	_level.add_child(_bike)
	_camera = FollowCamera.new()
	_camera.target = _bike
	_level.add_child(_camera)
	add_child(_level)
	await wait_physics_frames(1)


func after_each() -> void:
	_level.queue_free()


func test_it_follows_a_bike_riding_circles() -> void:
	_bike.max_speed_kmh = 15.0
	_bike.set_drive(1.0, 0.0)
	_bike.set_turn(0.5)
	for second: int in 20:
		await wait_frames(60)
		var to_bike := _bike.get_center_of_mass() - _camera.global_position
		assert_lt(to_bike.length(), 12.0, "distance after %d s" % second)
		assert_gt(-_camera.global_basis.z.dot(to_bike.normalized()), 0.9, "looking at the bike")
	assert_false(_bike.is_crashed(), "the arcade controller kept it up through 20 s of circles")
	assert_gt(_camera.global_position.y, _bike.get_center_of_mass().y, "above the bike")


func test_a_wall_between_bike_and_camera_pulls_the_camera_in() -> void:
	# The camera sits about 5 m behind and to the right; a wall 2 m behind the bike.
	var wall := StaticBody3D.new()
	var shape := CollisionShape3D.new()
	var box := BoxShape3D.new()
	box.size = Vector3(20, 6, 0.3)
	shape.shape = box
	wall.add_child(shape)
	wall.position = Vector3(0, 2, 2)
	_level.add_child(wall)
	await wait_frames(30)
	assert_lt(_camera.global_position.z, 2.0 - 0.15, "in front of the wall")
	assert_gt(_camera.global_position.z, 0.0, "still behind the bike")


func test_the_d_pad_orbits_and_the_view_drifts_back() -> void:
	Input.action_press(&"camera_right")
	await wait_frames(30)
	Input.action_release(&"camera_right")
	assert_lt(_camera.orbit.x, -0.5, "orbited")
	await wait_frames(300)
	assert_almost_eq(_camera.orbit.x, 0.0, 0.1, "back behind the bike after a while")


func test_the_low_side_view_looks_at_the_bike_from_beside_it_near_the_ground() -> void:
	_camera.mode = "low_side"
	_bike.max_speed_kmh = 15.0
	_bike.set_drive(1.0, 0.0)
	await wait_frames(120)
	var centre := _bike.get_center_of_mass()
	var forward := _bike.get_body_transform(BikeSimulation.FRAME).basis.x.normalized()
	var right := forward.cross(Vector3.UP).normalized()
	var to_camera := _camera.global_position - centre
	assert_lt(_camera.global_position.y, centre.y, "below the rider's centre of mass")
	assert_gt(to_camera.dot(right), 2.5, "well out to the right of the bike")
	var to_bike := (centre - _camera.global_position).normalized()
	assert_gt(-_camera.global_basis.z.dot(to_bike), 0.9, "looking at the bike")


func test_the_camera_button_cycles_the_modes_in_order() -> void:
	var seen: Array[String] = []
	for i in FollowCamera.MODES.size():
		seen.append(_camera.cycle_mode())
	assert_eq(seen, ["low_side", "helmet", "chase"])
	assert_eq(_camera.cycle_mode(-1), "helmet", "and back")
	expect_error("no camera mode")
	_camera.mode = "drone"
	assert_eq(_camera.mode, "helmet", "an unknown mode is refused")


func test_a_bike_put_down_facing_back_gets_the_camera_round_behind_it() -> void:
	await wait_frames(30)
	_bike.reset_to(Transform3D(Basis(Vector3.UP, PI), Vector3(0, 0.02, 0)))
	await wait_frames(3 * 60)
	var to_bike := _bike.get_center_of_mass() - _camera.global_position
	var heading := _bike.get_body_transform(BikeSimulation.FRAME).basis.x
	assert_gt(heading.dot(to_bike.normalized()), 0.7, "behind the bike, looking along it")
