@tool
class_name GateLine
extends Node3D
## A line across the way, `width` wide and centred on this node, crossed forwards along
## this node's −z: the track's lap gates, a course's gates, lines painted on the road. Each
## kind draws itself (`_draw_into`); what they share is how a ride crosses them.

## Width of the line (m), centred on this node.
@export_range(1.0, 60.0, 0.5, "suffix:m") var width := 8.0:
	set(value):
		width = value
		_build()

var _visual: Node3D


func _ready() -> void:
	_build()


## +1 when the segment `from` → `to` (global) crosses the line forwards within its width,
## −1 backwards, 0 when it does not cross within the width.
func crossing(from: Vector3, to: Vector3) -> int:
	var offset := crossing_offset(from, to)
	if is_nan(offset) or absf(offset) > width / 2.0:
		return 0
	return 1 if to_local(from).z > 0.0 else -1


## Where the segment `from` → `to` (global) crosses the line drawn on for ever either side:
## how far from the middle (m, + to the right going forwards), or NAN where it does not
## cross. A course tells a gate passed from one missed with it.
func crossing_offset(from: Vector3, to: Vector3) -> float:
	var a := to_local(from)
	var b := to_local(to)
	if (a.z > 0.0) == (b.z > 0.0):
		return NAN
	return lerpf(a.x, b.x, a.z / (a.z - b.z))


## How far (m) `point` (global) lies past the line going forwards; negative before it.
func distance_past(point: Vector3) -> float:
	return -to_local(point).z


func _build() -> void:
	if not is_inside_tree():
		return
	if _visual != null:
		_visual.free()
	_visual = Node3D.new()
	_visual.name = "Visual"
	add_child(_visual)
	_draw_into(_visual)


## Adds the meshes that show this line to `visual` (rebuilt whenever a number changes).
func _draw_into(_visual_root: Node3D) -> void:
	pass


## A strip `length` (m, along the way) by this line's width painted on the ground.
func _painted_strip(length: float, colour: Color) -> MeshInstance3D:
	var line := MeshInstance3D.new()
	var strip := BoxMesh.new()
	strip.size = Vector3(width, 0.02, length)
	strip.material = material(colour)
	line.mesh = strip
	line.position.y = 0.01
	line.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	return line


## A plain, slightly rough material of `colour`.
static func material(colour: Color) -> StandardMaterial3D:
	var made := StandardMaterial3D.new()
	made.albedo_color = colour
	made.roughness = 0.8
	return made
