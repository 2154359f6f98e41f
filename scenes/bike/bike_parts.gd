class_name BikeParts
extends RefCounted
## The drawn bike's pieces: meshes authored in the bike's frame at rest (BikeRestFrame: x
## forward, y up, z right, metres) and each carried by one simulated body from then on.
## VisualBikeView and the builders of its parts (BikeWheels) add pieces here; the view puts
## them on the bodies every frame.

var _frame: BikeRestFrame
## Where the pieces are added as children.
var _parent: Node3D
var _paint: Color
var _ghost: bool
## Per piece: its node, the body it rides on and its offset within that body.
var _pieces: Array[Dictionary] = []


func _init(frame: BikeRestFrame, parent: Node3D, paint: Color, ghost: bool) -> void:
	_frame = frame
	_parent = parent
	_paint = paint
	_ghost = ghost


## The bike at rest the pieces are authored on.
func frame() -> BikeRestFrame:
	return _frame


## Puts every piece on the bodies at `bodies` (global transforms, in body order).
func place(bodies: Array[Transform3D]) -> void:
	for piece: Dictionary in _pieces:
		(piece.node as Node3D).global_transform = bodies[piece.body] * (piece.offset as Transform3D)


## Adds a mesh placed at `world_at_rest` that rides on `body` from now on.
func add(body: int, mesh: Mesh, look: String, world_at_rest: Transform3D) -> MeshInstance3D:
	var node := MeshInstance3D.new()
	node.mesh = mesh
	var colour := _paint if look == "paint" else Color(0, 0, 0, 0)
	BikeLooks.dress(node, look, colour, _ghost)
	node.top_level = true
	node.name = "%s_%d" % [look, _pieces.size()]
	_parent.add_child(node)
	_pieces.append({node = node, body = body, offset = _frame.on_body(body, world_at_rest)})
	return node


## A capsule (rounded rod) from `a` to `b` (bike frame), `widen` times wider sideways.
func rod(
	body: int, a: Vector3, b: Vector3, radius: float, look: String, widen := 1.0
) -> MeshInstance3D:
	var capsule := CapsuleMesh.new()
	capsule.radius = radius
	capsule.height = a.distance_to(b) + 2.0 * radius
	var from := _frame.world_of(a)
	var to := _frame.world_of(b)
	var basis := basis_with_y((to - from).normalized(), _frame.right()).scaled_local(
		Vector3(widen, 1.0, 1.0)
	)
	return add(body, capsule, look, Transform3D(basis, (from + to) / 2.0))


## A box about `centre` (bike frame), `size` along the bike's forward, up and right,
## tilted nose up by `pitch` (radians).
func box(body: int, centre: Vector3, size: Vector3, pitch: float, look: String) -> MeshInstance3D:
	var mesh := BoxMesh.new()
	mesh.size = Vector3(size.z, size.y, size.x)
	var basis := _frame.basis() * Basis(Vector3.RIGHT, pitch)
	return add(body, mesh, look, Transform3D(basis, _frame.world_of(centre)))


## A flat disc of `radius` and `thickness` about `centre` (bike frame), facing sideways
## (a wheel's, a brake's, a sprocket's).
func disc(
	body: int, centre: Vector3, radius: float, thickness: float, look: String
) -> MeshInstance3D:
	var mesh := CylinderMesh.new()
	mesh.top_radius = radius
	mesh.bottom_radius = radius
	mesh.height = thickness
	var facing := basis_with_y(_frame.right(), Vector3.UP)
	return add(body, mesh, look, Transform3D(facing, _frame.world_of(centre)))


## `unit` (a metre each way about its centre) stretched to `block`'s size and tilt (see
## BikeBodywork.fitted_block).
func unit_shape(body: int, unit: Mesh, block: Dictionary, look: String) -> MeshInstance3D:
	var size: Vector3 = block.size
	var basis := (
		_frame.basis()
		* Basis(Vector3.RIGHT, block.pitch)
		* Basis.from_scale(Vector3(size.z, size.y, size.x))
	)
	return add(body, unit, look, Transform3D(basis, _frame.world_of(block.centre)))


static func unit_sphere() -> SphereMesh:
	var sphere := SphereMesh.new()
	sphere.radius = 0.5
	sphere.height = 1.0
	return sphere


## An orthonormal basis whose y is `y` and whose x is as close to `x_hint` as it can be.
static func basis_with_y(y: Vector3, x_hint: Vector3) -> Basis:
	var hint := (
		x_hint
		if absf(x_hint.normalized().dot(y)) < 0.95
		else y.cross(Vector3.UP + Vector3.RIGHT * 0.3)
	)
	var x := (hint - y * hint.dot(y)).normalized()
	return Basis(x, y, x.cross(y))
