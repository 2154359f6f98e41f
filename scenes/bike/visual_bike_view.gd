class_name VisualBikeView
extends Node3D
## The bike and rider as the player sees them: a stylised naked motorcycle and a rider
## with two arms and two legs, built from primitive meshes and carried by the simulated
## bodies (thesis §4.2). The simulation has one arm and one leg in the mid-plane; each is
## drawn twice, moved out to either side, so the hands reach the grips and the knees hug
## the tank. Every piece is authored in the bike's frame at rest (x forward, y up,
## z right, origin on the ground between the wheels) and then rides on its body.

const WHEELS: Array[int] = [BikeSimulation.REAR_WHEEL, BikeSimulation.FRONT_WHEEL]
const FORK := BikeSimulation.FORK
const FRAME := BikeSimulation.FRAME
const FORK_LOWER := BikeSimulation.FORK_LOWER
const SWINGARM := BikeSimulation.SWINGARM
const LOWER_LEG := BikeSimulation.LOWER_LEG
const UPPER_LEG := BikeSimulation.UPPER_LEG
const TORSO := BikeSimulation.TORSO
const UPPER_ARM := BikeSimulation.UPPER_ARM
const LOWER_ARM := BikeSimulation.LOWER_ARM
## Directions in the bike frame.
const BIKE_FORWARD := Vector3(1, 0, 0)
## How far out from the mid-plane the thighs are drawn at the hips (m), and a boot's size
## (length, height, width; VisualFeet draws the leg put down with both).
const HIP_OUT := 0.13
const BOOT_SIZE := Vector3(0.26, 0.1, 0.1)
const BIKE_DOWN := Vector3(0, -1, 0)
## Render layer of the neck, helmet and visor alone, so a camera at the rider's eyes can leave
## them out (layer 20, the last one the editor names).
const HEAD_LAYER := 1 << 19

## The simulation to draw; by default the parent.
@export var simulation_path: NodePath = ^".."
## Posed by `show_pose` (a ghost, a replay) instead of following the simulation, which
## then only gives the shapes and the rest pose.
@export var posed_by_recording := false
## Drawn see-through (a ghost).
@export var ghost := false

var _simulation: BikeSimulation
## The bike node's transform when the bodies were at rest: bike frame → world.
var _rest := Transform3D.IDENTITY
## Per piece: the mesh, the body it rides on and its offset within that body.
var _pieces: Array[Dictionary] = []
## Per side (−1 left, 1 right): the nodes of the leg drawn on that footpeg.
var _peg_legs := {-1.0: [], 1.0: []}
## Centre of the grips (bike frame), where the simulated hand holds the bar.
var _grip := Vector3.ZERO
## The rear shock's coil, stretched between its mounts every frame: its mounts on the
## frame and on the swingarm (each in its body's frame) and its length at rest.
var _shock: MeshInstance3D
var _shock_mounts: Array[Vector3] = []
var _shock_rest_length := 1.0
## One stanchion (on the fork) and the lower leg it slides in, to measure the drawn fork.
var _stanchion: Node3D
var _fork_leg: Node3D
## The helmet, for the view from the rider's eyes.
var _helmet: Node3D


func _ready() -> void:
	_simulation = get_node_or_null(simulation_path) as BikeSimulation
	if _simulation != null and not _simulation.is_node_ready():
		await _simulation.ready
	if _simulation == null or not _simulation.is_running():
		push_error("VisualBikeView: no running BikeSimulation at %s" % simulation_path)
		set_process(false)
		return
	_rest = _simulation.global_transform
	_grip = _capsule_ends(LOWER_ARM, -BIKE_FORWARD)[1]
	_build_wheels()
	_build_frame()
	_build_swingarm()
	_build_fork()
	_build_rider()
	_follow()


func _process(_delta: float) -> void:
	if visible and not posed_by_recording:
		_follow()


