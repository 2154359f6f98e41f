class_name BikeDriver
extends Node
## The player's hands: reads the throttle, brake, turn and rider-position actions every
## physics tick and passes them to the bike. Auto-accelerate (X / F) holds a chosen speed
## instead of the triggers; an automatic level also takes the turn command away, as in the
## thesis's test. The game's settings of the drive (`auto_accelerate`, `auto_speed_kmh`,
## `max_speed_kmh`) and the controller reach it by name: they are its properties.

## Says something the player should read (the game shows it on the HUD).
signal announced(text: String)

## Throttle used by auto-accelerate: the rear motor drives towards the chosen speed with
## this share of its force, so the start is brisk without lifting the front wheel.
const AUTO_THROTTLE := 0.6

## The bike being driven (set by the game).
var bike: BikeSimulation
## Hold `auto_speed_kmh` without the triggers (always on an automatic level).
var auto_accelerate := false
## Speed auto-accelerate holds (km/h); the game sets the player's, from the settings.
var auto_speed_kmh: float = Settings.schema_entry(&"auto_speed_kmh").default
## An automatic level: it accelerates by itself and ignores the turn command.
var automatic := false
## An automatic level's attempt is over (the goal reached, or out of time): until the
## level starts the next one the rider brakes to a stop, whatever the triggers, so the bike
## waits at the goal rather than riding on over the level's end.
var stopping := false
## Top speed (km/h) of full throttle when driving by hand.
var max_speed_kmh: float = Settings.schema_entry(&"max_speed_kmh").default
## Who balances and steers, by the registry's name: the player's choice, saved as it is;
## one this bike does not offer (learned, on a bike without a model of its own) rides with
## arcade and says why.
var controller: StringName:
	set(value):
		controller = value
		if bike == null:
			return
		if bike.get_offered_controller_names().has(value):
			bike.controller = value
		else:
			bike.controller = &"arcade"
			announced.emit(
				"%s is not offered on this bike: it has no learned model" % value.capitalize()
			)
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
	if stopping:
		throttle = 0.0
		brake = 1.0
	elif auto_accelerate or automatic:
		bike.max_speed_kmh = auto_speed_kmh
		throttle = AUTO_THROTTLE
	else:
		bike.max_speed_kmh = max_speed_kmh
		throttle = Input.get_action_strength(&"throttle")
	bike.set_drive(throttle, brake)
	turn = 0.0 if automatic else Input.get_axis(&"steer_left", &"steer_right")
	bike.set_turn(turn)
	# Without a controller (manual mode) the stick steers the bar directly.
	bike.set_steer_rate(-turn * 0.6)
	# The rider's weight (right stick, I J K L): x to the right, y forward.
	rider = Input.get_vector(&"rider_left", &"rider_right", &"rider_back", &"rider_forward")
	bike.set_rider_position(rider.y, rider.x)
