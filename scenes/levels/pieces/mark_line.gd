@tool
class_name MarkLine
extends GateLine
## A line painted across the way for a lesson or challenge to measure from: where to be
## at speed, where to stop, a mark to reach. Riding, it is paint only.

## The line's paint.
@export var colour := Color(0.95, 0.95, 0.92):
	set(value):
		colour = value
		_build()
## Length of the paint along the way (m).
@export_range(0.05, 2.0, 0.05, "suffix:m") var thickness := 0.3:
	set(value):
		thickness = value
		_build()
## Cones at both ends, for a line to see from afar (where to be at speed).
@export var cones := false:
	set(value):
		cones = value
		_build()


func _draw_into(visual: Node3D) -> void:
	visual.add_child(_painted_strip(thickness, colour))
	if cones:
		for side: float in [-1.0, 1.0]:
			var cone := CourseGate.cone(Color(1.0, 0.45, 0.1))
			cone.position.x = side * (width / 2.0 + 0.3)
			visual.add_child(cone)