## Puts every piece on the bodies at `bodies` (global transforms, in body order).
func show_pose(bodies: Array[Transform3D]) -> void:
	for piece: Dictionary in _pieces:
		(piece.node as Node3D).global_transform = bodies[piece.body] * (piece.offset as Transform3D)
	# The coil between its mounts: it shortens as the swingarm rises.
	var top := bodies[FRAME] * _shock_mounts[0]
	var bottom := bodies[SWINGARM] * _shock_mounts[1]
	var stretch := top.distance_to(bottom) / _shock_rest_length
	var basis := _basis_with_y((top - bottom).normalized(), _rest.basis.x)
	_shock.global_transform = Transform3D(
		basis.scaled_local(Vector3(1, stretch, 1)), (top + bottom) / 2.0
	)


func _follow() -> void:
	# One native call per body, not per piece: some sixty pieces ride on eleven bodies.
	var bodies: Array[Transform3D] = []
	for body in _simulation.get_body_count():
		bodies.append(_simulation.get_body_transform(body))
	show_pose(bodies)


## How long the fork is drawn now (m, from the middle of a lower leg up its axis to the
## middle of its stanchion): it shortens by as much as the simulated fork compresses.
func drawn_fork_length() -> float:
	var up := _fork_leg.global_basis.y.normalized()
	return (_stanchion.global_position - _fork_leg.global_position).dot(up)


## Shows or hides the leg drawn on the `side` footpeg (−1 left, 1 right): hidden while
## the rider's foot on that side is down (VisualFeet draws it there).
func show_leg_on_peg(side: float, shown: bool) -> void:
	for node: Node3D in _peg_legs[signf(side)]:
		node.visible = shown


## Where the rider's eyes are now (global), inside the helmet: a camera there leaves out
## HEAD_LAYER.
func eye_point() -> Vector3:
	# The helmet is authored in Godot's axes: −z is the rider's forward.
	var helmet := _helmet.global_transform
	return helmet.origin - helmet.basis.z.normalized() * 0.08 + helmet.basis.y.normalized() * 0.02


## How long the rear shock's coil is drawn now (m, between its mounts).
func drawn_shock_length() -> float:
	return _shock.global_transform.basis.y.length() * _shock_rest_length


func _build_wheels() -> void:
	for body in WHEELS:
		var hub := _rest_of(body).origin
		var axle := _rest.basis.x.normalized()
		var facing := _basis_with_y(axle, Vector3.UP)
		var tyre := TorusMesh.new()
		tyre.inner_radius = 0.225
		tyre.outer_radius = 0.3
		tyre.rings = 48
		_add(body, tyre, "tyre", Transform3D(facing, hub))
		var rim := TorusMesh.new()
		rim.inner_radius = 0.19
		rim.outer_radius = 0.235
		_add(body, rim, "rim", Transform3D(facing, hub))
		var hub_mesh := CylinderMesh.new()
		hub_mesh.top_radius = 0.05
		hub_mesh.bottom_radius = 0.05
		hub_mesh.height = 0.16
		_add(body, hub_mesh, "metal", Transform3D(facing, hub))
		# Spokes make the wheel's turning visible.
		for i in 5:
			var spoke := BoxMesh.new()
			spoke.size = Vector3(0.02, 0.2, 0.035)
			var radial := _rest.basis.y.rotated(axle, TAU * i / 5.0)
			_add(body, spoke, "rim", Transform3D(_basis_with_y(radial, axle), hub + radial * 0.1))
		if body == BikeSimulation.REAR_WHEEL:
			var disc := CylinderMesh.new()
			disc.top_radius = 0.12
			disc.bottom_radius = 0.12
			disc.height = 0.01
			_add(body, disc, "metal", Transform3D(facing, hub - axle * 0.07))


