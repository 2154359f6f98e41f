class_name LayoutCheck
extends RefCounted
## Test helper: what in a laid-out UI runs into something else or off the screen. The
## controls that draw something (a label with text, a dial, a pad) are compared in pairs
## by their rectangles; a rectangle is never allowed to leave the area.

## The game's canvas (project.godot's viewport size); windows stretch it, keeping its
## aspect or widening it (`expand`). The windows every layout is checked in.
const BASE := Vector2(1280, 720)
const WINDOWS: Array[Vector2] = [Vector2(1280, 720), Vector2(1920, 1080), Vector2(800, 600)]


## The canvas a `window` gives the UI at UI scale `scale`: the game's canvas stretched to
## the window keeping its aspect and widened to fill it, then shrunk by the scale.
static func canvas(window: Vector2, scale: float) -> Vector2:
	var stretch := minf(window.x / BASE.x, window.y / BASE.y)
	return (window / stretch / scale).floor()


## The controls below `root` that are shown and draw something: labels with text and
## any control that is not a container (a dial, a pad, the drawn inputs).
static func drawn(root: Node) -> Array[Control]:
	var found: Array[Control] = []
	for node in root.find_children("*", "Control", true, false):
		var control := node as Control
		if not control.is_visible_in_tree() or control is Container:
			continue
		if control is Label and (control as Label).text.strip_edges().is_empty():
			continue
		found.append(control)
	return found


## Every pair of `controls` whose rectangles overlap, and every one not wholly inside
## `area`, a line each (empty: the layout is clean).
static func problems(controls: Array[Control], area: Rect2) -> PackedStringArray:
	var found := PackedStringArray()
	for i in controls.size():
		var rect := controls[i].get_global_rect()
		if not area.encloses(rect.grow(-0.5)):
			found.append("%s %s leaves the screen %s" % [controls[i].name, rect, area])
		for j in range(i + 1, controls.size()):
			var other := controls[j].get_global_rect()
			if rect.intersects(other):
				found.append(
					"%s %s overlaps %s %s" % [controls[i].name, rect, controls[j].name, other]
				)
	return found


## The least distance (px) between any two of `controls`' rectangles that are not parts
## of one instrument (a dial and its speed below it share a parent and touch by design).
static func smallest_gap(controls: Array[Control]) -> float:
	var least := INF
	for i in controls.size():
		for j in range(i + 1, controls.size()):
			if controls[i].get_parent() == controls[j].get_parent():
				continue
			least = minf(least, _gap(controls[i].get_global_rect(), controls[j].get_global_rect()))
	return least


static func _gap(a: Rect2, b: Rect2) -> float:
	var dx := maxf(0.0, maxf(a.position.x - b.end.x, b.position.x - a.end.x))
	var dy := maxf(0.0, maxf(a.position.y - b.end.y, b.position.y - a.end.y))
	return Vector2(dx, dy).length()
