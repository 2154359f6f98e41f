class_name FollowCamera
extends Camera3D
## Follows the bike in one of three modes (`mode`, cycled by the camera button):
## **chase** from behind and a little to the side (the thesis's camera, §6.2, so both rider
## and road stay in view), **low side** from beside the bike near the ground, as a
## trackside camera, and **helmet** from the rider's eyes. Smoothly, never upside down.
## The d-pad (or numpad 8/4/6/2, or dragging with the right mouse button) orbits around
## the bike, or turns the rider's head in the helmet view; the view drifts back when let
## go. The camera never goes through the level's geometry: it moves in front of whatever
## is between it and the bike.

## The modes, in the order the camera button cycles them; saved in the settings by name.
const MODES: Array[String] = ["chase", "low_side", "helmet"]
const MODE_LABELS := {chase = "Chase", low_side = "Low side", helmet = "Helmet"}
## Metres behind, beside (to the right) and above the bike's centre of mass, per mode
## that looks at the bike from outside.
const OFFSETS := {chase = Vector3(2.6, 1.5, 4.2), low_side = Vector3(3.4, -0.25, 1.4)}
## Share of the bike's lean the helmet view rolls with: riders keep their eyes nearer
## level than the bike.
const HELMET_ROLL := 0.5
## How far the helmet view looks down (rad), so the bars and the road ahead are in view.
const HELMET_PITCH := 0.25

## Lowest and highest pitch of the orbit (rad) relative to the default view.
const PITCH_LIMITS := Vector2(-0.25, 1.0)
## Distance kept from geometry between the camera and the bike (m).
const CLEARANCE := 0.3

## How the camera follows the bike: one of MODES.
@export_enum("chase", "low_side", "helmet") var mode := "chase":
	set(value):
		if not MODES.has(value):
			push_error("FollowCamera: no camera mode is called '%s'" % value)
			return
		mode = value
		_placed = false
		# From the rider's eyes the helmet is left out of the picture.
		if mode == "helmet":
			cull_mask &= ~RiderFigure.HEAD_LAYER
		else:
			cull_mask |= RiderFigure.HEAD_LAYER
## How quickly the camera catches up (1/s); higher is stiffer.
@export var stiffness := 4.0
## Orbit speed with the d-pad held (rad/s).
@export var orbit_speed := 2.2
## Seconds after the d-pad is let go before the view drifts back behind the bike.
@export var recentre_delay := 2.0
## Mouse orbit (rad per pixel while the right button is held).
@export var mouse_sensitivity := 0.006

## The bike to follow.
var target: BikeSimulation
## The camera setting (the game sets it by name): the mode.
var camera: String:
	get:
		return mode
	set(value):
		mode = value
## Orbit around the bike: yaw (rad, positive to the left) and pitch (rad, positive up).
var orbit := Vector2.ZERO

var _heading := Vector3.FORWARD
var _placed := false
var _idle := 0.0


func _process(delta: float) -> void:
	if target == null or not target.is_running():
		return
	_orbit_from_buttons(delta)
	if mode == "helmet":
		_look_from_helmet(delta)
		return
	var centre := target.get_center_of_mass()
	var frame := target.get_body_transform(BikeSimulation.FRAME)
	# The frame's forward (−z of the bike's node frame is +x of its body frame).
	var forward := frame.basis.x
	forward.y = 0.0
	if forward.length() > 0.1:
		# Turned about the vertical by a share of the angle between them: it comes round
		# from any heading, a reversed one too (a spawn point facing back along the lap),
		# which a blend of the two directions never leaves.
		var angle := _heading.signed_angle_to(forward.normalized(), Vector3.UP)
		var turned := _heading.rotated(Vector3.UP, angle * clampf(stiffness * delta, 0.0, 1.0))
		if is_finite(turned.length()) and turned.length() > 1e-3:
			_heading = turned.normalized()
	var wanted := centre + _offset_around(_heading, OFFSETS[mode])
	var catch_up := clampf(stiffness * delta, 0.0, 1.0) if _placed else 1.0
	global_position = _unblocked(centre, global_position.lerp(wanted, catch_up))
	_placed = true
	# The chase view looks ahead of the bike; the low one at the bike, which fills it.
	var ahead := 2.0 if mode == "chase" else 0.6
	look_at(centre + _heading * ahead * cos(orbit.x), Vector3.UP)


