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
## A mark fades in over its first FADE_PIECES pieces and out over its last, and its edges
## are soft (the rubber is laid thickest in the middle of the contact patch). The newest
## MAX_SEGMENTS pieces of mark are kept; the oldest go first.

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
## Pieces over which a mark fades in at its start and out at its end.
const FADE_PIECES := 4

## The bike whose tyres mark the ground.
@export var bike: BikeSimulation

var _last: Array = [null, null]
## Each piece of mark as four corners and its opacity where it starts and where it ends
## (a mark's pieces meet at the same opacity), oldest first; `_serial` numbers them, so a
## mark's pieces are found however many old ones have gone since.
var _pieces: Array[PackedVector3Array] = []
var _start_opacity: PackedFloat32Array = []
var _opacity: PackedFloat32Array = []
var _first_serial := 0
## Per wheel: the serial numbers of the mark it is laying (empty: none).
var _run: Array[PackedInt64Array] = [PackedInt64Array(), PackedInt64Array()]
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
	material.albedo_texture = _soft_edges()
	material_override = material
	for wheel in 2:
		var smoke := Puffs.cloud(Puffs.SMOKE)
		smoke.name = "Smoke%d" % wheel
		add_child(smoke)
		_smoke.append(smoke)


## Pieces of mark on the ground now.
func piece_count() -> int:
	return _pieces.size()


## Piece `index`'s (oldest first) opacity where it starts and where it ends.
func piece_opacity(index: int) -> Vector2:
	return Vector2(_start_opacity[index], _opacity[index])


## Whether wheel `wheel` (0 rear, 1 front) smokes now.
func smoking(wheel: int) -> bool:
	return _smoke[wheel].emitting


## Forgets every mark (a new ride on the same ground).
func clear() -> void:
	_pieces.clear()
	_start_opacity.clear()
	_opacity.clear()
	_run = [PackedInt64Array(), PackedInt64Array()]
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
			_end_run(wheel)
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
		_add_piece(wheel, from, at, lerpf(FAINT, DARK, strength))
		_last[wheel] = at
	if _changed:
		_rebuild()


func _add_piece(wheel: int, from: Vector3, to: Vector3, opacity: float) -> void:
	var across := (to - from).cross(Vector3.UP).normalized() * WIDTH / 2.0
	var run := _run[wheel]
	var fade_in := minf(float(run.size() + 1) / FADE_PIECES, 1.0)
	var previous := _index_of(run[-1]) if not run.is_empty() else -1
	_pieces.append(PackedVector3Array([from - across, from + across, to + across, to - across]))
	_start_opacity.append(_opacity[previous] if previous >= 0 else 0.0)
	_opacity.append(opacity * fade_in)
	run.append(_first_serial + _pieces.size() - 1)
	if _pieces.size() > MAX_SEGMENTS:
		_pieces.pop_front()
		_start_opacity.remove_at(0)
		_opacity.remove_at(0)
		_first_serial += 1
	_changed = true


## The wheel's mark ended: its last pieces fade out to nothing at its end.
func _end_run(wheel: int) -> void:
	var run := _run[wheel]
	var count := mini(run.size(), FADE_PIECES)
	for back in count:
		var index := _index_of(run[run.size() - 1 - back])
		if index < 0:
			break
		_opacity[index] *= float(back) / count
		_start_opacity[index] *= float(back + 1) / count
		_changed = true
	_run[wheel] = PackedInt64Array()


## Where piece `serial` is in `_pieces` now (-1: it has gone).
func _index_of(serial: int) -> int:
	var index := serial - _first_serial
	return index if index >= 0 and index < _pieces.size() else -1


## A strip's texture across the mark: opaque in the middle, fading to nothing at both
## edges.
static func _soft_edges() -> GradientTexture2D:
	var gradient := Gradient.new()
	gradient.offsets = PackedFloat32Array([0.0, 0.3, 0.7, 1.0])
	gradient.colors = PackedColorArray(
		[Color(1, 1, 1, 0), Color(1, 1, 1, 1), Color(1, 1, 1, 1), Color(1, 1, 1, 0)]
	)
	var texture := GradientTexture2D.new()
	texture.gradient = gradient
	texture.width = 32
	texture.height = 1
	return texture


func _rebuild() -> void:
	_changed = false
	var array_mesh := mesh as ArrayMesh
	array_mesh.clear_surfaces()
	if _pieces.is_empty():
		return
	var vertices := PackedVector3Array()
	var colours := PackedColorArray()
	var normals := PackedVector3Array()
	var uvs := PackedVector2Array()
	# Corners 0 and 1 are where a piece starts, 2 and 3 where it ends; 0 and 3 on one edge.
	var across := [0.0, 1.0, 1.0, 0.0]
	for i in _pieces.size():
		var quad := _pieces[i]
		var opacity := [_start_opacity[i], _start_opacity[i], _opacity[i], _opacity[i]]
		for corner: int in [0, 1, 2, 0, 2, 3]:
			vertices.append(to_local(quad[corner]))
			colours.append(Color(RUBBER, opacity[corner]))
			normals.append(Vector3.UP)
			uvs.append(Vector2(across[corner], 0.5))
	var arrays := []
	arrays.resize(Mesh.ARRAY_MAX)
	arrays[Mesh.ARRAY_VERTEX] = vertices
	arrays[Mesh.ARRAY_NORMAL] = normals
	arrays[Mesh.ARRAY_COLOR] = colours
	arrays[Mesh.ARRAY_TEX_UV] = uvs
	array_mesh.add_surface_from_arrays(Mesh.PRIMITIVE_TRIANGLES, arrays)
