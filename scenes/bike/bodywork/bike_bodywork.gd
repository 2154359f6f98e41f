class_name BikeBodywork
extends Resource
## A bike's bodywork as data: the pieces on its frame body (BodyworkPiece) as drawn on one
## bike, and that bike's key points, so the same bodywork fits a bike of another size.
## A point is moved piecewise linearly between the key points (lengthwise by the axles and
## the swingarm's pivot low down, by the axles, the seat and the steering head up top;
## heightwise by the axles, the seat and the steering head) and keeps its distance to the
## outermost ones, so a tank still runs from the seat to the steering head, an engine sits
## ahead of the pivot and a tail overhangs the rear wheel as much.

## The closest two key points may come, so a bike with odd proportions bends its bodywork
## instead of folding it over (m).
const MIN_KNOT_GAP := 0.02

## What a bike whose description names no bodywork wears.
const STANDARD := "res://scenes/bike/bodywork/naked.tres"

## The key points (bike frame) of the bike the pieces were drawn on.
@export var rear_axle := Vector3.ZERO
@export var swingarm_pivot := Vector3.ZERO
@export var steering_head := Vector3.ZERO
@export var front_axle := Vector3.ZERO
## Where the rider sits: the bottom of the torso.
@export var seat := Vector3.ZERO
@export var pieces: Array[BodyworkPiece] = []

@export_group("On the fork")
## What the fork carries up front: a round headlamp (a road bike's), a number board (a
## dirt bike's) or nothing (a fairing on the frame carries the lamps).
@export_enum("lamp", "number_board", "none") var fork_front := "lamp"
## The front mudguard: just above the tyre (a road bike's), or high under the fork's
## bottom clamp, clear of mud and the long travel (a dirt bike's).
@export var high_mudguard := false
## Mirrors on stalks from the bar (a road bike's).
@export var mirrors := false

@export_group("Wheels")
## Cast spokes (a road bike's) or laced wire spokes (a dirt bike's) (BikeWheels).
@export_enum("cast", "spoked") var wheels := "cast"
## Brake discs on the front wheel: two on a road bike that stops hard, one on a light one.
@export_range(0, 2) var front_discs := 1

@export_group("The rider")
## What the rider wears (RiderSkin): road leathers and a full-face helmet, or a motocross
## kit, its helmet with a peak and goggles.
@export_enum("road", "motocross") var gear := "road"
## Speed (km/h) where the rider starts to tuck in behind the clocks, and where they are
## tucked all the way; equal speeds, never (a dirt rider sits up).
@export var tuck_from_kmh := 0.0
@export var tuck_full_kmh := 0.0
## How far the rider hangs off into a bend (RiderStance): 0 sits on the centre line, 1 puts
## the inside knee all the way out and the head inside the bike's.
@export_range(0.0, 1.0) var hang_off := 0.0
## Stands on the pegs in the air and over rough ground, as a dirt rider does.
@export var stands_on_pegs := false


## The bodywork `bike` (a BikeDescription) names, or the standard one (with an error
## saying why) when it names none, or something that is not bodywork, or bodywork whose key
## points are out of order.
static func worn_by(bike: BikeDescription) -> BikeBodywork:
	var bodywork := bike.bodywork as BikeBodywork
	if bike.bodywork != null and bodywork == null:
		push_error("%s: its bodywork is not a BikeBodywork; drawing the standard one" % bike.name)
	elif bodywork != null and not bodywork.problem().is_empty():
		push_error("%s: %s; drawing the standard bodywork" % [bike.name, bodywork.problem()])
		bodywork = null
	return bodywork if bodywork != null else load(STANDARD) as BikeBodywork


## Where `point` (drawn on the authored bike) goes on a bike whose key points are
## `points` (a Dictionary of the key points' names to bike-frame positions).
func fitted(point: Vector3, points: Dictionary) -> Vector3:
	# Low down the bodywork follows the swingarm's pivot (the engine sits ahead of it), up
	# top the seat (the tank runs from it to the steering head); in between, a blend.
	var low := _knots(points, "x", ["rear_axle", "swingarm_pivot", "front_axle"])
	var high := _knots(points, "x", ["rear_axle", "seat", "steering_head", "front_axle"])
	var up := _knots(points, "y", ["rear_axle", "seat", "steering_head"])
	var height := clampf(inverse_lerp(rear_axle.y, seat.y, point.y), 0.0, 1.0)
	var x := lerpf(_warp(point.x, low), _warp(point.x, high), height)
	return Vector3(x, _warp(point.y, up), point.z)


## A box's or an ellipsoid's `centre`, `size` and `pitch` (see BodyworkPiece) fitted to a
## bike with key points `points`: its lengthwise and upright axes are fitted end to end.
func fitted_block(centre: Vector3, size: Vector3, pitch: float, points: Dictionary) -> Dictionary:
	var along := Vector3(cos(pitch), sin(pitch), 0.0) * size.x / 2.0
	var up := Vector3(-sin(pitch), cos(pitch), 0.0) * size.y / 2.0
	var back := fitted(centre - along, points)
	var front := fitted(centre + along, points)
	var height := fitted(centre + up, points).distance_to(fitted(centre - up, points))
	return {
		centre = fitted(centre, points),
		size = Vector3(back.distance_to(front), height, size.z),
		pitch = atan2(front.y - back.y, front.x - back.x),
	}


## Why these key points cannot fit anything (they are not in order along and up the
## bike), or "" when they can.
func problem() -> String:
	var low := [rear_axle.x, swingarm_pivot.x, front_axle.x]
	var high := [rear_axle.x, seat.x, steering_head.x, front_axle.x]
	var up := [rear_axle.y, seat.y, steering_head.y]
	for order: Array in [low, high, up]:
		for i in range(1, order.size()):
			if not float(order[i]) > float(order[i - 1]):
				return "key points out of order: %s" % [authored_points()]
	return ""


## The key points this bodywork was drawn on, by name.
func authored_points() -> Dictionary:
	return {
		rear_axle = rear_axle,
		swingarm_pivot = swingarm_pivot,
		steering_head = steering_head,
		front_axle = front_axle,
		seat = seat,
	}


## Pairs [authored, fitted] of one coordinate of the named key points, in authored order,
## the fitted ones kept increasing.
func _knots(points: Dictionary, axis: String, names: Array) -> Array[Vector2]:
	var knots: Array[Vector2] = []
	var authored := authored_points()
	for name: String in names:
		var was: float = (authored[name] as Vector3)[axis]
		var now: float = (points.get(name, authored[name]) as Vector3)[axis]
		if not knots.is_empty():
			now = maxf(now, knots[-1].y + MIN_KNOT_GAP)
		knots.append(Vector2(was, now))
	return knots


## `value` moved piecewise linearly through `knots` ([authored, fitted] pairs), shifted
## with the nearest end outside them.
static func _warp(value: float, knots: Array[Vector2]) -> float:
	if value <= knots[0].x:
		return value - knots[0].x + knots[0].y
	for i in range(1, knots.size()):
		if value <= knots[i].x:
			var share := (value - knots[i - 1].x) / (knots[i].x - knots[i - 1].x)
			return lerpf(knots[i - 1].y, knots[i].y, share)
	return value - knots[-1].x + knots[-1].y