func _build_frame() -> void:
	_box(FRAME, Vector3(0.05, 0.46, 0.0), Vector3(0.46, 0.34, 0.28), 0.0, "engine")
	_ellipsoid(FRAME, Vector3(0.14, 0.94, 0.0), Vector3(0.52, 0.26, 0.36), "paint")
	_box(FRAME, Vector3(-0.3, 0.88, 0.0), Vector3(0.5, 0.08, 0.26), -0.08, "seat")
	_box(FRAME, Vector3(-0.64, 0.93, 0.0), Vector3(0.36, 0.09, 0.16), 0.22, "paint")
	_box(FRAME, Vector3(-0.83, 0.99, 0.0), Vector3(0.04, 0.06, 0.12), 0.0, "tail_light")
	_box(FRAME, Vector3(0.33, 0.62, 0.0), Vector3(0.05, 0.28, 0.3), -0.2, "metal")
	for side: float in [-1.0, 1.0]:
		_rod(
			FRAME,
			Vector3(0.34, 0.98, side * 0.08),
			Vector3(-0.22, 0.5, side * 0.11),
			0.025,
			"frame"
		)
		_rod(
			FRAME, Vector3(-0.05, 0.38, side * 0.2), Vector3(-0.1, 0.38, side * 0.2), 0.02, "metal"
		)
	_rod(FRAME, Vector3(0.0, 0.28, 0.15), Vector3(-0.42, 0.42, 0.2), 0.045, "metal")
	_rod(FRAME, Vector3(-0.42, 0.42, 0.2), Vector3(-0.72, 0.52, 0.2), 0.06, "exhaust")


## The swingarm's two arms from the pivot to the axle, and the rear shock from the frame
## to the swingarm: its coil is stretched between the mounts every frame.
func _build_swingarm() -> void:
	var pivot_axle := _capsule_ends(SWINGARM, BIKE_FORWARD)
	var pivot: Vector3 = pivot_axle[0]
	var axle := _bike_of(_rest_of(BikeSimulation.REAR_WHEEL).origin)
	for side: float in [-1.0, 1.0]:
		_rod(
			SWINGARM,
			pivot + Vector3(0, 0, side * 0.1),
			axle + Vector3(0, 0, side * 0.1),
			0.03,
			"frame"
		)
	_rod(SWINGARM, pivot + Vector3(0, 0, -0.1), pivot + Vector3(0, 0, 0.1), 0.035, "frame")
	# A monoshock under the seat: from the frame to a third of the way along the arm.
	var bottom := pivot.lerp(axle, 0.35) + Vector3(0, 0.04, 0)
	var top := pivot + Vector3(-0.12, 0.36, 0)
	_rod(FRAME, top, top.lerp(bottom, 0.45), 0.03, "metal")
	_rod(SWINGARM, bottom, bottom.lerp(top, 0.5), 0.012, "metal")
	var coil := CylinderMesh.new()
	coil.top_radius = 0.045
	coil.bottom_radius = 0.045
	_shock_rest_length = top.distance_to(bottom) * 0.6
	coil.height = _shock_rest_length
	_shock = MeshInstance3D.new()
	_shock.mesh = coil
	_shock.material_override = BikeLooks.material("spring")
	_shock.top_level = true
	_shock.name = "shock_spring"
	add_child(_shock)
	_shock_mounts = [
		_rest_of(FRAME).affine_inverse() * _world_of(top),
		_rest_of(SWINGARM).affine_inverse() * _world_of(bottom),
	]


