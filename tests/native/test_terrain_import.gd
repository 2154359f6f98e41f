extends TestCase
## Levels built from ordinary Godot collision shapes become the bike's terrain: the bike
## rests on its wheels on every kind of shape, at the right height.

const TOP := 0.5
const WHEEL_RADIUS := 0.3
## Physics ticks to settle (the runner uses --fixed-fps 60: 45 ticks are 0.75 s).
const SETTLE_TICKS := 45

var _level: Node3D


func before_each() -> void:
	_level = Node3D.new()
	add_child(_level)


func after_each() -> void:
	_level.queue_free()


func test_box() -> void:
	var box := BoxShape3D.new()
	box.size = Vector3(20, 1, 20)
	await _assert_rests_on(box, Transform3D(Basis(), Vector3(0, TOP - 0.5, 0)))


func test_sphere() -> void:
	var sphere := SphereShape3D.new()
	sphere.radius = 60.0
	await _assert_rests_on(sphere, Transform3D(Basis(), Vector3(0, TOP - 60.0, 0)))


func test_capsule_lying_across() -> void:
	var capsule := CapsuleShape3D.new()
	capsule.radius = 8.0
	capsule.height = 40.0
	# Lying along z, under the bike's path (it faces −z).
	await _assert_rests_on(
		capsule, Transform3D(Basis(Vector3.RIGHT, PI / 2), Vector3(0, TOP - 8.0, 0))
	)


func test_cylinder() -> void:
	var cylinder := CylinderShape3D.new()
	cylinder.radius = 12.0
	cylinder.height = 1.0
	await _assert_rests_on(cylinder, Transform3D(Basis(), Vector3(0, TOP - 0.5, 0)))


func test_world_boundary() -> void:
	await _assert_rests_on(WorldBoundaryShape3D.new(), Transform3D(Basis(), Vector3(0, TOP, 0)))


func test_scaled_height_map() -> void:
	var map := HeightMapShape3D.new()
	map.map_width = 11
	map.map_depth = 11
	var data := PackedFloat32Array()
	data.resize(121)
	data.fill(0.25)
	map.map_data = data
	# Heights scale with y: 0.25 × 2 = 0.5 above the node at 0.
	await _assert_rests_on(map, Transform3D(Basis().scaled(Vector3(2, 2, 2)), Vector3.ZERO))


func test_concave_triangle_mesh() -> void:
	var mesh := ConcavePolygonShape3D.new()
	var a := Vector3(-10, 0, -10)
	var b := Vector3(10, 0, -10)
	var c := Vector3(10, 0, 10)
	var d := Vector3(-10, 0, 10)
	# Godot's front faces wind clockwise seen from the front (here: from above).
	mesh.set_faces(PackedVector3Array([a, b, c, a, c, d]))
	await _assert_rests_on(mesh, Transform3D(Basis(), Vector3(0, TOP, 0)))


func test_convex_polygon() -> void:
	var convex := ConvexPolygonShape3D.new()
	var points := PackedVector3Array()
	for x: float in [-10.0, 10.0]:
		for y: float in [-1.0, 0.0]:
			for z: float in [-10.0, 10.0]:
				points.append(Vector3(x, y, z))
	convex.points = points
	await _assert_rests_on(convex, Transform3D(Basis(), Vector3(0, TOP, 0)))


func test_unsupported_shapes_are_named_and_skipped() -> void:
	_add_static("Floor", WorldBoundaryShape3D.new(), Transform3D.IDENTITY)
	_add_static("Ray", SeparationRayShape3D.new(), Transform3D.IDENTITY)
	expect_error("Ray/Shape: SeparationRayShape3D is not supported")
	var bike := await _add_bike(Vector3(0, 0.05, 0))
	assert_true(bike.is_running(), "the rest of the level is still used")


func test_broken_geometry_stops_the_simulation_with_a_clear_error() -> void:
	var flat := ConcavePolygonShape3D.new()
	flat.set_faces(PackedVector3Array([Vector3.ZERO, Vector3.ZERO, Vector3.ZERO]))
	_add_static("Broken", flat, Transform3D.IDENTITY)
	expect_error("Broken/Shape: mesh has no triangle with an area")
	var bike := await _add_bike(Vector3(0, 1, 0))
	assert_false(bike.is_running())


func test_a_rebuilt_level_takes_effect_without_losing_the_ride() -> void:
	var floor_shape := BoxShape3D.new()
	floor_shape.size = Vector3(20, 1, 20)
	_add_static("Floor", floor_shape, Transform3D(Basis(), Vector3(0, -0.5, 0)))
	var bike := await _add_bike(Vector3(0, 0.03, 0))
	await wait_physics_frames(SETTLE_TICKS)
	# The level lowers its floor (as a regenerated bump field would change): after the
	# rebuild the bike drops onto the new floor instead of hovering on the old one.
	(_level.get_node("Floor") as Node3D).position.y = -1.5
	assert_true(bike.rebuild_terrain())
	await wait_physics_frames(SETTLE_TICKS)
	assert_almost_eq(
		bike.get_body_transform(BikeSimulation.REAR_WHEEL).origin.y, -1.0 + WHEEL_RADIUS, 0.02
	)


func _assert_rests_on(shape: Shape3D, where: Transform3D) -> void:
	_add_static("Ground", shape, where)
	var bike := await _add_bike(Vector3(0, TOP + 0.03, 0))
	assert_true(bike.is_running(), "the simulation started")
	await wait_physics_frames(SETTLE_TICKS)
	for body: int in [BikeSimulation.REAR_WHEEL, BikeSimulation.FRONT_WHEEL]:
		var wheel_height := bike.get_body_transform(body).origin.y
		assert_almost_eq(
			wheel_height, TOP + WHEEL_RADIUS, 0.015, "%s centre" % bike.get_body_name(body)
		)
	assert_false(bike.is_crashed())


func _add_static(body_name: String, shape: Shape3D, where: Transform3D) -> void:
	var body := StaticBody3D.new()
	body.name = body_name
	body.transform = where
	var collision := CollisionShape3D.new()
	collision.name = "Shape"
	collision.shape = shape
	body.add_child(collision)
	_level.add_child(body)


func _add_bike(position: Vector3) -> BikeSimulation:
	var bike := BikeSimulation.new()
	bike.position = position
	_level.add_child(bike)
	await wait_physics_frames(1)
	return bike
