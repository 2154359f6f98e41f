@tool
class_name BankPiece
extends ConcretePiece
## A stretch of road banked sideways, a camber to stop on and pull away from: along this
## node's −z from its origin it twists up from the ground over `twist_length`, falls
## `bank_deg` towards −x (its left edge stays on the ground, its right edge rises) for
## `bank_length`, and twists back down. Both ends lie flat on the ground, so a bike rides
## on and off it either way: riding along −z the road falls to the left, back along +z
## to the right. The right edge is a wall as high as the bank lifts it. Builds its own
## mesh and a matching collision mesh (the bank's twist is not convex).

## Mesh stations along the road (m): close enough that a wheel meets the twist as a
## smooth surface rather than as facets.
const STATION_SPACING := 0.25
## Strips across the road: the surface is straight across, these only shade it evenly.
const STRIPS_ACROSS := 4

## Width across the road (m), centred on the origin.
@export_range(1.0, 20.0, 0.1, "suffix:m") var width := 4.0:
	set(value):
		width = value
		_build()
## How far the road falls sideways where it is fully banked (°).
@export_range(0.0, 20.0, 0.5, "suffix:°") var bank_deg := 8.0:
	set(value):
		bank_deg = value
		_build()
## Length of each twist, from flat to fully banked (m).
@export_range(0.5, 40.0, 0.1, "suffix:m") var twist_length := 5.0:
	set(value):
		twist_length = value
		_build()
## Length fully banked (m).
@export_range(0.0, 80.0, 0.1, "suffix:m") var bank_length := 8.0:
	set(value):
		bank_length = value
		_build()


## The bank (°) at `distance` m along the piece: eased in and out of each twist
## (smoothstep), so the road's twist starts and ends without a kink.
func bank_at(distance: float) -> float:
	var length := 2.0 * twist_length + bank_length
	var from_an_end := clampf(minf(distance, length - distance), 0.0, twist_length)
	return bank_deg * smoothstep(0.0, twist_length, from_an_end)


## The road's height (m) at `across` m from the centre line (positive to the right, +x)
## and `distance` m along it.
func height_at(across: float, distance: float) -> float:
	var from_left_edge := clampf(across + width / 2.0, 0.0, width)
	return from_left_edge * tan(deg_to_rad(bank_at(distance)))


func _piece_mesh() -> ArrayMesh:
	var length := 2.0 * twist_length + bank_length
	var stations := maxi(ceili(length / STATION_SPACING), 1)
	var tool := SurfaceTool.new()
	tool.begin(Mesh.PRIMITIVE_TRIANGLES)
	tool.set_color(colour)
	var at := func(across: float, distance: float) -> Vector3:
		return Vector3(across, height_at(across, distance), -distance)
	var right := width / 2.0
	for i in stations:
		var near := length * i / stations
		var far := length * (i + 1) / stations
		for j in STRIPS_ACROSS:
			var left_x := -right + width * j / STRIPS_ACROSS
			var right_x := -right + width * (j + 1) / STRIPS_ACROSS
			_quad(
				tool,
				at.call(left_x, near),
				at.call(right_x, near),
				at.call(right_x, far),
				at.call(left_x, far)
			)
		# The right edge's wall, facing +x, where the bank has lifted it.
		var low_near := Vector3(right, 0.0, -near)
		var low_far := Vector3(right, 0.0, -far)
		_quad(tool, low_near, low_far, at.call(right, far), at.call(right, near))
	tool.generate_normals()
	tool.set_material(CONCRETE)
	return tool.commit()


## Two triangles over the quad a-b-c-d, front faces clockwise (Godot's winding) seen from
## the side the quad faces; those with no area (a wall where the road is flat) are left out.
static func _quad(tool: SurfaceTool, a: Vector3, b: Vector3, c: Vector3, d: Vector3) -> void:
	for triangle: PackedVector3Array in [
		PackedVector3Array([a, c, b]), PackedVector3Array([a, d, c])
	]:
		var area := (triangle[1] - triangle[0]).cross(triangle[2] - triangle[0]).length()
		if area < 1e-6:
			continue
		for vertex: Vector3 in triangle:
			tool.add_vertex(vertex)
