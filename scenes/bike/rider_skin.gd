class_name RiderSkin
extends RefCounted
## What the rider wears, skinned onto RiderFigure's skeleton as RiderMesh tubes: road
## leathers (a one-piece suit, its jacket in the bike's colours, short race boots) or a
## motocross kit (a loose jersey in the bike's colours, light pants, knee-high boots).

## The kits a bike's bodywork can name (BikeBodywork.gear).
const ROAD := "road"
const MOTOCROSS := "motocross"
## Motocross pants: light, as the kits are, so the jersey's colour reads against them.
const MOTOCROSS_PANTS := Color(0.88, 0.88, 0.86)
## How much looser a jersey is than a leather jacket.
const JERSEY_LOOSE := 1.12

var _mesh: RiderMesh
var _skeleton: Skeleton3D
var _gear: String


func _init(mesh: RiderMesh, skeleton: Skeleton3D, gear: String, jacket: Color) -> void:
	_mesh = mesh
	_skeleton = skeleton
	_gear = gear
	_mesh.colours = {jacket = jacket}
	if gear == MOTOCROSS:
		_mesh.colours.trousers = MOTOCROSS_PANTS


## The legs and arms on side `s` ("_L" or "_R"; each a tube bending at the knee or elbow),
## boots and gloves; `at` holds the joints (bike frame) and `local` takes a bike-frame
## point to skeleton space.
func limbs(s: String, local: Callable, at: Dictionary) -> void:
	var side := Vector3.RIGHT
	var bone := func(bone_name: String) -> int: return _skeleton.find_bone(bone_name + s)
	var loose := JERSEY_LOOSE if _gear == MOTOCROSS else 1.0
	_mesh.add_tube(
		"trousers",
		PackedVector3Array([local.call(at.hip), local.call(at.knee), local.call(at.ankle)]),
		PackedFloat32Array([0.085 * loose, 0.066 * loose, 0.055]),
		PackedInt32Array([bone.call("thigh"), bone.call("shin")]),
		side
	)
	var ankle: Vector3 = at.ankle
	_mesh.add_tube(
		"boots",
		PackedVector3Array(
			[
				local.call(ankle + Vector3(-0.07, -0.05, 0)),
				local.call(ankle + Vector3(0.17, -0.07, 0))
			]
		),
		PackedFloat32Array([0.055, 0.045]),
		PackedInt32Array([bone.call("foot")]),
		side
	)
	if _gear == MOTOCROSS:
		# A motocross boot's shaft, up to just below the knee, over the pants.
		var knee: Vector3 = at.knee
		_mesh.add_tube(
			"boots",
			PackedVector3Array([local.call(knee.lerp(ankle, 0.25)), local.call(ankle)]),
			PackedFloat32Array([0.072, 0.064]),
			PackedInt32Array([bone.call("shin")]),
			side
		)
	var hand: Vector3 = local.call(at.hand)
	var elbow: Vector3 = local.call(at.elbow)
	var reach := (hand - elbow).normalized()
	_mesh.add_tube(
		"jacket",
		PackedVector3Array([local.call(at.shoulder), elbow, hand - reach * 0.06]),
		PackedFloat32Array([0.065 * loose, 0.052 * loose, 0.042 * loose]),
		PackedInt32Array([bone.call("upper_arm"), bone.call("forearm")]),
		side
	)
	_mesh.add_tube(
		"gloves",
		PackedVector3Array([hand - reach * 0.07, hand + reach * 0.03]),
		PackedFloat32Array([0.045, 0.045]),
		PackedInt32Array([bone.call("hand")]),
		side
	)


## The torso, wider than deep, from below the hips to the base of the neck: `joints` are
## its points (skeleton space) at the hips, spine, chest and neck bones.
func torso(joints: PackedVector3Array) -> void:
	var loose := JERSEY_LOOSE if _gear == MOTOCROSS else 1.0
	var bones := PackedInt32Array()
	for bone: String in ["hips", "spine", "chest"]:
		bones.append(_skeleton.find_bone(bone))
	_mesh.add_tube(
		"jacket",
		joints,
		PackedFloat32Array([0.14 * loose, 0.15 * loose, 0.17 * loose, 0.06]),
		bones,
		Vector3.RIGHT,
		1.25
	)
