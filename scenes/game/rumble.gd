class_name Rumble
extends Node
## The pad's rumble, answering the simulation: a landing shakes it by how fast the bike
## came down (its centre of mass's fall, measured per control step, at the moment a wheel
## touches again: `BikeSimulation.landed`), a crash shakes it hard. While riding, the light
## motor pulses while the ABS works a braked wheel and buzzes as the engine nears its
## limiter; neither cuts a landing's or a crash's shake short. Off with the `rumble`
## setting (this node is one of the game's setting targets).

## A fall this fast (m/s) or faster gives a full shake; a landing shakes at least LIGHTEST.
const HARDEST_FALL := 4.0
const LIGHTEST := 0.15
const LANDING_S := 0.25
const CRASH_S := 0.6
## The ABS at work: the bike slowing harder than ABS_DECELERATION (m/s²) with a grounded
## tyre slipping more than ABS_SLIP of the road speed (the ABS holds a braked wheel near
## 10 %), above MOVING (m/s). It pulses the light motor, as the pump is felt at the lever.
const ABS_DECELERATION := 3.0
const ABS_SLIP := 0.05
const MOVING := 2.0
const ABS_PULSE := 0.45
## The engine's buzz: from ENGINE_FROM of the limiter's crank speed, up to ENGINE_BUZZ on
## the light motor at the limiter.
const ENGINE_FROM := 0.75
const ENGINE_BUZZ := 0.2
## How long each riding pulse lasts (s): renewed every physics frame while it holds.
const RIDING_S := 0.1

## Whether the pad rumbles (the `rumble` setting).
var rumble := true:
	set(value):
		rumble = value
		if not rumble:
			Input.stop_joy_vibration(device)
## The pad that rumbles.
var device := 0

var _bike: BikeSimulation
var _sound: BikeSound
var _fall_speed := 0.0
var _falling := StepRate.new()
var _deceleration := 0.0
var _slowing := StepRate.new()
## Until when (ms, engine ticks) a landing's or a crash's shake runs.
var _event_until := 0


## Rumbles for `bike`'s landings, crashes, ABS and engine (its `Sound` node's).
func follow(bike: BikeSimulation) -> void:
	_bike = bike
	_sound = bike.get_node_or_null(^"Sound") as BikeSound
	bike.landed.connect(func() -> void: landed(_fall_speed))
	bike.crashed.connect(func(_cause: String) -> void: crashed())


func _physics_process(_delta: float) -> void:
	if _bike == null or not _bike.is_running():
		_falling.reset()
		_slowing.reset()
		return
	var now := _falling.falling(_bike, _bike.get_center_of_mass().y)
	if not is_nan(now):
		_fall_speed = now
	var slowing := _slowing.falling(_bike, _bike.get_speed())
	if not is_nan(slowing):
		_deceleration = slowing
	if _bike.is_crashed():
		return
	var grounded: Array[bool] = [_bike.is_rear_wheel_grounded(), _bike.is_front_wheel_grounded()]
	var abs_on := abs_working(_bike.get_tyres(), grounded, _bike.get_speed(), _deceleration)
	var revs := _sound.revs() if _sound != null else 0.0
	riding(abs_on, revs)


## Whether the ABS is at work on `tyres` (contact, and slide speed as the fourth number)
## that are `grounded`, the bike at `speed` (m/s) slowing at `deceleration` (m/s²).
static func abs_working(
	tyres: Array[Vector4], grounded: Array[bool], speed: float, deceleration: float
) -> bool:
	if not (speed > MOVING and deceleration > ABS_DECELERATION):
		return false
	for wheel in mini(tyres.size(), grounded.size()):
		if grounded[wheel] and tyres[wheel].w > ABS_SLIP * speed:
			return true
	return false


## The light motor's buzz (0–ENGINE_BUZZ) with the crank at `revs` of its limiter's speed
## (`BikeSound.revs`).
static func engine_buzz(revs: float) -> float:
	var share := (revs - ENGINE_FROM) / (1.0 - ENGINE_FROM)
	return clampf(share, 0.0, 1.0) * ENGINE_BUZZ if is_finite(share) else 0.0


## The riding rumble for one physics frame: the ABS's pulse, else the engine's buzz;
## nothing over a landing's or a crash's shake.
func riding(abs_on: bool, revs: float) -> void:
	if not rumble or Time.get_ticks_msec() < _event_until:
		return
	var light := ABS_PULSE if abs_on else engine_buzz(revs)
	if light > 0.0:
		Input.start_joy_vibration(device, light, 0.0, RIDING_S)


## Shakes the pad for a landing from a fall at `fall_speed` (m/s, downwards).
func landed(fall_speed: float) -> void:
	var strength := clampf(fall_speed / HARDEST_FALL, LIGHTEST, 1.0)
	_shake(strength * 0.6, strength, LANDING_S)


## Shakes the pad hard: the bike went down.
func crashed() -> void:
	_shake(1.0, 1.0, CRASH_S)


func _shake(weak: float, strong: float, seconds: float) -> void:
	if rumble:
		Input.start_joy_vibration(device, weak, strong, seconds)
		_event_until = Time.get_ticks_msec() + roundi(seconds * 1000.0)
