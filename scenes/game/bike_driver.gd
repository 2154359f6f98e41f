class_name BikeDriver
extends Node
## The player's hands: reads the throttle, brake, turn and rider-position actions every
## physics tick and passes them to the bike. Auto-accelerate (X / F) holds a chosen speed
## instead of the triggers; an automatic level also takes the turn command away, as in the
## thesis's test.

## Throttle used by auto-accelerate: the rear motor drives towards the chosen speed with
## this share of its force, so the start is brisk without lifting the front wheel.
const AUTO_THROTTLE := 0.6

## The bike being driven (set by the game).
var bike: BikeSimulation
## Hold `auto_speed_kmh` without the triggers.
var auto_accelerate := false
## Speed auto-accelerate holds (km/h); the game sets the player's, from the settings.
var auto_speed_kmh: float = Settings.schema_entry(&"auto_speed_kmh").default
## Ignore the turn command (automatic levels).
var steering_locked := false
## Top speed (km/h) of full throttle when driving by hand.
var max_speed_kmh: float = Settings.schema_entry(&"max_speed_kmh").default
## What the player's hands gave the bike at the last tick (for replays): the triggers
## (0–1), the turn (−1 left to 1 right) and the rider stick (x right, y forward).
var throttle := 0.0
var brake := 0.0
var turn := 0.0
var rider := Vector2.ZERO


func _physics_process(_delta: float) -> void:
	if bike == null:
		return
	brake = Input.get_action_strength(&"brake")
	if auto_accelerate:
		bike.max_speed_kmh = auto_speed_kmh
		throttle = AUTO_THROTTLE
	else:
		bike.max_speed_kmh = max_speed_kmh
		throttle = Input.get_action_strength(&"throttle")
	bike.set_drive(throttle, brake)
	turn = 0.0 if steering_locked else Input.get_axis(&"steer_left", &"steer_right")
	bike.set_turn(turn)
	# Without a controller (manual mode) the stick steers the bar directly.
	bike.set_steer_rate(-turn * 0.6)
	# The rider's weight (right stick, I J K L): x to the right, y forward.
	rider = Input.get_vector(&"rider_left", &"rider_right", &"rider_back", &"rider_forward")
	bike.set_rider_position(rider.y, rider.x)