## The fork: stanchions on the steered part slide into the lower legs, which carry the
## axle and the mudguard, so the fork visibly compresses.
func _build_fork() -> void:
	var axle := _bike_of(_rest_of(BikeSimulation.FRONT_WHEEL).origin)
	var lower_top: Vector3 = _capsule_ends(FORK_LOWER, BIKE_DOWN)[1]
	var stanchions := _capsule_ends(FORK, BIKE_DOWN)
	var top: Vector3 = stanchions[1]
	for side: float in [-1.0, 1.0]:
		var out := Vector3(0, 0, side * 0.09)
		_rod(FORK, stanchions[0] + out, top + out, 0.022, "metal")
		_stanchion = _pieces[-1].node
		_rod(FORK_LOWER, axle + out, lower_top + out, 0.032, "frame")
		_fork_leg = _pieces[-1].node
		_rod(
			FORK,
			top + Vector3(-0.04, 0.04, side * 0.06),
			Vector3(_grip.x, _grip.y, side * 0.33),
			0.016,
			"frame"
		)
	_rod(FORK, Vector3(_grip.x, _grip.y, -0.38), Vector3(_grip.x, _grip.y, 0.38), 0.015, "frame")
	for side: float in [-1.0, 1.0]:
		_rod(
			FORK,
			Vector3(_grip.x, _grip.y, side * 0.3),
			Vector3(_grip.x, _grip.y, side * 0.4),
			0.022,
			"rubber"
		)
	_box(FORK, top + Vector3(0.0, -0.02, 0.0), Vector3(0.08, 0.05, 0.24), 0.0, "frame")
	var lamp := SphereMesh.new()
	lamp.radius = 0.085
	lamp.height = 0.15
	_add(FORK, lamp, "lamp", Transform3D(_bike_basis(), _world_of(top + Vector3(0.14, -0.12, 0.0))))
	_box(FORK_LOWER, axle + Vector3(0.0, 0.35, 0.0), Vector3(0.3, 0.03, 0.14), 0.0, "paint")


func _build_rider() -> void:
	var ankle_knee := _capsule_ends(LOWER_LEG, BIKE_DOWN)
	var knee_hip := _capsule_ends(UPPER_LEG, BIKE_FORWARD)
	var hip_head := _capsule_ends(TORSO, BIKE_DOWN)
	var shoulder_elbow := _capsule_ends(UPPER_ARM, -BIKE_DOWN)
	var elbow_grip := _capsule_ends(LOWER_ARM, -BIKE_FORWARD)
	for side: float in [-1.0, 1.0]:
		var knee_out := side * 0.19
		var first_leg_piece := _pieces.size()
		_limb(LOWER_LEG, ankle_knee, side * 0.2, knee_out, 0.06, "trousers")
		_limb(UPPER_LEG, knee_hip, knee_out, side * HIP_OUT, 0.08, "trousers")
		_box(LOWER_LEG, ankle_knee[0] + Vector3(0.05, -0.02, side * 0.2), BOOT_SIZE, 0.0, "boots")
		for piece: Dictionary in _pieces.slice(first_leg_piece):
			_peg_legs[side].append(piece.node)
		_limb(UPPER_ARM, shoulder_elbow, side * 0.19, side * 0.27, 0.05, "jacket")
		_limb(LOWER_ARM, elbow_grip, side * 0.27, side * 0.35, 0.045, "jacket")
		var glove := SphereMesh.new()
		glove.radius = 0.05
		glove.height = 0.1
		var grip := elbow_grip[1] + Vector3(0, 0, side * 0.35)
		_add(LOWER_ARM, glove, "gloves", Transform3D(_bike_basis(), _world_of(grip)))
	var hip: Vector3 = hip_head[0]
	var along: Vector3 = (hip_head[1] - hip).normalized()
	_rod(TORSO, hip + along * 0.05, hip + along * 0.5, 0.17, "jacket", 1.25)
	_rod(TORSO, hip + along * 0.5, hip + along * 0.6, 0.06, "trousers")
	var helmet := SphereMesh.new()
	helmet.radius = 0.135
	helmet.height = 0.28
	var head := hip + along * 0.66
	_add(TORSO, helmet, "helmet", Transform3D(_bike_basis(), _world_of(head)))
	_helmet = _pieces[-1].node
	_ellipsoid(TORSO, head + Vector3(0.09, 0.0, 0.0), Vector3(0.1, 0.11, 0.2), "visor")
	# Neck, helmet and visor.
	for head_piece: Dictionary in _pieces.slice(-3):
		(head_piece.node as VisualInstance3D).layers = HEAD_LAYER


