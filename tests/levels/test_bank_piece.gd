extends TestCase
## BankPiece, the camber a level designer lays down: flat on the ground at both ends,
## banked as asked in the middle, and a collision mesh the bike simulation takes.


func _piece(bank_deg: float) -> BankPiece:
	var piece := BankPiece.new()
	piece.width = 4.0
	piece.twist_length = 5.0
	piece.bank_length = 8.0
	piece.bank_deg = bank_deg
	add_child(piece)
	return piece


func test_the_road_lies_flat_at_both_ends_and_is_banked_as_asked_between() -> void:
	var piece := _piece(8.0)
	var rise := 4.0 * tan(deg_to_rad(8.0))
	for across: float in [-2.0, 0.0, 2.0]:
		assert_almost_eq(piece.height_at(across, 0.0), 0.0, 1e-9, "flat where it starts")
		assert_almost_eq(piece.height_at(across, 18.0), 0.0, 1e-9, "flat where it ends")
	for along: float in [5.0, 9.0, 13.0]:
		assert_almost_eq(piece.bank_at(along), 8.0, 1e-9, "fully banked at %.0f m" % along)
		assert_almost_eq(piece.height_at(-2.0, along), 0.0, 1e-9, "the left edge on the ground")
		assert_almost_eq(piece.height_at(2.0, along), rise, 1e-9, "the right edge lifted")
	assert_almost_eq(piece.bank_at(2.5), 4.0, 1e-9, "half banked half way up the twist")
	assert_almost_eq(piece.bank_at(15.5), 4.0, 1e-9, "and half way down the other")
	piece.free()


func test_its_collision_mesh_is_the_road_it_draws_and_the_simulation_takes_it() -> void:
	var piece := _piece(8.0)
	var shape := (piece.get_node(^"Shape") as CollisionShape3D).shape as ConcavePolygonShape3D
	assert_not_null(shape, "a triangle mesh: the twist is not convex")
	var faces := shape.get_faces()
	assert_gt(faces.size(), 0)
	var highest := 0.0
	for vertex in faces:
		assert_true(vertex.y >= -1e-6, "nothing below the ground")
		assert_true(vertex.z <= 1e-6 and vertex.z >= -18.0 - 1e-6, "along its length")
		highest = maxf(highest, vertex.y)
	assert_almost_eq(highest, 4.0 * tan(deg_to_rad(8.0)), 1e-4, "as high as the bank lifts it")
	# The road's triangles face up (Godot winds front faces clockwise) so wheels land on
	# them: a triangle's normal from its clockwise winding points out of the road.
	var up_faces := 0
	for i in range(0, faces.size(), 3):
		var normal := (faces[i + 2] - faces[i]).cross(faces[i + 1] - faces[i])
		if normal.y > 0.0:
			up_faces += 1
		else:
			assert_almost_eq(normal.normalized().x, 1.0, 1e-6, "the only other face: the wall")
	assert_gt(up_faces, faces.size() / 3 / 2, "most triangles are the road's, facing up")
	assert_true(TerrainCheck.problems(piece).is_empty(), "the simulation takes it")
	piece.free()


func test_a_flat_piece_has_no_wall_and_is_still_a_usable_road() -> void:
	var piece := _piece(0.0)
	var shape := (piece.get_node(^"Shape") as CollisionShape3D).shape as ConcavePolygonShape3D
	for vertex in shape.get_faces():
		assert_almost_eq(vertex.y, 0.0, 1e-9)
	assert_true(TerrainCheck.problems(piece).is_empty(), "no wall triangles without an area")
	piece.free()
