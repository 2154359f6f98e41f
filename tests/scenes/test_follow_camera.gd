extends TestCase
## The follow camera stays with the bike through long turns, behind and above it, without
## numerical drift (any engine error raised while it runs fails the test).

var _level: Node3D
var _bike: BikeSimulation
var _camera: FollowCamera


func before_each() -> void:
	_level = FlatLevel.create()
	_bike = BikeSimulation.new()
	_bike.name = "Bike"
	_level.add_child(_bike)
	_camera = FollowCamera.new()
	_camera.target_path = ^"../Bike"
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
