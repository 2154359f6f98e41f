class_name Rumble
extends Node
## The pad's rumble, answering the simulation: a landing shakes it by how fast the bike
## came down (its centre of mass's fall, measured per control step, at the moment a wheel
## touches again: `BikeSimulation.landed`), a crash shakes it hard. Off with the `rumble`
## setting (this node is one of the game's setting targets).

## A fall this fast (m/s) or faster gives a full shake; a landing shakes at least LIGHTEST.
const HARDEST_FALL := 4.0
const LIGHTEST := 0.15
const LANDING_S := 0.25
const CRASH_S := 0.6

## Whether the pad rumbles (the `rumble` setting).
var rumble := true:
	set(value):
		rumble = value
		if not rumble:
			Input.stop_joy_vibration(device)
## The pad that rumbles.
var device := 0

var _bike: BikeSimulation
var _fall_speed := 0.0
var _falling := StepRate.new()


## Rumbles for `bike`'s landings and crashes.
func follow(bike: BikeSimulation) -> void:
	_bike = bike
	bike.landed.connect(func() -> void: landed(_fall_speed))
	bike.crashed.connect(func(_cause: String) -> void: crashed())


func _physics_process(_delta: float) -> void:
	if _bike == null or not _bike.is_running():
		_falling.reset()
		return
	var now := _falling.falling(_bike, _bike.get_center_of_mass().y)
	if not is_nan(now):
		_fall_speed = now


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
