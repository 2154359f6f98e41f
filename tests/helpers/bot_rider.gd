class_name BotRider
extends Node
## A scripted rider for headless rides through the player's own input: every physics tick
## it presses the throttle, brake and turn actions (with analog strengths, as a gamepad
## would) to follow a Path3D at a chosen speed: it asks for the path's curvature a little
## ahead and corrects its heading and sideways errors. Told to wheelie, it pulls the rider
## stick back and opens the throttle wide. It never touches the bike's state. With
## `through_pad` its hands are a gamepad's: every press is a pad axis event (PadHands).

## Curvature asked per radian of heading error (1/m) and per metre of sideways error
## (1/m²): errors fade over a second or two at riding speeds. With `steady_at_speed`,
## faster than about 25 km/h the gains shrink with the speed (HEADING_RATE / v, SIDE_RATE /
## v²), so errors fade in the same time as at 25 km/h: at 60 km/h the fixed gains asked
## for lean that swung the bike from side to side.
const HEADING_GAIN := 0.25
const SIDE_GAIN := 0.04
const HEADING_RATE := 1.75
const SIDE_RATE := 1.95
const TURN_ACTIONS: Array[StringName] = [&"steer_left", &"steer_right"]
const DRIVE_ACTIONS: Array[StringName] = [&"brake", &"throttle"]
## Trigger per m/s of speed error: the throttle's, and the brake's (the whole brake answers
## the trigger, where the motor share scales the throttle: 0.6 × 0.6 brakes as hard for an
## error as the bot did when the share scaled the brake too).
const THROTTLE_GAIN := 0.6
const BRAKE_GAIN := 0.36
const RIDER_ACTIONS: Array[StringName] = [&"rider_back", &"rider_forward"]
## In the air with `level_in_air`: the rider stick per degree of pitch and per degree a
## second of pitching (the bike leaves a kicker's lip pitching nose down, so the weight
## goes back at once, not only once the nose is down).
const AIR_PITCH_GAIN := 0.1
const AIR_PITCH_RATE_GAIN := 0.05

## The bike to ride and the path to follow.
var bike: BikeSimulation
var path: Path3D
## Speed to hold (km/h); a Callable(offset_m) -> km/h may vary it along the path.
var speed_kmh := 25.0
var speed_along: Callable
## How far ahead (s of riding) the path's curvature is read to turn into bends in time.
var preview := 0.5
## While true: the rider's weight back and the throttle wide open, a wheelie.
var wheelie := false
## In the air (both wheels off the ground) the rider's weight levels the bike: forward
## while the nose is up, back while it is down; to `air_pitch` (degrees, nose up +).
var level_in_air := false
var air_pitch := 0.0
## Distance along the path (m) of the bike's nearest point, as of the last tick.
var offset := 0.0
## Press through pad events (PadHands) rather than the actions themselves.
var through_pad := false
## Gains that shrink with the speed above 25 km/h (see HEADING_RATE); off, the rides the
## level tests were tuned on stay as they were.
var steady_at_speed := false

## The bike's pitch (degrees, nose up +) at the last tick, for its rate.
var _last_pitch := 0.0


func _physics_process(_delta: float) -> void:
	if bike == null or path == null or not bike.is_running():
		return
	var curve := path.curve
	var centre := bike.get_center_of_mass()
	offset = curve.get_closest_offset(path.to_local(centre))
	var length := curve.get_baked_length()
	var speed := bike.get_speed()
	var heading := bike.get_body_transform(BikeSimulation.FRAME).basis.x
	var here := path.to_global(curve.sample_baked(offset, true))
	var tangent := path.to_global(curve.sample_baked(fposmod(offset + 1.0, length), true)) - here
	heading.y = 0.0
	tangent.y = 0.0
	var to_path := here - centre
	to_path.y = 0.0
	# The path's own curvature a little ahead (the bike needs time to lean into a bend),
	# plus corrections of the heading error and the sideways error (both positive when
	# the path lies to the left).
	var heading_error := heading.signed_angle_to(tangent, Vector3.UP)
	var side_error := signf(heading.cross(to_path).y) * to_path.length()
	var bend := _path_curvature(fposmod(offset + speed * preview, length))
	var moving := maxf(absf(speed), 0.1) if steady_at_speed else 0.0
	var heading_gain := minf(HEADING_GAIN, HEADING_RATE / moving) if moving > 0.0 else HEADING_GAIN
	var side_gain := minf(SIDE_GAIN, SIDE_RATE / (moving * moving)) if moving > 0.0 else SIDE_GAIN
	var curvature := bend + heading_gain * heading_error + side_gain * side_error
	var stick := -curvature / BikeSimulation.max_turn_curvature()
	_press(TURN_ACTIONS, clampf(stick, -1.0, 1.0))
	var kmh: float = speed_along.call(offset) if speed_along.is_valid() else speed_kmh
	var wanted := kmh / 3.6
	var error := wanted - speed
	# Nothing slows a rolling bike but the brake (no drag, no rolling resistance), so the
	# triggers only correct the speed error: the throttle through the motor share, the
	# brake more lightly, as its trigger gives the bike's whole brake.
	var gain := THROTTLE_GAIN if error > 0.0 else BRAKE_GAIN
	var drive := clampf(gain * error, -1.0, 1.0) if wanted > 0.0 else -1.0
	_press(DRIVE_ACTIONS, 1.0 if wheelie else drive)
	_press(RIDER_ACTIONS, -1.0 if wheelie else _levelling())


## The rider stick (forward +) that levels the bike in the air; 0 on the ground.
func _levelling() -> float:
	var nose_up := rad_to_deg(asin(bike.get_body_transform(BikeSimulation.FRAME).basis.x.y))
	var rate := (nose_up - _last_pitch) * Engine.physics_ticks_per_second
	_last_pitch = nose_up
	if not level_in_air or bike.is_front_wheel_grounded() or bike.is_rear_wheel_grounded():
		return 0.0
	return clampf(AIR_PITCH_GAIN * (nose_up - air_pitch) + AIR_PITCH_RATE_GAIN * rate, -1.0, 1.0)


## Signed curvature of the path at `at` (m along it; 1/m, positive turning left): the turn
## of its direction over two metres.
func _path_curvature(at: float) -> float:
	var curve := path.curve
	var length := curve.get_baked_length()
	var before := curve.sample_baked(fposmod(at - 1.0, length), true)
	var here := curve.sample_baked(fposmod(at, length), true)
	var after := curve.sample_baked(fposmod(at + 1.0, length), true)
	var turned := (here - before).signed_angle_to(after - here, Vector3.UP)
	return turned / 1.0


## Lets go of everything.
func release() -> void:
	for action: StringName in TURN_ACTIONS + DRIVE_ACTIONS + RIDER_ACTIONS:
		Input.action_release(action)
	if through_pad:
		PadHands.release(TURN_ACTIONS + DRIVE_ACTIONS + RIDER_ACTIONS)


func _press(actions: Array[StringName], value: float) -> void:
	if through_pad:
		PadHands.press_axis(actions, value)
	else:
		_press_axis(actions, value)


## Presses `actions[1]` for positive `value` and `actions[0]` for negative, with its size as
## the strength, releasing the other (an axis as a stick or a pair of triggers gives it).
static func _press_axis(actions: Array[StringName], value: float) -> void:
	var pressed := actions[1] if value > 0.0 else actions[0]
	var released := actions[0] if value > 0.0 else actions[1]
	Input.action_release(released)
	if absf(value) > 0.0:
		Input.action_press(pressed, absf(value))
	else:
		Input.action_release(pressed)
