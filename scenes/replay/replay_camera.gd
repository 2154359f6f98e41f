class_name ReplayCamera
extends Camera3D
## The replay's camera, in three modes cycled by the camera button: **follow** (behind
## the bike, as the chase camera), **orbit** (circling the bike, turned by the d-pad or a
## right-mouse drag, drifting slowly round when let go) and **free** (flown with the right
## stick or I J K L, looking with the d-pad, wherever the player likes).

const MODES: Array[String] = ["follow", "orbit", "free"]
## Follow: metres behind, beside and above; orbit: distance and height.
const FOLLOW_OFFSET := Vector3(2.0, 1.4, 4.0)
const ORBIT_DISTANCE := 4.5
const ORBIT_HEIGHT := 1.2
## Turn rate of the d-pad and of an idle orbit (rad/s); free flight speed (m/s).
const TURN_SPEED := 1.8
const DRIFT_SPEED := 0.25
const FLY_SPEED := 6.0
const MOUSE_TURN := 0.006

var mode := "follow"
var _orbit_yaw := 0.0
var _look := Vector2.ZERO
var _placed := false


## Cycles to the next mode; returns its name.
func cycle_mode() -> String:
	mode = MODES[(MODES.find(mode) + 1) % MODES.size()]
	if mode == "free":
		_look = Vector2(global_rotation.y, global_rotation.x)
	return mode


## Frames the bike whose frame body is at `frame`, `delta` seconds of real time after the
## last call (the replay may be paused or slowed: the camera still moves smoothly).
func frame_bike(frame: Transform3D, delta: float) -> void:
	var centre := frame.origin + Vector3.UP * 0.3
	var forward := frame.basis.x
	forward.y = 0.0
	forward = forward.normalized() if forward.length() > 0.1 else Vector3.FORWARD
	var stick := Input.get_vector(&"camera_left", &"camera_right", &"camera_down", &"camera_up")
	match mode:
		"follow":
			var right := forward.cross(Vector3.UP)
			var wanted := centre - forward * FOLLOW_OFFSET.z + right * FOLLOW_OFFSET.x
			_move_to(wanted + Vector3.UP * FOLLOW_OFFSET.y, delta)
			look_at(centre + forward * 1.5, Vector3.UP)
		"orbit":
			_orbit_yaw += (-stick.x * TURN_SPEED if stick.x != 0.0 else DRIFT_SPEED) * delta
			var around := Vector3(sin(_orbit_yaw), 0.0, cos(_orbit_yaw)) * ORBIT_DISTANCE
			_move_to(centre + around + Vector3.UP * ORBIT_HEIGHT, delta)
			look_at(centre, Vector3.UP)
		"free":
			_look.x -= stick.x * TURN_SPEED * delta
			_look.y = clampf(_look.y + stick.y * TURN_SPEED * delta, -1.4, 1.4)
			global_rotation = Vector3(_look.y, _look.x, 0.0)
			var fly := Input.get_vector(
				&"rider_left", &"rider_right", &"rider_forward", &"rider_back"
			)
			global_position += global_basis * Vector3(fly.x, 0.0, fly.y) * FLY_SPEED * delta


func _unhandled_input(event: InputEvent) -> void:
	var motion := event as InputEventMouseMotion
	if motion == null or not motion.button_mask & MOUSE_BUTTON_MASK_RIGHT:
		return
	if mode == "orbit":
		_orbit_yaw -= motion.relative.x * MOUSE_TURN
	elif mode == "free":
		_look -= motion.relative * MOUSE_TURN


func _move_to(wanted: Vector3, delta: float) -> void:
	var catch_up := clampf(5.0 * delta, 0.0, 1.0) if _placed else 1.0
	global_position = global_position.lerp(wanted, catch_up)
	_placed = true
