class_name RiderStance
extends RefCounted
## How the drawn rider holds themself over the simulated one, as riders do: tucked behind
## the clocks at speed, the inside knee out and the head into the bend past about 30° of
## lean, standing on the pegs in the air and over rough ground (a dirt rider). It moves the
## drawing only: the simulated bodies are what they are. Each part eases in and out over a
## fraction of a second, so a rider never snaps between stances.

## Lean (degrees) where the rider starts to hang off, and where the knee is all the way out.
const HANG_FROM_DEG := 18.0
const HANG_FULL_DEG := 32.0
## How quickly each part follows what the ride asks (s, the time to cover about two thirds
## of a change).
const EASE := {tuck = 0.4, hang = 0.2, stand = 0.15}
## How long (s) both wheels must be off the ground before the rider stands: a crest that
## unloads the wheels for a frame is not a jump.
const AIRBORNE_AFTER := 0.12
## How fast (m/s, the two wheels' suspension travel together, eased over EASE.stand) the
## suspension must be working for the ground to count as rough.
const ROUGH_TRAVEL_SPEED := 0.35
## Faster than any bike rides (m/s): a recording that moves faster has jumped (a seek).
const FASTEST_BIKE := 100.0

## 0 sitting up, 1 tucked all the way.
var tuck := 0.0
## −1 hanging off to the left, 1 to the right, 0 sitting on the bike's centre line.
var hang := 0.0
## 0 seated, 1 standing on the pegs.
var stand := 0.0

var _airborne_for := 0.0
var _travel_speed := 0.0
var _last_compression := Vector2.ZERO
var _has_compression := false
## Where a recording last put the bike's frame (world), to read its speed.
var _recorded_at := Vector3.INF


## Moves the stance `delta` seconds on for the rider of `simulation` (a BikeSimulation),
## whose style is `bodywork`'s; a rider fallen or off the bike lets every part go.
func advance_riding(delta: float, bodywork: BikeBodywork, simulation: BikeSimulation) -> void:
	var riding := simulation.is_rider_on() and not simulation.is_crashed()
	var airborne := not (
		simulation.is_rear_wheel_grounded() or simulation.is_front_wheel_grounded()
	)
	advance(
		delta,
		bodywork,
		simulation.get_speed() if riding else 0.0,
		simulation.get_lean() if riding else 0.0,
		airborne and riding,
		simulation.get_suspension_compression()
	)


## Moves the stance `delta` seconds on for a recorded rider (a ghost, a replay), read from
## the recorded frame: where it is now (world) and its lean (radians); its speed is how far
## it moved since the last pose (a seek or a restart, which moves it further than any bike
## goes in a frame, reads as standing still).
func advance_recorded(delta: float, bodywork: BikeBodywork, frame_at: Vector3, lean: float) -> void:
	var speed := 0.0
	if _recorded_at.is_finite() and delta > 0.0:
		speed = frame_at.distance_to(_recorded_at) / delta
	_recorded_at = frame_at
	if speed > FASTEST_BIKE:
		speed = 0.0
	advance(delta, bodywork, speed, lean, false)


## Moves the stance `delta` seconds on towards what a ride in this state asks of a rider
## whose style is `bodywork`'s (BikeBodywork): `speed` (m/s), `lean` (radians, positive to
## the right), whether both wheels are off the ground, and the suspension's compression
## (front, rear; m) or null when it is not known (a recording).
func advance(
	delta: float,
	bodywork: BikeBodywork,
	speed: float,
	lean: float,
	airborne: bool,
	compression: Variant = null
) -> void:
	if not (delta > 0.0):
		return
	var want := wanted(bodywork, speed, lean, _stands(delta, airborne, compression))
	tuck = _ease(tuck, want.tuck, delta, EASE.tuck)
	hang = _ease(hang, want.hang, delta, EASE.hang)
	stand = _ease(stand, want.stand, delta, EASE.stand)


## What a rider of `bodywork`'s style does, at once, at `speed` (m/s) and `lean` (radians,
## positive to the right), standing or not: {tuck, hang, stand}.
static func wanted(bodywork: BikeBodywork, speed: float, lean: float, standing: bool) -> Dictionary:
	var lean_deg := rad_to_deg(lean) if is_finite(lean) else 0.0
	var hang_share := clampf(inverse_lerp(HANG_FROM_DEG, HANG_FULL_DEG, absf(lean_deg)), 0.0, 1.0)
	var hang_to := signf(lean_deg) * hang_share * bodywork.hang_off
	var tuck_to := 0.0
	if bodywork.tuck_full_kmh > bodywork.tuck_from_kmh and is_finite(speed):
		var kmh := speed * 3.6
		tuck_to = clampf(inverse_lerp(bodywork.tuck_from_kmh, bodywork.tuck_full_kmh, kmh), 0, 1)
	var stand_to := 1.0 if standing and bodywork.stands_on_pegs else 0.0
	# A rider hanging off or standing up is not tucked in as well.
	tuck_to *= (1.0 - hang_share) * (1.0 - stand_to)
	return {tuck = tuck_to, hang = hang_to, stand = stand_to}


## Whether the ride now asks the rider to stand: in the air for a moment, or the suspension
## working hard.
func _stands(delta: float, airborne: bool, compression: Variant) -> bool:
	_airborne_for = _airborne_for + delta if airborne else 0.0
	if compression is Vector2:
		var now: Vector2 = compression
		if _has_compression:
			var rate := (now - _last_compression).length() / delta
			_travel_speed = _ease(
				_travel_speed, rate if is_finite(rate) else 0.0, delta, EASE.stand
			)
		_last_compression = now
		_has_compression = true
	return _airborne_for >= AIRBORNE_AFTER or _travel_speed > ROUGH_TRAVEL_SPEED


static func _ease(from: float, to: float, delta: float, time_constant: float) -> float:
	return lerpf(from, to, 1.0 - exp(-delta / time_constant))
