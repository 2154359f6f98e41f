class_name CounterSteerWatch
extends RefCounted
## Watches a ride for what the player never does by hand: asked for a turn, the rider first
## turns the bar the other way, and the bike leans into the turn that follows. A turn
## starts when the wanted lean passes ASKED towards a side it was not already asking for
## (so an S is two turns); for WINDOW seconds the bar's widest turn the wrong way and the
## lean reached are measured.

## Wanted lean (rad) that counts as a turn asked, and below which a turn is over.
const ASKED := deg_to_rad(5.0)
const SETTLED := deg_to_rad(2.0)
const WINDOW := 1.5

## One dictionary a turn: side (+1 right, −1 left), counter (rad the bar turned the wrong
## way at most), lean (rad leaned into the turn at most).
var turns: Array[Dictionary] = []

var _side := 0.0
var _open_for := 0.0


## Takes the bike's state after `delta` seconds more.
func watch(bike: BikeSimulation, delta: float) -> void:
	var wanted := bike.get_desired_lean()
	if absf(wanted) > ASKED and signf(wanted) != _side:
		_side = signf(wanted)
		turns.append({side = _side, counter = 0.0, lean = 0.0})
		_open_for = WINDOW
	elif absf(wanted) < SETTLED:
		_side = 0.0
	if _open_for <= 0.0:
		return
	_open_for -= delta
	var turn: Dictionary = turns[-1]
	var side: float = turn.side
	# Steering is positive to the left and lean to the right: turning right, the bar's
	# wrong way is to the left.
	turn.counter = maxf(turn.counter, side * bike.get_steering_angle())
	turn.lean = maxf(turn.lean, side * bike.get_lean())


## The turns that leaned the bike, a line each: "a right turn: the bar 3.2° left first,
## then 24° of lean right" (a correction that hardly leaned it is left out).
func describe() -> PackedStringArray:
	var lines := PackedStringArray()
	for turn: Dictionary in turns:
		if turn.lean < ASKED:
			continue
		var right: bool = turn.side > 0.0
		(
			lines
			. append(
				(
					"a %s turn: the bar %.1f° %s first, then %d° of lean %s"
					% [
						"right" if right else "left",
						rad_to_deg(turn.counter),
						"left" if right else "right",
						roundi(rad_to_deg(turn.lean)),
						"right" if right else "left",
					]
				)
			)
		)
	return lines
