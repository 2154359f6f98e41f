@tool
class_name RampPiece
extends ConcretePiece
## A solid prism for ramps, hills, tables, drops and steps: it rises over `up_length`
## to `height`, stays level for `top_length` and comes down over `down_length` (along this
## node's −z, starting at its origin). A length of 0 makes that face vertical: a step to
## climb or a drop to ride off. Builds its own convex collision shape and mesh.

## Width (m), centred on the origin.
@export_range(0.5, 40.0, 0.1, "suffix:m") var width := 4.0:
	set(value):
		width = value
		_build()
## Height of the top (m).
@export_range(0.05, 10.0, 0.05, "suffix:m") var height := 0.6:
	set(value):
		height = value
		_build()
## Length of the way up (m); 0 is a vertical step.
@export_range(0.0, 40.0, 0.1, "suffix:m") var up_length := 4.0:
	set(value):
		up_length = value
		_build()
## Length of the level top (m).
@export_range(0.0, 80.0, 0.1, "suffix:m") var top_length := 2.0:
	set(value):
		top_length = value
		_build()
## Length of the way down (m); 0 is a drop.
@export_range(0.0, 40.0, 0.1, "suffix:m") var down_length := 4.0:
	set(value):
		down_length = value
		_build()


func _piece_mesh() -> ArrayMesh:
	return _prism_mesh(_profile())


## The prism as a convex hull: its profile at both sides.
func _piece_shape(_mesh_drawn: ArrayMesh) -> Shape3D:
	var profile := _profile()
	var points := PackedVector3Array()
	for side: float in [-width / 2.0, width / 2.0]:
		for p: Vector2 in profile:
			points.append(Vector3(side, p.y, -p.x))
	var convex := ConvexPolygonShape3D.new()
	convex.points = points
	return convex


## The side profile as (distance forward, height), anticlockwise from the rear bottom,
## without repeated points where a face is vertical or the top has no length.
func _profile() -> PackedVector2Array:
	var end := maxf(up_length + top_length + down_length, 0.05)
	var corners: Array[Vector2] = [
		Vector2(0.0, 0.0),
		Vector2(end, 0.0),
		Vector2(up_length + top_length, height) if down_length > 0.0 else Vector2(end, height),
		Vector2(up_length, height),
	]
	var profile := PackedVector2Array()
	for corner in corners:
		if profile.is_empty() or not profile[-1].is_equal_approx(corner):
			profile.append(corner)
	if profile.size() > 3 and profile[-1].is_equal_approx(profile[0]):
		profile.remove_at(profile.size() - 1)
	return profile


func _prism_mesh(profile: PackedVector2Array) -> ArrayMesh:
	var tool := SurfaceTool.new()
	tool.begin(Mesh.PRIMITIVE_TRIANGLES)
	tool.set_color(colour)
	var left := -width / 2.0
	var right := width / 2.0
	var at := func(p: Vector2, x: float) -> Vector3: return Vector3(x, p.y, -p.x)
	# Sides: a fan over the convex profile (winding per side so both face outwards).
	for i in range(1, profile.size() - 1):
		tool.add_vertex(at.call(profile[0], right))
		tool.add_vertex(at.call(profile[i + 1], right))
		tool.add_vertex(at.call(profile[i], right))
		tool.add_vertex(at.call(profile[0], left))
		tool.add_vertex(at.call(profile[i], left))
		tool.add_vertex(at.call(profile[i + 1], left))
	# The faces around the profile, each a quad between the two sides.
	for i in profile.size():
		var a := profile[i]
		var b := profile[(i + 1) % profile.size()]
		tool.add_vertex(at.call(a, left))
		tool.add_vertex(at.call(a, right))
		tool.add_vertex(at.call(b, right))
		tool.add_vertex(at.call(a, left))
		tool.add_vertex(at.call(b, right))
		tool.add_vertex(at.call(b, left))
	tool.generate_normals()
	tool.set_material(CONCRETE)
	return tool.commit()
