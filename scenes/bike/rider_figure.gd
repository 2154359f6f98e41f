class_name RiderFigure
extends Node3D
## The rider as the player sees them: a Skeleton3D wearing a skin generated in code
## (RiderMesh), posed every frame to the simulated bodies as the thesis posed its humanoid
## with Unity's IK (§4.2). The skeleton rides on the simulated torso; Godot's TwoBoneIK3D
## puts each hand on its simulated hand, each foot on its simulated foot (or on the road
## when the rider puts that foot down), bending elbows and knees towards the simulated ones;
## a LookAtModifier3D turns the head to where the front wheel points. The simulation has
## one arm and one leg in the mid-plane; each is drawn twice, moved out to either side, so
## the hands reach the grips and the knees hug the tank.

const LOWER_LEG := BikeSimulation.LOWER_LEG
const UPPER_LEG := BikeSimulation.UPPER_LEG
const TORSO := BikeSimulation.TORSO
const UPPER_ARM := BikeSimulation.UPPER_ARM
const LOWER_ARM := BikeSimulation.LOWER_ARM
const FORK := BikeSimulation.FORK
const BIKE_FORWARD := BikeRestFrame.FORWARD
const BIKE_DOWN := BikeRestFrame.DOWN
const SIDES: Array[float] = [-1.0, 1.0]
## How far out from the mid-plane (m) each joint of the doubled limbs is drawn.
const OUT := {hip = 0.13, knee = 0.19, ankle = 0.2, shoulder = 0.19, elbow = 0.27, hand = 0.35}
## Where along the torso (from the hips, as a share of hip to head) the spine's joints are.
const SPINE := {spine = 0.25, chest = 0.45, neck = 0.53, head = 0.66}
## The simulated hand holds the bar while it is this close (m) to the bar's grip point:
## then the drawn hands hold the drawn grips, which turn with the bar.
const HOLDING := 0.05
## The boot's sole below the ankle (m): a foot put down stands this far above the road.
const ANKLE_HEIGHT := 0.12
## Render layer of the neck, helmet and visor alone, so a camera at the rider's eyes can
## leave them out (layer 20, the last one the editor names).
const HEAD_LAYER := 1 << 19
## How far ahead of the head (m) the rider looks, along the front wheel, and how far down.
const LOOK_AHEAD := 6.0
const LOOK_DOWN := 1.2
## The drawn stance (RiderStance) at its fullest: standing lifts the hips off the seat and
## moves them forward over the pegs (m), the back bent forward over the bar (radians);
## tucking bends the back down behind the clocks, the eyes still up the road; hanging off
## moves the hips to the inside of the seat, rolls the back in, puts the inside knee out and
## turns the head to look through the bend.
const STAND_RISE := 0.24
const STAND_FORWARD := 0.1
const STAND_BEND := deg_to_rad(20.0)
const TUCK_BEND := deg_to_rad(36.0)
const TUCK_LOOK_DOWN := 0.3
const HANG_SHIFT := 0.08
const HANG_ROLL := deg_to_rad(14.0)
const KNEE_OUT := 0.22
const LOOK_INTO_BEND := 3.0

## The stance of a rider drawn as simulated (every part at rest), shared, so posing
## without a stance makes nothing each frame.
static var _seated := RiderStance.new()

## Drawn see-through (a ghost).
var ghost := false
## The bike's paint, which the helmet's stripe and spoiler wear and the jacket is dyed
## after, so a rider reads as the bike's at a glance (set before `build`).
var paint := Color.WHITE
## The kit the rider wears (RiderSkin.ROAD or MOTOCROSS; set before `build`).
var gear := RiderSkin.ROAD

var _skeleton: Skeleton3D
var _ik: TwoBoneIK3D
## The skeleton's transform in the torso body's frame.
var _skeleton_on_torso := Transform3D.IDENTITY
## Per limb ("arm_L", "leg_R", …): its root bone, where its end (hand or ankle) and middle
## joint (elbow or knee) are on the simulated bodies, and the markers the IK reaches for
## (see `_limb`); an arm also keeps its grip on the bar.
var _limbs := {}
## The front wheel's forward in the fork body's frame, and the point of the bar (in the same
## frame) that the simulated hand holds.
var _fork_forward := Vector3.FORWARD
var _mid_grip := Vector3.ZERO
var _look_target: Node3D
## The sides whose foot was drawn down at the last pose.
var _feet_down: Array[float] = []
## Every bone's pose (skeleton space) as the modifiers last left it: Skeleton3D puts the
## unmodified poses back after each update, so they are kept when it says it was updated.
var _posed: Array[Transform3D] = []


