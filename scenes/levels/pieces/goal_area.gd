@tool
class_name GoalArea
extends Node3D
## A box the bike has to reach: `contains` tells whether a point (the bike's centre of
## mass) is inside. Shown as a translucent green volume with a chequered line.

## How far (m) the drawn volume's bottom sits above the box's.
const VISUAL_INSET := 0.02

## Size of the box (m), centred on this node.
@export var size := Vector3(25.0, 3.0, 4.0):
	set(value):
		size = value.max(Vector3(0.1, 0.1, 0.1))
		_build()

var _mesh: MeshInstance3D


func _ready() -> void:
	_build()


## True when `point` (global) lies inside the box.
func contains(point: Vector3) -> bool:
	var local := to_local(point).abs()
	return local.x <= size.x / 2.0 and local.y <= size.y / 2.0 and local.z <= size.z / 2.0


func _build() -> void:
	if not is_inside_tree():
		return
	if _mesh == null:
		_mesh = MeshInstance3D.new()
		_mesh.name = "Volume"
		_mesh.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
		add_child(_mesh)
	# Drawn a little inside its box: its bottom face on the floor it stands on would fight
	# the floor's for the same depth, striping the ground around a bike standing there.
	var box := BoxMesh.new()
	box.size = size - Vector3(0.0, VISUAL_INSET, 0.0)
	_mesh.position.y = VISUAL_INSET / 2.0
	var material := StandardMaterial3D.new()
	material.albedo_color = Color(0.2, 0.9, 0.35, 0.25)
	material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	material.cull_mode = BaseMaterial3D.CULL_DISABLED
	box.material = material
	_mesh.mesh = box
