@tool
class_name Trackside
extends Node3D
## What stands beside a track and gives the ride its speed and scale: trees scattered
## beyond the road, tyre walls round the outside of its bends and cones along their inside
## edge. All of it is laid from the lap path (`path`), seeded so it stands in the same
## places every run, and is only seen: nothing here collides, so the riding is the same
## with or without it. The graphics quality thins the trees and may take their shadows
## (the preset's `tree_share` and `prop_shadows`).

## A bend is where the lap turns faster than this (rad a metre).
const BEND_CURVATURE := 0.02
## Tyre stacks this far apart round a bend, this far beyond the road's edge (m).
const TYRE_SPACING := 1.0
const TYRE_MARGIN := 2.5
## Cones along the inside edge of a bend, this far apart (m).
const CONE_SPACING := 4.0

## The lap: a Path3D whose curve runs along the middle of the road.
@export var path: NodePath:
	set(value):
		path = value
		_build()
## Half the road's width (m): nothing stands on the road.
@export_range(1.0, 20.0, 0.5, "suffix:m") var road_half_width := 3.5:
	set(value):
		road_half_width = value
		_build()
## Trees at full quality, and how far from the lap's middle they stand (m, nearest and
## farthest).
@export_range(0, 2000) var tree_count := 180:
	set(value):
		tree_count = value
		_build()
@export var tree_band := Vector2(11.0, 60.0):
	set(value):
		tree_band = value
		_build()
## Where the scattering starts: another seed, another wood.
@export var layout_seed := 2015:
	set(value):
		layout_seed = value
		_build()

var _trees: MultiMeshInstance3D
var _tyres: MultiMeshInstance3D
var _cones: MultiMeshInstance3D


func _ready() -> void:
	_build()
	if not Engine.is_editor_hint():
		Graphics.applied.connect(_on_graphics_applied)
		_on_graphics_applied(Graphics.preset)


## Where every tree stands (global), in the order the graphics quality keeps them.
func tree_positions() -> PackedVector3Array:
	return PropMesh.laid_at(_trees)


## Where every tyre stack and cone stands (global).
func tyre_positions() -> PackedVector3Array:
	return PropMesh.laid_at(_tyres)


func cone_positions() -> PackedVector3Array:
	return PropMesh.laid_at(_cones)


## Trees shown now (the graphics quality's share of tree_count).
func trees_shown() -> int:
	return _trees.multimesh.visible_instance_count if _trees != null else 0


func _on_graphics_applied(preset: String) -> void:
	if _trees == null or not Graphics.PRESETS.has(preset):
		return
	var settings: Dictionary = Graphics.PRESETS[preset]
	var share: float = settings.tree_share
	_trees.multimesh.visible_instance_count = roundi(_trees.multimesh.instance_count * share)
	PropMesh.cast_shadows([_trees, _tyres, _cones], settings.prop_shadows)


func _build() -> void:
	if not is_inside_tree():
		return
	for child: Node in [_trees, _tyres, _cones]:
		if child != null:
			child.queue_free()
	_trees = null
	_tyres = null
	_cones = null
	var lap := get_node_or_null(path) as Path3D
	if lap == null or lap.curve == null or lap.curve.get_baked_length() <= 0.0:
		if not path.is_empty():
			push_warning("Trackside: %s is not a Path3D with a curve; nothing is laid" % path)
		return
	var line := _line_in_my_space(lap)
	var random := RandomNumberGenerator.new()
	random.seed = layout_seed
	_trees = _instances("Trees", TracksideProps.tree(), _tree_transforms(line, random))
	var bends := _bend_transforms(line)
	_tyres = _instances("TyreWalls", TracksideProps.tyre_stack(), bends[0])
	_cones = _instances("Cones", TracksideProps.cone(), bends[1])


## The lap's middle line as points a metre apart, in this node's space, on the ground.
func _line_in_my_space(lap: Path3D) -> PackedVector3Array:
	var to_me := global_transform.affine_inverse() * lap.global_transform
	var line := PackedVector3Array()
	var length := lap.curve.get_baked_length()
	for i in ceili(length):
		var point := to_me * lap.curve.sample_baked(float(i), true)
		line.append(Vector3(point.x, 0.0, point.z))
	return line


func _tree_transforms(line: PackedVector3Array, random: RandomNumberGenerator) -> Array:
	var bounds := AABB(line[0], Vector3.ZERO)
	for point in line:
		bounds = bounds.expand(point)
	bounds = bounds.grow(tree_band.y)
	var transforms := []
	var tries := 0
	while transforms.size() < tree_count and tries < tree_count * 40:
		tries += 1
		var at := Vector3(
			random.randf_range(bounds.position.x, bounds.end.x),
			0.0,
			random.randf_range(bounds.position.z, bounds.end.z)
		)
		var away := _distance_to(line, at)
		if away < tree_band.x or away > tree_band.y:
			continue
		var size := random.randf_range(0.75, 1.35)
		var basis := Basis(Vector3.UP, random.randf() * TAU).scaled(Vector3.ONE * size)
		transforms.append(Transform3D(basis, at))
	return transforms


## Tyre stacks round the outside of each bend and cones along its inside edge.
func _bend_transforms(line: PackedVector3Array) -> Array:
	var tyres := []
	var cones := []
	var n := line.size()
	var since_tyre := TYRE_SPACING
	var since_cone := CONE_SPACING
	for i in n:
		var ahead := (line[(i + 1) % n] - line[i]).normalized()
		var behind := (line[i] - line[(i - 1 + n) % n]).normalized()
		var turn := behind.signed_angle_to(ahead, Vector3.UP)
		since_tyre += 1.0
		since_cone += 1.0
		if absf(turn) < BEND_CURVATURE:
			continue
		# The lap's left (+y turn, anticlockwise seen from above) is the bend's inside.
		var left := Vector3.UP.cross(ahead).normalized()
		var inside := left if turn > 0.0 else -left
		if since_tyre >= TYRE_SPACING:
			since_tyre = 0.0
			var at := line[i] - inside * (road_half_width + TYRE_MARGIN)
			tyres.append(Transform3D(Basis(), at))
		if since_cone >= CONE_SPACING:
			since_cone = 0.0
			cones.append(Transform3D(Basis(), line[i] + inside * (road_half_width + 0.4)))
	return [tyres, cones]


static func _distance_to(line: PackedVector3Array, at: Vector3) -> float:
	var nearest := INF
	for point in line:
		nearest = minf(nearest, point.distance_squared_to(at))
	return sqrt(nearest)


func _instances(title: String, mesh: Mesh, transforms: Array) -> MultiMeshInstance3D:
	var instances := PropMesh.instances(title, mesh, transforms)
	add_child(instances)
	return instances
