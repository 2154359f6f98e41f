class_name MedalBadge
extends Control
## A medal as a disc with its initial (G, S, B) in it, so it reads without its colour;
## an empty ring for none yet, a padlock bar for a lesson still locked.

const COLOURS: Array[Color] = [
	Color(1, 1, 1, 0.25), Color(0.80, 0.50, 0.25), Color(0.78, 0.80, 0.84), Color(1.0, 0.80, 0.20)
]
const INITIALS: Array[String] = ["", "B", "S", "G"]

## The medal shown.
var medal := Challenge.Medal.NONE:
	set(value):
		medal = value
		queue_redraw()
## Drawn as locked (a lesson not yet open).
var locked := false:
	set(value):
		locked = value
		queue_redraw()


func _init(size_px := 28.0) -> void:
	custom_minimum_size = Vector2(size_px, size_px)
	mouse_filter = Control.MOUSE_FILTER_IGNORE


func _draw() -> void:
	var centre := size / 2.0
	var radius := minf(size.x, size.y) / 2.0 - 1.0
	if locked:
		var body := Rect2(
			centre + Vector2(-radius * 0.6, -radius * 0.15), Vector2(radius * 1.2, radius * 0.95)
		)
		draw_arc(
			centre + Vector2(0, -radius * 0.15),
			radius * 0.4,
			PI,
			TAU,
			12,
			COLOURS[0].lightened(0.5),
			2.0,
			true
		)
		draw_rect(body, COLOURS[0].lightened(0.5))
		return
	if medal == Challenge.Medal.NONE:
		draw_arc(centre, radius - 1.0, 0.0, TAU, 32, COLOURS[0], 2.0, true)
		return
	var colour := COLOURS[medal]
	draw_circle(centre, radius, colour.darkened(0.35))
	draw_circle(centre, radius * 0.82, colour)
	var font := get_theme_default_font()
	var font_size := roundi(radius * 1.1)
	var text := INITIALS[medal]
	var extent := font.get_string_size(text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size)
	var baseline := centre + Vector2(-extent.x / 2.0, font.get_ascent(font_size) / 2.0 - 1.0)
	draw_string(
		font, baseline, text, HORIZONTAL_ALIGNMENT_LEFT, -1, font_size, Color(0.12, 0.1, 0.08)
	)
