class_name RoundedBox
extends RefCounted
## A box with rounded edges and corners, a metre each way about its centre: the
## superellipsoid |x|ᵖ + |y|ᵖ + |z|ᵖ = 0.5ᵖ, between a sphere (p = 2) and a box (p → ∞).
## Pressed tins, moulded seats and cast engine cases are shaped like this, where a plain
## box reads as a crate. One mesh, made once and shared, scaled to each piece.

## How square it is: 5 leaves flat faces and edges rounded over about a fifth of a side.
const SQUARENESS := 5.0
const RADIAL_SEGMENTS := 32
const RINGS := 16

static var _made: ArrayMesh


static func mesh() -> ArrayMesh:
	if _made == null:
		_made = _build()
	return _made


## A sphere's vertices pushed out along their directions to the superellipsoid, with the
## surface's own normals (its gradient) rather than the sphere's.
static func _build() -> ArrayMesh:
	var sphere := SphereMesh.new()
	sphere.radius = 0.5
	sphere.height = 1.0
	sphere.radial_segments = RADIAL_SEGMENTS
	sphere.rings = RINGS
	var arrays := sphere.get_mesh_arrays()
	var vertices: PackedVector3Array = arrays[Mesh.ARRAY_VERTEX]
	var normals: PackedVector3Array = arrays[Mesh.ARRAY_NORMAL]
	var p := SQUARENESS
	for i in vertices.size():
		var d := vertices[i].normalized()
		var reach := pow(pow(absf(d.x), p) + pow(absf(d.y), p) + pow(absf(d.z), p), -1.0 / p)
		var at := d * reach * 0.5
		vertices[i] = at
		var gradient := Vector3(
			signf(at.x) * pow(absf(at.x), p - 1.0),
			signf(at.y) * pow(absf(at.y), p - 1.0),
			signf(at.z) * pow(absf(at.z), p - 1.0)
		)
		normals[i] = gradient.normalized() if gradient.length() > 0.0 else d
	arrays[Mesh.ARRAY_VERTEX] = vertices
	arrays[Mesh.ARRAY_NORMAL] = normals
	arrays[Mesh.ARRAY_TANGENT] = null
	var made := ArrayMesh.new()
	made.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
	return made
