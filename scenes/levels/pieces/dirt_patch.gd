@tool
class_name DirtPatch
extends Node3D
## A stretch of packed dirt laid over the ground or a road, `size` across (x) and along (z),
## centred on this node: drawn in the dirt surface, and where a tyre throws dust (`Dust`
## asks `on_dirt`). It is only a surface's look: the tyres grip on it as on the ground under
## it, and nothing of it collides.

const DIRT_MATERIAL := preload("res://scenes/levels/materials/dirt.tres")
## How far over the ground the dirt is drawn (m): over the track's road (7 mm), under the
## tyre marks (`TyreMarks.LIFT`).
const RISE := 0.009
const GROUP := &"dirt_patches"

@export var size := Vector2(7.0, 30.0):
	set(value):
		size = value.max(Vector2(0.1, 0.1))
		_build()

var _mesh: MeshInstance3D


func _enter_tree() -> void:
	add_to_group(GROUP)


func _ready() -> void:
	_build()


## Whether `point` (global) lies over this patch.
func contains(point: Vector3) -> bool:
	var local := to_local(point)
	return absf(local.x) <= size.x / 2.0 and absf(local.z) <= size.y / 2.0


## Whether `point` (global) lies over any dirt patch in `tree`.
static func on_dirt(tree: SceneTree, point: Vector3) -> bool:
	for patch: DirtPatch in tree.get_nodes_in_group(GROUP):
		if patch.contains(point):
			return true
	return false


func _build() -> void:
	if not is_inside_tree():
		return
	if _mesh == null:
		_mesh = MeshInstance3D.new()
		_mesh.name = "Surface"
		_mesh.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
		_mesh.material_override = DIRT_MATERIAL
		_mesh.position.y = RISE
		add_child(_mesh)
	var plane := PlaneMesh.new()
	plane.size = size
	_mesh.mesh = plane
