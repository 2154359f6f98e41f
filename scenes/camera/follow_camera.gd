class_name FollowCamera
extends Camera3D
## Follows the bike from behind and a little to the side (as the thesis's camera did, so
## both the rider and the road ahead stay in view), smoothly, never turning upside down.

## The BikeSimulation to follow.
@export var target_path: NodePath
## Metres behind, beside (to the right) and above the bike's centre of mass.
@export var offset := Vector3(2.6, 1.5, 4.2)
## How quickly the camera catches up (1/s); higher is stiffer.
@export var stiffness := 4.0

var _target: Node
var _heading := Vector3.FORWARD
var _placed := false


func _ready() -> void:
	_target = get_node_or_null(target_path)
	if _target == null:
		push_error("FollowCamera: no target at %s" % target_path)
		set_process(false)


func _process(delta: float) -> void:
	if not _target.call(&"is_running"):
		return
	var centre: Vector3 = _target.call(&"get_center_of_mass")
	var frame: Transform3D = _target.call(&"get_body_transform", 3)
	# The frame's forward (−z of the bike's node frame is +x of its body frame).
	var forward := frame.basis.x
	forward.y = 0.0
	if forward.length() > 0.1:
		# A normalised lerp, not slerp: Godot's slerp normalises a near-zero cross product
		# in single precision when the headings are almost equal, and then errors.
		var blended := _heading.lerp(forward.normalized(), clampf(stiffness * delta, 0.0, 1.0))
		if blended.length() > 1e-3:
			_heading = blended.normalized()
	var right := _heading.cross(Vector3.UP).normalized()
	var wanted := centre - _heading * offset.z + right * offset.x + Vector3.UP * offset.y
	var catch_up := clampf(stiffness * delta, 0.0, 1.0) if _placed else 1.0
	global_position = global_position.lerp(wanted, catch_up)
	_placed = true
	look_at(centre + _heading * 2.0, Vector3.UP)
