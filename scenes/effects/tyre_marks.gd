class_name TyreMarks
extends MeshInstance3D
## Dark marks on the ground where a tyre slides (a locked wheel under the brake, a wheel
## spinning under the throttle, a tyre sliding sideways) or works near its grip (a hard
## stop, a hard turn), and a puff of smoke from it when it slides hard. Read every frame
## from the simulation: each tyre's contact and how fast it slides
## (`BikeSimulation.get_tyres()`), and how much of the tyres' friction circle the bike's
## deceleration and lean ask for (its speed's change and its lean, against the bike's
## `tyre_friction`): the simulated tyres grip without creeping until they slide, so a
## stop at 0.9 g marks the road through the grip it uses, as a real tyre's creep does.
## The newest MAX_SEGMENTS pieces of mark are kept; the oldest go first.

## Sliding faster than this (m/s) marks the ground; faster than SMOKE_SLIP it smokes.
const MARK_SLIP := 1.2
const SMOKE_SLIP := 3.0
## Using more of the friction circle than this marks a grounded tyre, darker towards all
## of it.
const MARK_GRIP := 0.8
## How quickly the measured deceleration follows the speed's change (s).
const DECELERATION_SMOOTHING := 0.15
## A piece of mark is laid each time the tyre has moved this far (m).
const SEGMENT := 0.2
const MAX_SEGMENTS := 1500
const WIDTH := 0.11
## Marks lie this far above the ground (m), so they never flicker into it.
const LIFT := 0.012
## Opacity of a mark at the least slide that marks, and at a hard slide.
const FAINT := 0.25
const DARK := 0.8
const RUBBER := Color(0.04, 0.04, 0.045)

## The bike whose tyres mark the ground.
@export var bike: BikeSimulation

var _last: Array = [null, null]
## Each piece of mark as four corners and an opacity, oldest first.
var _pieces: Array[PackedVector3Array] = []
var _opacity: PackedFloat32Array = []
var _changed := false
var _smoke: Array[CPUParticles3D] = []
var _slowing := StepRate.new()
var _deceleration := 0.0
## The bike's tyre friction, read once (the bike does not change within a ride).
var _friction := NAN


func _ready() -> void:
	mesh = ArrayMesh.new()
	cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	var material := StandardMaterial3D.new()
	material.vertex_color_use_as_albedo = true
	material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	material.cull_mode = BaseMaterial3D.CULL_DISABLED
	material.roughness = 0.95
	material_override = material
	for wheel in 2:
		var smoke := Puffs.cloud(Puffs.SMOKE)
		smoke.name = "Smoke%d" % wheel
		add_child(smoke)
		_smoke.append(smoke)


## Pieces of mark on the ground now.
func piece_count() -> int:
	return _pieces.size()


## Whether wheel `wheel` (0 rear, 1 front) smokes now.
func smoking(wheel: int) -> bool:
	return _smoke[wheel].emitting


## Forgets every mark (a new ride on the same ground).
func clear() -> void:
	_pieces.clear()
	_opacity.clear()
	_last = [null, null]
	_changed = true


func _physics_process(_delta: float) -> void:
	if bike == null or not bike.is_running():
		_slowing.reset()
		return
	var now := _slowing.falling(bike, bike.get_speed())
	if not is_nan(now):
		var share := minf(_slowing.elapsed / DECELERATION_SMOOTHING, 1.0)
		_deceleration += (now - _deceleration) * share
	var grounded: Array[bool] = [bike.is_rear_wheel_grounded(), bike.is_front_wheel_grounded()]
	follow(bike.get_tyres(), grounded, grip_in_use(_deceleration, bike.get_lean()))


## The share of the tyres' friction circle that braking at `deceleration` (m/s²) while
## leaning `lean` (rad) asks for: a steady turn's sideways pull is g·tan(lean).
func grip_in_use(deceleration: float, lean: float) -> float:
	var g := bike.get_gravity() if bike != null else 0.0
	if g <= 0.0:
		return 0.0
	if is_nan(_friction):
		_friction = _tyre_friction()
	var sideways := g * tan(clampf(absf(lean), 0.0, 1.4))
	return Vector2(deceleration, sideways).length() / (_friction * g)


func _tyre_friction() -> float:
	var description: BikeDescription = bike.bike if bike != null else null
	if description == null:
		description = BikeDescription.new()
	return maxf(float(description.get(&"tyre_friction")), 0.05)


## Marks and smokes for tyres at `tyres` (contact, and slide speed as the fourth number;
## rear then front) that are on the ground or not (`grounded`), while the bike uses
## `grip` of the friction circle.
func follow(tyres: Array[Vector4], grounded: Array[bool], grip := 0.0) -> void:
	for wheel in mini(tyres.size(), 2):
		var tyre := tyres[wheel]
		var at := Vector3(tyre.x, tyre.y + LIFT, tyre.z)
		var slide := tyre.w if grounded[wheel] else 0.0
		_smoke[wheel].global_position = at
		_smoke[wheel].emitting = slide > SMOKE_SLIP
		var working := grounded[wheel] and grip > MARK_GRIP
		if slide <= MARK_SLIP and not working:
			_last[wheel] = null
			continue
		if _last[wheel] == null:
			_last[wheel] = at
			continue
		var from: Vector3 = _last[wheel]
		if from.distance_to(at) < SEGMENT:
			continue
		var sliding := clampf((slide - MARK_SLIP) / (SMOKE_SLIP * 2.0), 0.0, 1.0)
		var gripping := clampf((grip - MARK_GRIP) / (1.0 - MARK_GRIP), 0.0, 1.0)
		var strength := maxf(sliding, gripping)
		_add_piece(from, at, lerpf(FAINT, DARK, strength))
		_last[wheel] = at
	if _changed:
		_rebuild()


func _add_piece(from: Vector3, to: Vector3, opacity: float) -> void:
	var across := (to - from).cross(Vector3.UP).normalized() * WIDTH / 2.0
	_pieces.append(PackedVector3Array([from - across, from + across, to + across, to - across]))
	_opacity.append(opacity)
	if _pieces.size() > MAX_SEGMENTS:
		_pieces.pop_front()
		_opacity.remove_at(0)
	_changed = true


func _rebuild() -> void:
	_changed = false
	var array_mesh := mesh as ArrayMesh
	array_mesh.clear_surfaces()
	if _pieces.is_empty():
		return
	var vertices := PackedVector3Array()
	var colours := PackedColorArray()
	var normals := PackedVector3Array()
	for i in _pieces.size():
		var quad := _pieces[i]
		var colour := Color(RUBBER, _opacity[i])
		for corner: int in [0, 1, 2, 0, 2, 3]:
			vertices.append(to_local(quad[corner]))
			colours.append(colour)
			normals.append(Vector3.UP)
	var arrays := []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = vertices
	arrays[Mesh.ARRAY_NORMAL] = normals
	arrays[Mesh.ARRAY_COLOR] = colours
	array_mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
