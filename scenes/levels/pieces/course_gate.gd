@tool
class_name CourseGate
extends GateLine
## A gate of a course (a slalom, a line through a bend): two flags on poles with cones at
## their feet, `width` apart, to ride between going forwards along this node's −z. A
## course judge names its gates in order; riding past one outside its poles misses it.

const POLE_HEIGHT := 1.6
const FLAG_SIZE := Vector2(0.5, 0.4)
const WHITE := Color(0.95, 0.95, 0.95)

## The flags' colour; courses alternate two colours as ski slaloms do.
@export var colour := Color(0.9, 0.15, 0.12):
	set(value):
		colour = value
		_build()


## A road cone of `colour` with a white band, standing on the ground at its origin.
static func cone(colour: Color) -> Node3D:
	var root := Node3D.new()
	root.add_child(_upright(Vector2(0.15, 0.03), 0.45, 0.0, colour))
	root.add_child(_upright(Vector2(0.105, 0.085), 0.09, 0.195, WHITE))
	return root


func _draw_into(visual: Node3D) -> void:
	for side: float in [-1.0, 1.0]:
		var foot := Vector3(side * width / 2.0, 0.0, 0.0)
		var base := cone(colour)
		base.position = foot
		visual.add_child(base)
		var pole := _upright(Vector2(0.02, 0.02), POLE_HEIGHT, 0.0, WHITE)
		pole.position += foot
		visual.add_child(pole)
		var flag := MeshInstance3D.new()
		var cloth := BoxMesh.new()
		cloth.size = Vector3(FLAG_SIZE.x, FLAG_SIZE.y, 0.01)
		cloth.material = GateLine.material(colour)
		flag.mesh = cloth
		# The flags fly inwards, marking the gate's opening.
		flag.position = (
			foot + Vector3(-side * FLAG_SIZE.x / 2.0, POLE_HEIGHT - FLAG_SIZE.y / 2.0, 0.0)
		)
		visual.add_child(flag)


## A round upright `height` tall from `base` m up, its radii (bottom, top) `radii`.
static func _upright(radii: Vector2, height: float, base: float, colour: Color) -> MeshInstance3D:
	var shape := CylinderMesh.new()
	shape.bottom_radius = radii.x
	shape.top_radius = radii.y
	shape.height = height
	shape.radial_segments = 12
	shape.material = GateLine.material(colour)
	var upright := MeshInstance3D.new()
	upright.mesh = shape
	upright.position.y = base + height / 2.0
	return upright
