class_name RiderPad
extends Control
## Where the rider's weight is, seen from above with the bike pointing up the screen: the
## position the player asks for (green ring, the right stick) and where the rider's centre
## of mass is (white dot), both in the stick's units (±1 at the edge, at full reach).
## Colours as the lean dial's: green wanted, white actual.

const ASKED_COLOUR := Color(0.3, 1.0, 0.45)
const ACTUAL_COLOUR := Color(1.0, 1.0, 1.0)

## The position asked for: x to the right, y forward, each in [−1, 1].
var asked := Vector2.ZERO:
	set(value):
		asked = value if value.is_finite() else Vector2.ZERO
		queue_redraw()
## Where the rider is, in the same units (may pass the edge: drawn on it).
var actual := Vector2.ZERO:
	set(value):
		actual = value if value.is_finite() else Vector2.ZERO
		queue_redraw()


func _draw() -> void:
	var half := minf(size.x, size.y) / 2.0 - 8.0
	var centre := size / 2.0
	var box := Rect2(centre - Vector2(half, half), Vector2(half, half) * 2.0)
	draw_rect(box, Color(0, 0, 0, 0.35))
	draw_rect(box, Color(1, 1, 1, 0.45), false, 2.0)
	# The bike from above: a slim frame along the pad, the front wheel at the top.
	draw_line(
		centre + Vector2(0, half * 0.9), centre - Vector2(0, half * 0.9), Color(1, 1, 1, 0.25), 6.0
	)
	draw_line(
		centre - Vector2(half * 0.35, half * 0.7),
		centre + Vector2(half * 0.35, -half * 0.7),
		Color(1, 1, 1, 0.25),
		3.0
	)
	var asked_at := _on_pad(centre, half, asked)
	draw_arc(asked_at, 9.0, 0.0, TAU, 24, Color(0, 0, 0, 0.5), 6.0, true)
	draw_arc(asked_at, 9.0, 0.0, TAU, 24, ASKED_COLOUR, 3.0, true)
	var actual_at := _on_pad(centre, half, actual)
	draw_circle(actual_at, 6.5, Color(0, 0, 0, 0.5))
	draw_circle(actual_at, 5.0, ACTUAL_COLOUR)


## Screen point of a position: right is right, forward is up; clamped to the pad.
func _on_pad(centre: Vector2, half: float, position: Vector2) -> Vector2:
	var clamped := position.clampf(-1.0, 1.0)
	return centre + Vector2(clamped.x, -clamped.y) * half