## Builds the skeleton, its skin and its IK from the bike at rest (`frame`).
func build(frame: BikeRestFrame) -> void:
	var hip_head := frame.capsule_ends(TORSO, BIKE_DOWN)
	var hip: Vector3 = hip_head[0]
	var along: Vector3 = (hip_head[1] - hip).normalized()
	var rest := Transform3D(frame.basis(), frame.world_of(hip))
	_skeleton_on_torso = frame.on_body(TORSO, rest)
	# Skeleton space: the rest pose's Godot axes, from the hips.
	var local := func(bike_point: Vector3) -> Vector3:
		return rest.affine_inverse() * frame.world_of(bike_point)
	_skeleton = Skeleton3D.new()
	_skeleton.name = "Skeleton"
	_skeleton.top_level = true
	_skeleton.modifier_callback_mode_process = Skeleton3D.MODIFIER_CALLBACK_MODE_PROCESS_MANUAL
	add_child(_skeleton)
	_bone("hips", "", Vector3.ZERO)
	var parent := "hips"
	for joint: String in SPINE:
		_bone(joint, parent, local.call(hip + along * float(SPINE[joint])))
		parent = joint
	var leg := frame.capsule_ends(UPPER_LEG, BIKE_FORWARD)
	var shin := frame.capsule_ends(LOWER_LEG, BIKE_DOWN)
	var arm := frame.capsule_ends(UPPER_ARM, -BIKE_DOWN)
	var forearm := frame.capsule_ends(LOWER_ARM, -BIKE_FORWARD)
	var joints := {
		hip = hip,
		knee = leg[0],
		ankle = shin[0],
		shoulder = arm[0],
		elbow = arm[1],
		hand = forearm[1]
	}
	var mesh := RiderMesh.new()
	var skin := RiderSkin.new(mesh, _skeleton, gear, jacket_colour(paint))
	for side in SIDES:
		var at := {}
		for joint: String in joints:
			at[joint] = (joints[joint] as Vector3) + Vector3(0, 0, side * float(OUT[joint]))
		var s := _suffix(side)
		_bone("thigh" + s, "hips", local.call(at.hip))
		_bone("shin" + s, "thigh" + s, local.call(at.knee))
		_bone("foot" + s, "shin" + s, local.call(at.ankle))
		_bone("upper_arm" + s, "chest", local.call(at.shoulder))
		_bone("forearm" + s, "upper_arm" + s, local.call(at.elbow))
		_bone("hand" + s, "forearm" + s, local.call(at.hand))
		var leg_ends := [LOWER_LEG, joints.ankle, OUT.ankle, UPPER_LEG, joints.knee, OUT.knee]
		_limbs["leg" + s] = _limb(frame, "thigh" + s, side, leg_ends)
		var arm_ends := [LOWER_ARM, joints.hand, OUT.hand, UPPER_ARM, joints.elbow, OUT.elbow]
		_limbs["arm" + s] = _limb(frame, "upper_arm" + s, side, arm_ends)
		# The grip on the bar, which the hand holds while the simulated hand holds the bar.
		_limbs["arm" + s].grip = frame.rest_of(FORK).affine_inverse() * frame.world_of(at.hand)
		skin.limbs(s, local, at)
	var torso := PackedVector3Array([local.call(hip - along * 0.03)])
	for joint: String in ["spine", "chest", "neck"]:
		torso.append(local.call(hip + along * float(SPINE[joint])))
	skin.torso(torso)
	_dress(mesh)
	_set_up_ik()
	_fork_forward = frame.rest_of(FORK).basis.inverse() * -frame.basis().z
	_mid_grip = frame.rest_of(FORK).affine_inverse() * frame.world_of(joints.hand)
	_look_target = _marker("look_target")
	_set_up_head(local.call(hip + along * float(SPINE.head)))
	_skeleton.skeleton_updated.connect(_keep_the_pose)
	_keep_the_pose()


