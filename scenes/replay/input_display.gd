class_name InputDisplay
extends Control
## The player's hands during a replay, as Trials draws them: the brake and throttle
## triggers as bars filling up, the left stick (turn) and the right stick (rider's weight)
## as a dot in a ring.

const BRAKE_COLOUR := Color(0.95, 0.3, 0.25)
const THROTTLE_COLOUR := Color(0.35, 0.95, 0.4)
const RING_COLOUR := Color(1, 1, 1, 0.85)
const BACK_COLOUR := Color(0, 0, 0, 0.45)
const TRIGGER_SIZE := Vector2(22, 90)
const STICK_RADIUS := 40.0

## Trigger pulls (0–1), the turn (−1 left to 1 right) and the rider stick (x right, y
## forward).
var brake := 0.0:
	set(value):
		brake = value
		queue_redraw()
var throttle := 0.0:
	set(value):
		throttle = value
		queue_redraw()
var turn := 0.0:
	set(value):
		turn = value
		queue_redraw()
var rider := Vector2.ZERO:
	set(value):
		rider = value
		queue_redraw()


func _init() -> void:
	custom_minimum_size = Vector2(2 * TRIGGER_SIZE.x + 4 * STICK_RADIUS + 60, TRIGGER_SIZE.y + 24)


func _draw() -> void:
	var top := 4.0
	_trigger(Vector2(0, top), brake, BRAKE_COLOUR, "LT")
	var left_stick := Vector2(TRIGGER_SIZE.x + 15 + STICK_RADIUS, top + TRIGGER_SIZE.y / 2)
	_stick(left_stick, Vector2(turn, 0.0), "turn")
	var right_stick := left_stick + Vector2(2 * STICK_RADIUS + 15, 0)
	# Forward is up on the pad.
	_stick(right_stick, Vector2(rider.x, -rider.y), "weight")
	_trigger(Vector2(right_stick.x + STICK_RADIUS + 15, top), throttle, THROTTLE_COLOUR, "RT")


func _trigger(corner: Vector2, pull: float, colour: Color, label: String) -> void:
	draw_rect(Rect2(corner, TRIGGER_SIZE), BACK_COLOUR)
	var filled := TRIGGER_SIZE.y * clampf(pull, 0.0, 1.0)
	draw_rect(
		Rect2(corner + Vector2(0, TRIGGER_SIZE.y - filled), Vector2(TRIGGER_SIZE.x, filled)), colour
	)
	draw_rect(Rect2(corner, TRIGGER_SIZE), RING_COLOUR, false, 1.5)
	_label(corner + Vector2(TRIGGER_SIZE.x / 2, TRIGGER_SIZE.y + 16), label)


func _stick(centre: Vector2, at: Vector2, label: String) -> void:
	draw_circle(centre, STICK_RADIUS, BACK_COLOUR)
	draw_arc(centre, STICK_RADIUS, 0.0, TAU, 48, RING_COLOUR, 1.5)
	draw_circle(centre + at.limit_length(1.0) * (STICK_RADIUS - 8), 8, Color.WHITE)
	_label(centre + Vector2(0, STICK_RADIUS + 16), label)


func _label(centre: Vector2, text: String) -> void:
	var font := get_theme_default_font()
	var width := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, 14).x
	draw_string(font, centre - Vector2(width / 2, 0), text, HORIZONTAL_ALIGNMENT_LEFT, -1, 14)
