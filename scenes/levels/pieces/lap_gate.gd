@tool
class_name LapGate
extends GateLine
## A line across the track that the bike crosses in the direction of this node's −z.
## Checkpoint 0 is the start/finish line; a lap counts when the bike has crossed every
## other checkpoint in increasing order before crossing line 0 again.

## 0: start/finish line; 1, 2, …: checkpoints in the order they must be passed.
@export_range(0, 32) var checkpoint := 0:
	set(value):
		checkpoint = value
		_build()


func _draw_into(visual: Node3D) -> void:
	var start := checkpoint == 0
	visual.add_child(
		_painted_strip(0.6 if start else 0.25, Color.WHITE if start else Color(1.0, 0.8, 0.2))
	)
	for side: float in [-1.0, 1.0]:
		var post := MeshInstance3D.new()
		var cylinder := CylinderMesh.new()
		cylinder.top_radius = 0.08
		cylinder.bottom_radius = 0.08
		cylinder.height = 3.0
		cylinder.material = material(Color(0.9, 0.15, 0.1) if start else Color(1.0, 0.8, 0.2))
		post.mesh = cylinder
		post.position = Vector3(side * (width / 2.0 + 0.3), 1.5, 0.0)
		visual.add_child(post)
	if start:
		var banner := MeshInstance3D.new()
		var board := BoxMesh.new()
		board.size = Vector3(width + 0.6, 0.5, 0.08)
		board.material = material(Color(0.1, 0.1, 0.12))
		banner.mesh = board
		banner.position.y = 3.0
		visual.add_child(banner)
