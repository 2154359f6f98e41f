@tool
class_name BumpField
extends Node3D
## Seeded random bumps: logs lying half-buried across an area, each a static cylinder the
## simulation collides with. `regenerate(seed)` lays out a new set; the same seed always
## gives the same bumps. The area is centred on this node, along its −z. The native core
## lays them (`LogFieldDescription.layout`), so the trainer and the scenario tool ride the
## same logs from the same seed.

## Where the logs fall and how big they are: a resource, so a level's field is one file
## the tools read too (the test level's is scenes/levels/test_level/log_field.tres).
## None lays no logs.
@export var field: LogFieldDescription:
	set(value):
		if field != null and field.changed.is_connected(_rebuild_in_editor):
			field.changed.disconnect(_rebuild_in_editor)
		field = value
		if field != null and Engine.is_editor_hint():
			field.changed.connect(_rebuild_in_editor)
		_rebuild_in_editor()
## Seed shown in the editor; games and experiments pass their own to `regenerate`.
@export var preview_seed := 1:
	set(value):
		preview_seed = value
		_rebuild_in_editor()

var _seed := 1
var _material: StandardMaterial3D


func _ready() -> void:
	regenerate(preview_seed)


## Replaces the bumps with the set for `seed`. The simulation reads the terrain when the
## bike is built: the level emits `terrain_changed` after this (`Level.attach`).
func regenerate(seed_value: int) -> void:
	_seed = seed_value
	for child in get_children():
		remove_child(child)
		child.queue_free()
	if _material == null:
		_material = StandardMaterial3D.new()
		_material.albedo_color = Color(0.42, 0.3, 0.2)
		_material.roughness = 0.9
	if field == null:
		return
	var logs := field.layout(seed_value)
	for i in logs.size():
		var placed: Dictionary = logs[i]
		add_child(_bump(i, placed.radius, placed.length, placed.angle, placed.centre))


## The seed of the current bumps.
func current_seed() -> int:
	return _seed


func _bump(index: int, radius: float, length: float, angle: float, centre: Vector3) -> StaticBody3D:
	var body := StaticBody3D.new()
	body.name = "Bump%d" % index
	# A cylinder stands along y: lay it along x (across the way), then turn it by `angle`.
	body.transform = Transform3D(
		Basis(Vector3.UP, angle) * Basis(Vector3.FORWARD, PI / 2.0), centre
	)
	var shape := CollisionShape3D.new()
	shape.name = "Shape"
	var cylinder := CylinderShape3D.new()
	cylinder.radius = radius
	cylinder.height = length
	shape.shape = cylinder
	body.add_child(shape)
	var mesh := MeshInstance3D.new()
	mesh.name = "Mesh"
	var visual := CylinderMesh.new()
	visual.top_radius = radius
	visual.bottom_radius = radius
	visual.height = length
	visual.radial_segments = 24
	visual.material = _material
	mesh.mesh = visual
	body.add_child(mesh)
	return body


func _rebuild_in_editor() -> void:
	if Engine.is_editor_hint() and is_inside_tree():
		regenerate(preview_seed)