## The two ends (bike frame) of a rider body's capsule, the one furthest along
## `first_towards` (bike frame direction) first.
func _capsule_ends(body: int, first_towards: Vector3) -> Array[Vector3]:
	for shape: Dictionary in _simulation.get_shapes():
		if shape.body != body or shape.kind != "capsule":
			continue
		var offset: Transform3D = shape.offset
		var half := offset.basis.z.normalized() * float(shape.length) / 2.0
		var body_rest := _rest_of(body)
		var a := _bike_of(body_rest * (offset.origin + half))
		var b := _bike_of(body_rest * (offset.origin - half))
		var ends: Array[Vector3] = [a, b]
		if b.dot(first_towards) > a.dot(first_towards):
			ends.reverse()
		return ends
	push_error("VisualBikeView: body %d has no capsule" % body)
	var fallback: Array[Vector3] = [Vector3.ZERO, Vector3.UP]
	return fallback


## A limb drawn between `ends`, moved out to z = `from_side` at the first end and
## `to_side` at the second.
func _limb(
	body: int, ends: Array[Vector3], from_side: float, to_side: float, radius: float, look: String
) -> void:
	_rod(body, ends[0] + Vector3(0, 0, from_side), ends[1] + Vector3(0, 0, to_side), radius, look)


## A capsule (rounded rod) from `a` to `b` (bike frame), `widen` times wider sideways.
func _rod(body: int, a: Vector3, b: Vector3, radius: float, look: String, widen := 1.0) -> void:
	var capsule := CapsuleMesh.new()
	capsule.radius = radius
	capsule.height = a.distance_to(b) + 2.0 * radius
	var from := _world_of(a)
	var to := _world_of(b)
	var basis := _basis_with_y((to - from).normalized(), _rest.basis.x).scaled_local(
		Vector3(widen, 1.0, 1.0)
	)
	_add(body, capsule, look, Transform3D(basis, (from + to) / 2.0))


func _box(body: int, centre: Vector3, size: Vector3, pitch: float, look: String) -> void:
	var box := BoxMesh.new()
	box.size = Vector3(size.z, size.y, size.x)
	var basis := _bike_basis() * Basis(Vector3.RIGHT, pitch)
	_add(body, box, look, Transform3D(basis, _world_of(centre)))


func _ellipsoid(body: int, centre: Vector3, size: Vector3, look: String) -> void:
	var sphere := SphereMesh.new()
	sphere.radius = 0.5
	sphere.height = 1.0
	var basis := _bike_basis() * Basis.from_scale(Vector3(size.z, size.y, size.x))
	_add(body, sphere, look, Transform3D(basis, _world_of(centre)))


## Adds a mesh placed at `world_at_rest` that rides on `body` from now on.
func _add(body: int, mesh: Mesh, look: String, world_at_rest: Transform3D) -> void:
	var node := MeshInstance3D.new()
	node.mesh = mesh
	if ghost:
		node.material_override = BikeLooks.ghost_material(look)
		node.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	else:
		node.material_override = BikeLooks.material(look)
	node.top_level = true
	node.name = "%s_%d" % [look, _pieces.size()]
	add_child(node)
	_pieces.append(
		{node = node, body = body, offset = _rest_of(body).affine_inverse() * world_at_rest}
	)


func _rest_of(body: int) -> Transform3D:
	return _simulation.get_body_transform(body)


## World rest position of a bike-frame point.
func _world_of(point: Vector3) -> Vector3:
	return _rest * Vector3(point.z, point.y, -point.x)


## Bike-frame point of a world rest position.
func _bike_of(world: Vector3) -> Vector3:
	var local := _rest.affine_inverse() * world
	return Vector3(-local.z, local.y, local.x)


## World rest basis whose x is the bike's right, y up and z backwards (Godot's meshes).
func _bike_basis() -> Basis:
	return _rest.basis.orthonormalized()


## An orthonormal basis whose y is `y` and whose x is as close to `x_hint` as it can be.
static func _basis_with_y(y: Vector3, x_hint: Vector3) -> Basis:
	var hint := (
		x_hint
		if absf(x_hint.normalized().dot(y)) < 0.95
		else y.cross(Vector3.UP + Vector3.RIGHT * 0.3)
	)
	var x := (hint - y * hint.dot(y)).normalized()
	return Basis(x, y, x.cross(y))
