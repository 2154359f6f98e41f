class_name VisualFeet
extends Node3D
## The rider's leg put down at a stop: when the simulation has a foot down on a side and
## it stands on the road (or the bike leans towards it), a leg is drawn from the rider's
## hip to that foot, bent at the knee by two-bone IK, in place of the leg on that peg.

const FRAME := BikeSimulation.FRAME
const UPPER_LEG := BikeSimulation.UPPER_LEG
const LOWER_LEG := BikeSimulation.LOWER_LEG
const HIP_OUT := VisualBikeView.HIP_OUT
const BOOT_SIZE := VisualBikeView.BOOT_SIZE

## The simulation to draw, and the VisualBikeView whose peg legs it hides (by default
## the parent, so hiding the drawn bike hides these legs too).
@export var simulation_path: NodePath = ^"../.."
@export var visual_bike_path: NodePath = ^".."

var _simulation: BikeSimulation
var _visual_bike: VisualBikeView
## The hip end of the thigh, in the upper leg body's frame; the thigh's and shin's
## lengths (m).
var _hip_on_thigh := Vector3.ZERO
var _thigh := 0.43
var _shin := 0.43
## Per side (−1, 1): the drawn thigh, shin and boot.
var _legs := {}


func _ready() -> void:
	_simulation = get_node_or_null(simulation_path) as BikeSimulation
	_visual_bike = get_node_or_null(visual_bike_path) as VisualBikeView
	if _simulation != null and not _simulation.is_node_ready():
		await _simulation.ready
	if _simulation == null or not _simulation.is_running():
		push_error("VisualFeet: no running BikeSimulation at %s" % simulation_path)
		set_process(false)
		return
	_measure_the_leg()
	for side: float in [-1.0, 1.0]:
		_legs[side] = [_piece(_capsule(0.08), "trousers"), _piece(_capsule(0.06), "trousers")]
		var boot := BoxMesh.new()
		boot.size = BOOT_SIZE
		_legs[side].append(_piece(boot, "boots"))
	_follow()


func _process(_delta: float) -> void:
	if visible:
		_follow()


## Whether a leg is drawn down on `side` now (−1 left, 1 right).
func is_leg_down(side: float) -> bool:
	return (_legs[signf(side)][0] as Node3D).visible


func _follow() -> void:
	var feet := _simulation.get_feet()
	var frame := _simulation.get_body_transform(FRAME)
	var lean := _simulation.get_lean()
	for i in feet.size():
		var side := -1.0 if i == 0 else 1.0
		var foot: Dictionary = feet[i]
		var down: bool = foot.down and (foot.on_ground or lean * side > 0.0)
		for node: Node3D in _legs[side]:
			node.visible = down
		if _visual_bike != null:
			_visual_bike.show_leg_on_peg(side, not down)
		if down:
			var sole := frame * (foot.on_frame as Vector3)
			var right := frame.basis.z.normalized()
			var hip := _simulation.get_body_transform(UPPER_LEG) * _hip_on_thigh
			_pose_leg(_legs[side], hip + right * side * HIP_OUT, sole, frame.basis)


## Thigh, shin and boot from `hip` to the boot on `sole` (world), the knee bent towards
## the bike's front (`bike` is the frame's basis: x forward, y up, z right).
func _pose_leg(leg: Array, hip: Vector3, sole: Vector3, bike: Basis) -> void:
	var ankle := sole + bike.y.normalized() * (BOOT_SIZE.y + 0.02)
	var reach := ankle - hip
	var along := reach.normalized()
	var d := minf(reach.length(), _thigh + _shin - 1e-3)
	var a := (_thigh * _thigh - _shin * _shin + d * d) / (2.0 * d)
	var forward := bike.x.normalized()
	var bend := (forward - along * forward.dot(along)).normalized()
	var knee := hip + along * a + bend * sqrt(maxf(_thigh * _thigh - a * a, 0.0))
	_place_rod(leg[0], hip, knee)
	_place_rod(leg[1], knee, ankle)
	var boot := Basis(bike.z.normalized(), bike.y.normalized(), -bike.x.normalized())
	(leg[2] as Node3D).global_transform = Transform3D(
		boot, sole + bike.y.normalized() * BOOT_SIZE.y / 2.0 + forward * 0.05
	)


## The thigh's hip end (in its body's frame, the end higher up at rest) and the two
## segments' lengths, from the simulation's capsules.
func _measure_the_leg() -> void:
	for shape: Dictionary in _simulation.get_shapes():
		if shape.kind != "capsule" or not shape.body in [UPPER_LEG, LOWER_LEG]:
			continue
		var offset: Transform3D = shape.offset
		var half := offset.basis.z.normalized() * float(shape.length) / 2.0
		var length := 2.0 * half.length() + 2.0 * float(shape.radius)
		if shape.body == LOWER_LEG:
			_shin = length
			continue
		_thigh = length
		var body := _simulation.get_body_transform(UPPER_LEG)
		var a := offset.origin + half
		var b := offset.origin - half
		_hip_on_thigh = a if (body * a).y > (body * b).y else b


static func _capsule(radius: float) -> CapsuleMesh:
	var capsule := CapsuleMesh.new()
	capsule.radius = radius
	return capsule


func _piece(mesh: Mesh, look: String) -> MeshInstance3D:
	var node := MeshInstance3D.new()
	node.mesh = mesh
	node.material_override = BikeLooks.material(look)
	node.top_level = true
	node.visible = false
	add_child(node)
	return node


## Stretches a capsule node from `a` to `b` (world).
static func _place_rod(node: MeshInstance3D, a: Vector3, b: Vector3) -> void:
	var capsule := node.mesh as CapsuleMesh
	capsule.height = a.distance_to(b) + 2.0 * capsule.radius
	var y := (b - a).normalized()
	var x := y.cross(Vector3.FORWARD if absf(y.dot(Vector3.FORWARD)) < 0.9 else Vector3.UP)
	x = x.normalized()
	node.global_transform = Transform3D(Basis(x, y, x.cross(y)), (a + b) / 2.0)
