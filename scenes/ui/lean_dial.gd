class_name LeanDial
extends Control
## The lean indicator: a dial seen from behind the bike with the two vectors of the
## thesis's Figure 4.11, the lean the controller aims for (green) and the bike's lean
## (white). Angles are radians, positive to the right.

const RANGE := deg_to_rad(75.0)
const TICKS_DEG: Array[int] = [-60, -45, -30, -15, 0, 15, 30, 45, 60]
const DESIRED_COLOUR := Color(0.3, 1.0, 0.45)
const CURRENT_COLOUR := Color(1.0, 1.0, 1.0)

## The lean the controller aims for.
var desired := 0.0:
	set(value):
		desired = value if is_finite(value) else 0.0
		queue_redraw()
## The bike's lean.
var current := 0.0:
	set(value):
		current = value if is_finite(value) else 0.0
		queue_redraw()


func _draw() -> void:
	var pivot := Vector2(size.x / 2.0, size.y - 10.0)
	var radius := minf(size.x / 2.0, size.y) - 16.0
	draw_arc(
		pivot, radius, -PI / 2.0 - RANGE, -PI / 2.0 + RANGE, 48, Color(1, 1, 1, 0.35), 3.0, true
	)
	for degrees in TICKS_DEG:
		var direction := _direction(deg_to_rad(degrees))
		var inner := radius * (0.86 if degrees % 30 == 0 else 0.92)
		draw_line(
			pivot + direction * inner, pivot + direction * radius, Color(1, 1, 1, 0.6), 2.0, true
		)
	draw_line(pivot + Vector2(-radius, 0), pivot + Vector2(radius, 0), Color(1, 1, 1, 0.25), 2.0)
	_needle(pivot, radius * 0.95, desired, DESIRED_COLOUR, 4.0)
	_needle(pivot, radius * 0.8, current, CURRENT_COLOUR, 6.0)
	draw_circle(pivot, 6.0, Color.WHITE)


## Unit vector on screen for a lean: up at 0, to the right for a right lean.
func _direction(lean: float) -> Vector2:
	var shown := clampf(lean, -RANGE, RANGE)
	return Vector2(sin(shown), -cos(shown))


func _needle(pivot: Vector2, length: float, lean: float, colour: Color, width: float) -> void:
	var tip := pivot + _direction(lean) * length
	draw_line(pivot, tip, Color(0, 0, 0, 0.5), width + 3.0, true)
	draw_line(pivot, tip, colour, width, true)
	draw_circle(tip, width, colour)
