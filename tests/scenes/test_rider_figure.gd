extends TestCase
## The skinned rider is posed by IK on the simulated bodies: hands on the simulated
## hands, feet on the simulated feet, elbows and knees bent towards the simulated ones,
## the head turned into a turn; after a crash the drawn rider follows the tumbling bodies.
## The jacket is dyed after the bike's paint. (The stance drawn over the simulated rider is
## test_rider_stance.gd's.)

## How close (m) the IK puts a hand or foot to where the simulation has it.
const REACH := 0.02
const SIDES: Array[float] = [-1.0, 1.0]

var _game: Game


func before_each() -> void:
	_game = await GameFixture.start(self)


## Stops the game and lets the drawn rider's IK pose it on the bodies as they are now.
func _posed_now() -> void:
	get_tree().paused = true
	_view().follow()
	await _view().rider().skeleton().skeleton_updated


func after_each() -> void:
	get_tree().paused = false
	for action: StringName in InputMap.get_actions():
		Input.action_release(action)
	_game.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func _view() -> VisualBikeView:
	return _game.bike.get_node(^"VisualBikeView") as VisualBikeView


## Where the simulation has the mid-plane `body`'s end nearest `near` (world), moved out to
## `side` by `out` metres along the drawn rider's right (its torso's).
func _simulated_end(body: int, near: Vector3, side: float, out: float) -> Vector3:
	var ends := _capsule_ends(body)
	var right := _view().rider().skeleton().global_basis.x.normalized()
	var end: Vector3 = ends[0] if ends[0].distance_to(near) < ends[1].distance_to(near) else ends[1]
	return end + right * side * out


func _capsule_ends(body: int) -> Array[Vector3]:
	var ends: Array[Vector3] = []
	for shape: BikeShape in _game.bike.get_shapes():
		if shape.body == body and shape.kind == "capsule":
			var world := _game.bike.get_body_transform(body) * shape.offset
			var half := world.basis.z.normalized() * shape.length / 2.0
			ends = [world.origin + half, world.origin - half]
	return ends


func test_the_skin_is_bound_to_a_skeleton_of_two_armed_two_legged_rider() -> void:
	var rider := _view().rider()
	var skeleton := rider.skeleton()
	for bone: String in ["hips", "head", "hand_L", "hand_R", "foot_L", "foot_R"]:
		assert_gt(skeleton.find_bone(bone), -1, "bone %s" % bone)
	var body := skeleton.get_node(^"Body") as MeshInstance3D
	var mesh := body.mesh as ArrayMesh
	assert_eq(mesh.get_surface_count(), 1, "one skinned surface")
	var arrays := mesh.surface_get_arrays(0)
	var vertices := (arrays[Mesh.ARRAY_VERTEX] as PackedVector3Array).size()
	assert_eq((arrays[Mesh.ARRAY_BONES] as PackedInt32Array).size(), 4 * vertices, "4 bones each")
	assert_eq((arrays[Mesh.ARRAY_WEIGHTS] as PackedFloat32Array).size(), 4 * vertices, "weights")
	var colours := arrays[Mesh.ARRAY_COLOR] as PackedColorArray
	var worn := BikeLooks.COLOURS.duplicate()
	worn.jacket = RiderFigure.jacket_colour(_game.bike.bike.paint)
	for look: String in ["jacket", "trousers", "boots", "gloves"]:
		assert_true(_has_colour(colours, worn[look]), "%s in the skin's colours" % look)
	assert_false(body.skeleton.is_empty(), "the skin follows the skeleton")
	assert_eq(_inward_faces(mesh), 0, "every face faces outwards")
	assert_not_null(skeleton.get_node_or_null(^"LimbIK") as TwoBoneIK3D, "limbs by TwoBoneIK3D")
	assert_not_null(skeleton.get_node_or_null(^"HeadLook") as LookAtModifier3D, "head look-at")