## Cycles to the next mode (`step` 1) or the previous (−1); returns its name.
func cycle_mode(step := 1) -> String:
	mode = MODES[posmod(MODES.find(mode) + step, MODES.size())]
	return mode


## From the rider's eyes (the drawn helmet's visor), looking along the bike's heading and
## rolling with part of its lean; the orbit turns the head.
func _look_from_helmet(delta: float) -> void:
	var frame := target.get_body_transform(BikeSimulation.FRAME)
	var forward := frame.basis.x.normalized()
	var up := Vector3.UP.lerp(frame.basis.y.normalized(), HELMET_ROLL).normalized()
	var right := forward.cross(up).normalized()
	var looking := Basis(right, right.cross(forward), -forward)
	looking = looking.rotated(up, orbit.x) if orbit.x != 0.0 else looking
	looking = looking * Basis(Vector3.RIGHT, orbit.y * 0.5 - HELMET_PITCH)
	var eye := _eye_point()
	var catch_up := clampf(4.0 * stiffness * delta, 0.0, 1.0) if _placed else 1.0
	global_basis = global_basis.slerp(looking.orthonormalized(), catch_up).orthonormalized()
	global_position = eye
	_placed = true


## Where the rider's eyes are: the drawn helmet's visor, or above the torso when the
## drawn bike is not there.
func _eye_point() -> Vector3:
	var drawn := target.get_node_or_null(^"VisualBikeView") as VisualBikeView
	if drawn != null and drawn.is_node_ready():
		return drawn.eye_point()
	var torso := target.get_body_transform(BikeSimulation.TORSO)
	return torso.origin + Vector3.UP * 0.6


func _unhandled_input(event: InputEvent) -> void:
	var motion := event as InputEventMouseMotion
	if motion != null and motion.button_mask & MOUSE_BUTTON_MASK_RIGHT:
		orbit.x -= motion.relative.x * mouse_sensitivity
		orbit.y += motion.relative.y * mouse_sensitivity
		orbit.y = clampf(orbit.y, PITCH_LIMITS.x, PITCH_LIMITS.y)
		_idle = 0.0


func _orbit_from_buttons(delta: float) -> void:
	var stick := Input.get_vector(&"camera_left", &"camera_right", &"camera_down", &"camera_up")
	if stick.length() > 0.0:
		orbit.x -= stick.x * orbit_speed * delta
		orbit.y = clampf(orbit.y + stick.y * orbit_speed * delta, PITCH_LIMITS.x, PITCH_LIMITS.y)
		_idle = 0.0
		return
	_idle += delta
	if _idle > recentre_delay:
		orbit.x = wrapf(orbit.x, -PI, PI)
		orbit = orbit.lerp(Vector2.ZERO, clampf(1.5 * delta, 0.0, 1.0))


## The camera's offset from the bike for a heading, turned by the orbit.
func _offset_around(heading: Vector3, offset: Vector3) -> Vector3:
	var right := heading.cross(Vector3.UP).normalized()
	var behind := -heading * offset.z + right * offset.x
	var pitched := behind.length() * cos(orbit.y)
	var height := offset.y + behind.length() * sin(orbit.y)
	return (behind.normalized() * pitched).rotated(Vector3.UP, orbit.x) + Vector3.UP * height


## `wanted`, or the point just in front of the first thing between it and `centre`.
func _unblocked(centre: Vector3, wanted: Vector3) -> Vector3:
	var query := PhysicsRayQueryParameters3D.create(centre, wanted)
	var hit := get_world_3d().direct_space_state.intersect_ray(query)
	if hit.is_empty():
		return wanted
	var to_camera := wanted - centre
	var reach := maxf((hit.position as Vector3).distance_to(centre) - CLEARANCE, 0.5)
	return centre + to_camera.normalized() * minf(reach, to_camera.length())
