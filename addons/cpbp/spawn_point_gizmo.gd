@tool
extends EditorNode3DGizmoPlugin
## Draws every SpawnPoint in the editor as the bike it places: an outline of the bike's
## size standing on the ground, with an arrow along the way it will face.

const LENGTH := 2.0
const WIDTH := 0.8
const HEIGHT := 1.4


func _init() -> void:
	create_material("outline", Color(0.2, 0.85, 1.0))
	create_material("arrow", Color(1.0, 0.75, 0.1))


func _get_gizmo_name() -> String:
	return "SpawnPoint"


func _has_gizmo(node: Node3D) -> bool:
	return node is SpawnPoint


func _redraw(gizmo: EditorNode3DGizmo) -> void:
	gizmo.clear()
	var box := PackedVector3Array()
	var half := Vector3(WIDTH / 2.0, 0.0, LENGTH / 2.0)
	var corners: Array[Vector3] = [
		Vector3(-half.x, 0, -half.z),
		Vector3(half.x, 0, -half.z),
		Vector3(half.x, 0, half.z),
		Vector3(-half.x, 0, half.z),
	]
	for i in 4:
		var a := corners[i]
		var b := corners[(i + 1) % 4]
		box.append_array(
			[a, b, a + Vector3.UP * HEIGHT, b + Vector3.UP * HEIGHT, a, a + Vector3.UP * HEIGHT]
		)
	gizmo.add_lines(box, get_material("outline", gizmo))
	var tip := Vector3(0, 0.05, -LENGTH / 2.0 - 0.8)
	var arrow := PackedVector3Array(
		[
			Vector3(0, 0.05, 0),
			tip,
			tip,
			tip + Vector3(-0.25, 0, 0.35),
			tip,
			tip + Vector3(0.25, 0, 0.35),
		]
	)
	gizmo.add_lines(arrow, get_material("arrow", gizmo))
