class_name FollowCamera
extends Camera3D
## Follows the bike from behind and a little to the side (the thesis's camera, §6.2, so
## both rider and road stay in view), smoothly and never upside down. The d-pad (or
## numpad 8/4/6/2, or dragging with the right mouse button) orbits around the bike; the
## view drifts back behind it when let go. The camera never goes through the level's
## geometry: it moves in front of whatever is between it and the bike.

## Lowest and highest pitch of the orbit (rad) relative to the default view.
const PITCH_LIMITS := Vector2(-0.25, 1.0)
## Distance kept from geometry between the camera and the bike (m).
const CLEARANCE := 0.3

## Metres behind, beside (to the right) and above the bike's centre of mass.
@export var offset := Vector3(2.6, 1.5, 4.2)
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
## Orbit around the bike: yaw (rad, positive to the left) and pitch (rad, positive up).
var orbit := Vector2.ZERO

var _heading := Vector3.FORWARD
var _placed := false
var _idle := 0.0


func _process(delta: float) -> void:
	if target == null or not target.is_running():
		return
	_orbit_from_buttons(delta)
	var centre := target.get_center_of_mass()
	var frame := target.get_body_transform(BikeSimulation.FRAME)
	# The frame's forward (−z of the bike's node frame is +x of its body frame).
	var forward := frame.basis.x
	forward.y = 0.0
	if forward.length() > 0.1:
		# A normalised lerp, not slerp: Godot's slerp normalises a near-zero cross product
		# in single precision when the headings are almost equal, and then errors.
		var blended := _heading.lerp(forward.normalized(), clampf(stiffness * delta, 0.0, 1.0))
		if blended.length() > 1e-3:
			_heading = blended.normalized()
	var wanted := centre + _offset_around(_heading)
	var catch_up := clampf(stiffness * delta, 0.0, 1.0) if _placed else 1.0
	global_position = _unblocked(centre, global_position.lerp(wanted, catch_up))
	_placed = true
	look_at(centre + _heading * 2.0 * cos(orbit.x), Vector3.UP)


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
func _offset_around(heading: Vector3) -> Vector3:
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
