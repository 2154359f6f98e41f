@tool
class_name BumpField
extends Node3D
## Seeded random bumps: logs lying half-buried across an area, each a static cylinder the
## simulation collides with. `regenerate(seed)` lays out a new set; the same seed always
## gives the same bumps. The area is centred on this node, along its −z.

## Area the bump centres fall in (m): width (x) × length (z).
@export var area := Vector2(14.0, 20.0):
	set(value):
		area = value.max(Vector2(0.5, 0.5))
		_rebuild_in_editor()
## How many bumps.
@export_range(0, 200) var count := 10:
	set(value):
		count = value
		_rebuild_in_editor()
## Bump radius range (m); they are buried to their axis, so this is their height.
@export var radius_range := Vector2(0.06, 0.12):
	set(value):
		radius_range = value
		_rebuild_in_editor()
## Bump length range (m).
@export var length_range := Vector2(1.0, 3.0):
	set(value):
		length_range = value
		_rebuild_in_editor()
## Largest angle (degrees) between a bump and the line across the area.
@export_range(0.0, 90.0) var max_angle_deg := 35.0:
	set(value):
		max_angle_deg = value
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
	var rng := RandomNumberGenerator.new()
	rng.seed = seed_value
	if _material == null:
		_material = StandardMaterial3D.new()
		_material.albedo_color = Color(0.42, 0.3, 0.2)
		_material.roughness = 0.9
	for i in count:
		var radius := rng.randf_range(radius_range.x, radius_range.y)
		var length := rng.randf_range(length_range.x, length_range.y)
		var angle := deg_to_rad(rng.randf_range(-max_angle_deg, max_angle_deg))
		var centre := Vector3(
			rng.randf_range(-area.x / 2.0, area.x / 2.0),
			0.0,
			rng.randf_range(-area.y / 2.0, area.y / 2.0)
		)
		add_child(_bump(i, radius, length, angle, centre))


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
