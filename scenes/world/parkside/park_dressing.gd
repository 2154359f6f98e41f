@tool
class_name ParkDressing
extends Node3D
## What makes a walled square of ground a built skate park: a concrete floor poured in
## slabs under the walls and the pieces, a steel fence round the outside, floodlight masts
## at the corners and benches and bins for the onlookers between the wall and the fence.
## All of it is only seen: nothing here collides (the floor is drawn a few millimetres
## over the level's ground, which is what the tyres meet), so the riding is the same with
## or without it. The graphics quality may take the props' shadows (`prop_shadows`).

const SLAB_MATERIAL := preload("res://scenes/levels/materials/slab.tres")
## How far over the ground the floor is drawn (m): enough that it never flickers with the
## grass beneath, too little for a tyre to be seen sinking into it.
const FLOOR_RISE := 0.004
## Fence posts this far apart (m).
const POST_SPACING := 2.5
## Benches stand this far outside the walls (m), each with a bin beside it.
const BENCH_OUT := 0.75
const BIN_BESIDE := 1.3

## The walled square the park is ridden in (m, x and z, centred on this node).
@export var size := Vector2(60.0, 60.0):
	set(value):
		size = value
		_build()
## How far outside the walls the fence stands (m); the floor reaches it.
@export_range(0.5, 10.0, 0.1, "suffix:m") var fence_margin := 1.5:
	set(value):
		fence_margin = value
		_build()
## Benches along the +z side, spread evenly.
@export_range(0, 20) var bench_count := 4:
	set(value):
		bench_count = value
		_build()

var _floor: MeshInstance3D
var _posts: MultiMeshInstance3D
var _rails: MultiMeshInstance3D
var _lights: MultiMeshInstance3D
var _benches: MultiMeshInstance3D
var _bins: MultiMeshInstance3D


func _ready() -> void:
	_build()
	if not Engine.is_editor_hint():
		Graphics.applied.connect(_on_graphics_applied)
		_on_graphics_applied(Graphics.preset)


## The floor's extent (m, x and z): the walled square and the margin out to the fence.
func floor_size() -> Vector2:
	return size + Vector2.ONE * 2.0 * fence_margin


func post_positions() -> PackedVector3Array:
	return PropMesh.laid_at(_posts)


func floodlight_positions() -> PackedVector3Array:
	return PropMesh.laid_at(_lights)


func bench_positions() -> PackedVector3Array:
	return PropMesh.laid_at(_benches)


func _on_graphics_applied(preset: String) -> void:
	if Graphics.PRESETS.has(preset):
		var shadows: bool = Graphics.PRESETS[preset].prop_shadows
		PropMesh.cast_shadows([_posts, _rails, _lights, _benches, _bins], shadows)


func _build() -> void:
	if not is_inside_tree():
		return
	for child: Node in [_floor, _posts, _rails, _lights, _benches, _bins]:
		if is_instance_valid(child):
			child.queue_free()
	_floor = _floor_mesh()
	var fence := size / 2.0 + Vector2.ONE * fence_margin
	_posts = _instances("FencePosts", ParkProps.post(), _post_transforms(fence))
	_rails = _instances("FenceRails", ParkProps.rail(), _rail_transforms(fence))
	_lights = _instances("Floodlights", ParkProps.floodlight(), _light_transforms(fence))
	var benches := _bench_transforms()
	_benches = _instances("Benches", ParkProps.bench(), benches)
	var bins := []
	for bench: Transform3D in benches:
		bins.append(bench.translated(Vector3(BIN_BESIDE, 0.0, 0.0)))
	_bins = _instances("Bins", ParkProps.bin(), bins)


func _floor_mesh() -> MeshInstance3D:
	var plane := PlaneMesh.new()
	plane.size = floor_size()
	var mesh := MeshInstance3D.new()
	mesh.name = "Floor"
	mesh.mesh = plane
	mesh.material_override = SLAB_MATERIAL
	mesh.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	mesh.position.y = FLOOR_RISE
	add_child(mesh)
	return mesh


## The four corners of the fence (half extents `fence`), going round.
static func _corners(fence: Vector2) -> Array[Vector3]:
	return [
		Vector3(-fence.x, 0, -fence.y),
		Vector3(fence.x, 0, -fence.y),
		Vector3(fence.x, 0, fence.y),
		Vector3(-fence.x, 0, fence.y),
	]


func _post_transforms(fence: Vector2) -> Array:
	var transforms := []
	var corners := _corners(fence)
	for side in 4:
		var from := corners[side]
		var to := corners[(side + 1) % 4]
		var gaps := maxi(1, ceili(from.distance_to(to) / POST_SPACING))
		for i in gaps:
			transforms.append(Transform3D(Basis(), from.lerp(to, float(i) / gaps)))
	return transforms


## Each side's rails: the metre-long rail stretched along the side at each rail height.
func _rail_transforms(fence: Vector2) -> Array:
	var transforms := []
	var corners := _corners(fence)
	for side in 4:
		var from := corners[side]
		var to := corners[(side + 1) % 4]
		var along := to - from
		var basis := Basis(Vector3.UP, -atan2(along.z, along.x))
		basis = basis.scaled_local(Vector3(along.length(), 1.0, 1.0))
		for height in ParkProps.RAIL_HEIGHTS:
			transforms.append(Transform3D(basis, (from + to) / 2.0 + Vector3.UP * height))
	return transforms


## A mast a metre outside each corner of the fence, its lamps turned to the middle.
func _light_transforms(fence: Vector2) -> Array:
	var transforms := []
	for corner in _corners(fence + Vector2.ONE):
		var facing := Basis.looking_at(-Vector3(corner.x, 0.0, corner.z), Vector3.UP)
		transforms.append(Transform3D(facing, corner))
	return transforms


## Benches along the +z side between the wall and the fence, facing the park.
func _bench_transforms() -> Array:
	var transforms := []
	var z := size.y / 2.0 + BENCH_OUT
	for i in bench_count:
		var x := size.x * ((i + 0.5) / bench_count - 0.5) * 0.8
		transforms.append(Transform3D(Basis(), Vector3(x, 0.0, z)))
	return transforms


func _instances(title: String, mesh: Mesh, transforms: Array) -> MultiMeshInstance3D:
	var instances := PropMesh.instances(title, mesh, transforms)
	add_child(instances)
	return instances