## Puts the rider on `bodies` (global transforms, in body order), holding `stance` over
## them (none: as simulated); `feet_down` lists the soles (world) of the feet put down on
## the road, as {side, sole, up}.
func pose(
	bodies: Array[Transform3D], feet_down: Array[Dictionary], stance: RiderStance = null
) -> void:
	var held := stance if stance != null else _seated
	var seated := bodies[TORSO] * _skeleton_on_torso
	var up := seated.basis.y.normalized()
	seated.origin += (
		up * STAND_RISE * held.stand
		- seated.basis.z.normalized() * STAND_FORWARD * held.stand
		+ seated.basis.x.normalized() * HANG_SHIFT * held.hang
	)
	_skeleton.global_transform = seated
	_bend_back(held)
	_feet_down.clear()
	for foot: Dictionary in feet_down:
		_feet_down.append(foot.side)
	# The limbs drawn either side go out along the torso's right from the simulated ones.
	var right := _skeleton.global_basis.x.normalized()
	var forward := bodies[FORK].basis * _fork_forward
	var simulated_hand: Vector3 = bodies[LOWER_ARM] * (_limbs.arm_L.end_mid as Vector3)
	var holding := simulated_hand.distance_to(bodies[FORK] * _mid_grip)
	for key: String in _limbs:
		var limb: Dictionary = _limbs[key]
		var end: Vector3 = bodies[limb.end_body] * (limb.end_mid as Vector3) + right * limb.end_out
		var middle: Vector3 = (
			bodies[limb.middle_body] * (limb.middle_mid as Vector3) + right * limb.middle_out
		)
		var root := _skeleton.global_transform * limb.root_rest as Vector3
		if limb.has("grip") and holding < HOLDING:
			end = bodies[FORK] * (limb.grip as Vector3)
		if key == "leg" + _suffix(held.hang) and held.hang != 0.0:
			# The inside knee out towards the road, the foot still on its peg.
			middle += right * KNEE_OUT * held.hang - up * KNEE_OUT * 0.3 * absf(held.hang)
		for foot: Dictionary in feet_down:
			if key == "leg" + _suffix(foot.side):
				end = (foot.sole as Vector3) + (foot.up as Vector3) * ANKLE_HEIGHT
				# The knee bends forward over the foot put down.
				middle = (root + end) / 2.0 + forward * 0.4
		(limb.target as Node3D).global_position = end
		# The pole beyond the middle joint, away from the line through root and end, so the
		# plane it makes with them stays defined when the limb is nearly straight.
		var bend := middle - (root + end) / 2.0
		(limb.pole as Node3D).global_position = middle + bend.normalized() * 0.3
	var head := _skeleton.global_transform * _skeleton.get_bone_global_rest(_bone_index("head"))
	var look_down := lerpf(LOOK_DOWN, TUCK_LOOK_DOWN, held.tuck)
	_look_target.global_position = (
		head.origin
		+ forward * LOOK_AHEAD
		- bodies[TORSO].basis.y.normalized() * look_down
		+ right * LOOK_INTO_BEND * held.hang
	)
	_skeleton.advance(0.0)


## Bends the back for `stance`, half at the spine and half at the chest: forward (about
## the skeleton's right; its forward is −z) to tuck or stand, and in to the bend (about
## its forward).
func _bend_back(stance: RiderStance) -> void:
	var forward_bend := TUCK_BEND * stance.tuck + STAND_BEND * stance.stand
	var roll := HANG_ROLL * stance.hang
	var half := (
		Quaternion(Vector3.RIGHT, -forward_bend / 2.0) * Quaternion(Vector3.BACK, -roll / 2.0)
	)
	for bone: String in ["spine", "chest"]:
		_skeleton.set_bone_pose_rotation(_bone_index(bone), half)


## Where the rider's eyes are now (global), inside the helmet.
func eye_point() -> Vector3:
	var head := bone_transform("head")
	# The head's axes are Godot's: −z is the rider's forward.
	return head.origin - head.basis.z.normalized() * 0.08 + head.basis.y.normalized() * 0.02


## Whether the leg on `side` (−1 left, 1 right) was drawn down to the road at the last pose.
func is_leg_down(side: float) -> bool:
	return signf(side) in _feet_down


## Where a bone of the drawn rider is now (global), e.g. "hand_L", "foot_R", "head".
func bone_transform(bone: String) -> Transform3D:
	return _skeleton.global_transform * _posed[_bone_index(bone)]


func _keep_the_pose() -> void:
	_posed.resize(_skeleton.get_bone_count())
	for bone in _posed.size():
		_posed[bone] = _skeleton.get_bone_global_pose(bone)


## The skeleton, for tests and tools that look at its bones.
func skeleton() -> Skeleton3D:
	return _skeleton


static func _suffix(side: float) -> String:
	return "_L" if side < 0.0 else "_R"


func _bone_index(bone: String) -> int:
	return _skeleton.find_bone(bone)


## Adds a bone whose head is at `at` (skeleton space) to the skeleton.
func _bone(bone: String, parent: String, at: Vector3) -> void:
	var index := _skeleton.add_bone(bone)
	var parent_at := Vector3.ZERO
	if not parent.is_empty():
		var parent_index := _bone_index(parent)
		_skeleton.set_bone_parent(index, parent_index)
		parent_at = _skeleton.get_bone_global_rest(parent_index).origin
	_skeleton.set_bone_rest(index, Transform3D(Basis.IDENTITY, at - parent_at))
	_skeleton.reset_bone_pose(index)