func test_hands_and_feet_are_where_the_simulation_has_them_in_a_turn() -> void:
	# The drawing of the simulated rider alone: the stance riders take is drawn over it
	# (test_rider_stance.gd).
	_view().stance_drawn = false
	# The arcade controller plans nothing, so the ride is the same however busy the machine.
	_game.bike.controller = "arcade"
	Input.action_press(&"throttle", 0.7)
	await wait_physics_frames(120)
	Input.action_press(&"steer_right", 0.8)
	await wait_physics_frames(90)
	assert_false(_game.bike.is_crashed(), "rode into the turn")
	await _posed_now()
	var rider := _view().rider()
	var out := RiderFigure.OUT
	# The hands hold the grips, either side of where the simulated hand holds the bar.
	var hands := [rider.bone_transform("hand_L").origin, rider.bone_transform("hand_R").origin]
	var between: Vector3 = (hands[0] + hands[1]) / 2.0
	var held := _simulated_end(BikeSimulation.LOWER_ARM, between, 0.0, 0.0)
	assert_lt(between.distance_to(held), REACH, "hands either side of the simulated hand")
	var apart: float = hands[0].distance_to(hands[1])
	assert_almost_eq(apart, 2.0 * out.hand, REACH, "hands on the grips %.2f m apart" % apart)
	for side in SIDES:
		var s := "_L" if side < 0.0 else "_R"
		var foot := rider.bone_transform("foot" + s).origin
		var peg := _simulated_end(BikeSimulation.LOWER_LEG, foot, side, out.ankle)
		assert_lt(
			foot.distance_to(peg), REACH, "foot%s on the peg (%.3f m)" % [s, foot.distance_to(peg)]
		)
		var knee := rider.bone_transform("shin" + s).origin
		var simulated_knee := _simulated_end(BikeSimulation.UPPER_LEG, knee, side, out.knee)
		assert_lt(knee.distance_to(simulated_knee), REACH, "knee%s bent as simulated" % s)
		var elbow := rider.bone_transform("forearm" + s).origin
		var simulated_elbow := _simulated_end(BikeSimulation.UPPER_ARM, elbow, side, out.elbow)
		# 2 mm measured: the hands hold the drawn grips, a little off the simulated hand.
		assert_lt(elbow.distance_to(simulated_elbow), REACH, "elbow%s bent as simulated" % s)
	var eyes := _view().eye_point()
	var head := rider.bone_transform("head")
	var looking := -head.basis.z.normalized()
	var right := _game.bike.get_body_transform(BikeSimulation.FRAME).basis.z.normalized()
	assert_gt(looking.dot(right), 0.02, "looks into the right turn")
	assert_lt(eyes.distance_to(head.origin), 0.12, "eyes inside the helmet")


func test_a_fallen_rider_is_drawn_on_the_tumbling_bodies() -> void:
	# Nobody balancing and a nudge of the bar: the bike falls and the rider lets go.
	await GameFixture.ride_unbalanced_and_nudge(self, _game)
	for frame in 400:
		await wait_physics_frames(1)
		if not _game.bike.is_rider_on():
			break
	Input.action_release(&"throttle")
	assert_false(_game.bike.is_rider_on(), "the rider fell off")
	await wait_physics_frames(40)
	await _posed_now()
	var rider := _view().rider()
	for side in SIDES:
		var s := "_L" if side < 0.0 else "_R"
		var hand := rider.bone_transform("hand" + s).origin
		var simulated := _simulated_end(BikeSimulation.LOWER_ARM, hand, side, RiderFigure.OUT.hand)
		assert_lt(hand.distance_to(simulated), 0.05, "hand%s with the tumbling arm" % s)


## Triangles whose front (clockwise, Godot's) faces away from their vertices' normals.
static func _inward_faces(mesh: ArrayMesh) -> int:
	var inward := 0
	for surface in mesh.get_surface_count():
		var arrays := mesh.surface_get_arrays(surface)
		var at: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
		var normals: PackedVector3Array = arrays[Mesh.ARRAY_NORMAL]
		var corners: PackedInt32Array = arrays[Mesh.ARRAY_INDEX]
		for i in range(0, corners.size(), 3):
			var a := corners[i]
			var front := (at[corners[i + 2]] - at[a]).cross(at[corners[i + 1]] - at[a])
			if front.length() > 1e-8 and front.dot(normals[a] + normals[corners[i + 1]]) < 0.0:
				inward += 1
	return inward


func test_the_helmet_wears_the_bikes_paint_and_a_visor() -> void:
	var head := _view().rider().find_child("Head", true, false) as Node3D
	var colours: Array[Color] = []
	for piece: MeshInstance3D in head.find_children("*", "MeshInstance3D", false, false):
		colours.append((piece.material_override as StandardMaterial3D).albedo_color)
	assert_has(colours, _game.bike.bike.paint, "a stripe in the bike's paint")
	assert_has(colours, BikeLooks.COLOURS.visor, "a visor")
	assert_has(colours, BikeLooks.COLOURS.helmet, "a shell")


func test_the_jacket_is_dyed_after_the_bikes_paint() -> void:
	var body := _view().rider().skeleton().get_node(^"Body") as MeshInstance3D
	var colours := body.mesh.surface_get_arrays(0)[Mesh.ARRAY_COLOR] as PackedColorArray
	var jacket := RiderFigure.jacket_colour(_game.bike.bike.paint)
	assert_true(_has_colour(colours, jacket), "the jacket in the bike's colours")
	assert_false(_has_colour(colours, BikeLooks.COLOURS.jacket), "not the stock blue")
	assert_true(_has_colour(colours, BikeLooks.COLOURS.trousers), "the trousers stay dark")
	var dyed := RiderFigure.jacket_colour(Color(0.38, 0.72, 0.08))
	assert_lt(dyed.v, 0.72, "a shade darker than the gloss")
	assert_almost_eq(dyed.h, Color(0.38, 0.72, 0.08).h, 0.01, "the same hue")


## Whether `colours` (a mesh's, stored at 8 bits a channel) hold one within 0.01 of `near`.
func _has_colour(colours: PackedColorArray, near: Color) -> bool:
	for colour in colours:
		if Vector3(colour.r - near.r, colour.g - near.g, colour.b - near.b).length() < 0.01:
			return true
	return false
