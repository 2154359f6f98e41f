@tool
class_name LapGate
extends Node3D
## A line across the track that the bike crosses in the direction of this node's −z.
## Checkpoint 0 is the start/finish line; a lap counts when the bike has crossed every
## other checkpoint in increasing order before crossing line 0 again.

## 0: start/finish line; 1, 2, …: checkpoints in the order they must be passed.
@export_range(0, 32) var checkpoint := 0:
	set(value):
		checkpoint = value
		_build()
## Width of the gate (m), centred on this node.
@export_range(1.0, 60.0, 0.5, "suffix:m") var width := 8.0:
	set(value):
		width = value
		_build()

var _visual: Node3D


func _ready() -> void:
	_build()


## +1 when the segment `from` → `to` (global) crosses the gate forwards, −1 backwards,
## 0 when it does not cross within the gate's width.
func crossing(from: Vector3, to: Vector3) -> int:
	var a := to_local(from)
	var b := to_local(to)
	if (a.z > 0.0) == (b.z > 0.0):
		return 0
	var t := a.z / (a.z - b.z)
	if absf(lerpf(a.x, b.x, t)) > width / 2.0:
		return 0
	return 1 if a.z > 0.0 else -1


func _build() -> void:
	if not is_inside_tree():
		return
	if _visual != null:
		_visual.free()
	_visual = Node3D.new()
	_visual.name = "Visual"
	add_child(_visual)
	var line := MeshInstance3D.new()
	var strip := BoxMesh.new()
	strip.size = Vector3(width, 0.02, 0.6 if checkpoint == 0 else 0.25)
	strip.material = _material(Color.WHITE if checkpoint == 0 else Color(1.0, 0.8, 0.2))
	line.mesh = strip
	line.position.y = 0.01
	_visual.add_child(line)
	for side: float in [-1.0, 1.0]:
		var post := MeshInstance3D.new()
		var cylinder := CylinderMesh.new()
		cylinder.top_radius = 0.08
		cylinder.bottom_radius = 0.08
		cylinder.height = 3.0
		cylinder.material = _material(
			Color(0.9, 0.15, 0.1) if checkpoint == 0 else Color(1.0, 0.8, 0.2)
		)
		post.mesh = cylinder
		post.position = Vector3(side * (width / 2.0 + 0.3), 1.5, 0.0)
		_visual.add_child(post)
	if checkpoint == 0:
		var banner := MeshInstance3D.new()
		var board := BoxMesh.new()
		board.size = Vector3(width + 0.6, 0.5, 0.08)
		board.material = _material(Color(0.1, 0.1, 0.12))
		banner.mesh = board
		banner.position.y = 3.0
		_visual.add_child(banner)


func _material(colour: Color) -> StandardMaterial3D:
	var material := StandardMaterial3D.new()
	material.albedo_color = colour
	material.roughness = 0.8
	return material