## A limb's IK inputs: its root bone, and where its end and middle joints are: on which
## body, where on it in the mid-plane, and how far out to `side` ([end body, end, end's
## way out, middle body, middle, middle's way out]; points in the bike frame at rest).
func _limb(frame: BikeRestFrame, root: String, side: float, ends: Array) -> Dictionary:
	return {
		root = root,
		root_rest = _skeleton.get_bone_global_rest(_bone_index(root)).origin,
		end_body = ends[0],
		end_mid = frame.rest_of(ends[0]).affine_inverse() * frame.world_of(ends[1]),
		end_out = side * float(ends[2]),
		middle_body = ends[3],
		middle_mid = frame.rest_of(ends[3]).affine_inverse() * frame.world_of(ends[4]),
		middle_out = side * float(ends[5]),
		target = _marker(root + "_target"),
		pole = _marker(root + "_pole"),
	}


func _marker(marker_name: String) -> Node3D:
	var marker := Node3D.new()
	marker.name = marker_name
	marker.top_level = true
	add_child(marker)
	return marker


## One TwoBoneIK3D with a setting per limb: root, middle and end bone, target and pole.
func _set_up_ik() -> void:
	_ik = TwoBoneIK3D.new()
	_ik.name = "LimbIK"
	_skeleton.add_child(_ik)
	_ik.setting_count = _limbs.size()
	var index := 0
	for key: String in _limbs:
		var limb: Dictionary = _limbs[key]
		var bones: Array[String] = []
		var bone: int = _bone_index(limb.root)
		for i in 3:
			bones.append(_skeleton.get_bone_name(bone))
			bone = _skeleton.get_bone_children(bone)[0] if i < 2 else bone
		_ik.set_root_bone_name(index, bones[0])
		_ik.set_middle_bone_name(index, bones[1])
		_ik.set_end_bone_name(index, bones[2])
		_ik.set_target_node(index, _ik.get_path_to(limb.target))
		_ik.set_pole_node(index, _ik.get_path_to(limb.pole))
		index += 1


## The jacket of a rider of a bike painted `bike_paint`: the paint as a textile wears it,
## a shade darker and less saturated than the bike's gloss.
static func jacket_colour(bike_paint: Color) -> Color:
	var dyed := bike_paint.darkened(0.15)
	dyed.s *= 0.9
	return dyed


## The skin, bound to the skeleton (its skin made from the rest pose).
func _dress(mesh: RiderMesh) -> void:
	var body := MeshInstance3D.new()
	body.name = "Body"
	body.mesh = mesh.build(BikeLooks.skin_material(ghost))
	if ghost:
		body.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	_skeleton.add_child(body)
	body.skeleton = body.get_path_to(_skeleton)


## Neck and helmet (RiderHelmet) ride on the head bone; the head looks where the front
## wheel points.
func _set_up_head(head: Vector3) -> void:
	var attachment := BoneAttachment3D.new()
	attachment.name = "Head"
	_skeleton.add_child(attachment)
	attachment.bone_name = "head"
	for piece: Array in RiderHelmet.pieces(gear):
		_head_piece(attachment, piece[0], piece[1], piece[2])
	var neck_at := _skeleton.get_bone_global_rest(_bone_index("neck")).origin - head
	var neck := CapsuleMesh.new()
	neck.radius = 0.06
	neck.height = neck_at.length() + 0.12
	var neck_basis := Basis(Quaternion(Vector3.UP, -neck_at.normalized()))
	_head_piece(attachment, neck, "trousers", Transform3D(neck_basis, neck_at / 2.0))
	var look := LookAtModifier3D.new()
	look.name = "HeadLook"
	_skeleton.add_child(look)
	look.bone_name = "head"
	look.forward_axis = SkeletonModifier3D.BONE_AXIS_MINUS_Z
	look.primary_rotation_axis = Vector3.AXIS_Y
	look.use_secondary_rotation = true
	look.use_angle_limitation = true
	look.symmetry_limitation = true
	look.primary_limit_angle = deg_to_rad(110.0)
	look.secondary_limit_angle = deg_to_rad(60.0)
	look.target_node = look.get_path_to(_look_target)


func _head_piece(attachment: Node3D, mesh: Mesh, look: String, at: Transform3D) -> void:
	var piece := MeshInstance3D.new()
	piece.mesh = mesh
	BikeLooks.dress(piece, look, paint if look == "paint" else Color(0, 0, 0, 0), ghost)
	piece.transform = at
	piece.layers = HEAD_LAYER
	attachment.add_child(piece)
