class_name RiderMesh
extends RefCounted
## The rider's skin, generated in code: each part is a tube of rings along a chain of
## joints (a leg from hip to knee to ankle, the torso from the hips to the neck), with
## rounded ends. Every ring is bound to the bone of its segment, and the rings near an
## inner joint are shared between the two bones either side of it, so a knee or an elbow
## bends smoothly instead of breaking into two rods. One surface, in the skeleton's space
## at rest, each part's look (jacket, trousers, boots, gloves) in its vertices' colour: a
## single draw of one skinned mesh costs the software renderer far less than one a look.

## Vertices around a ring, rings along a segment, and rings in each rounded end.
const RING_VERTICES := 14
const SEGMENT_RINGS := 6
const CAP_RINGS := 3
## How far either side of an inner joint (as a share of the tube's radius there) the
## skin is shared between the two bones meeting at it.
const BLEND_RADII := 1.2

## Colours that replace a look's own (BikeLooks.COLOURS), by look: the rider's jacket in
## the colours of the bike ridden.
var colours := {}

## The triangles collected so far, and how many vertices they have.
var _tool := SurfaceTool.new()
var _count := 0


func _init() -> void:
	_tool.set_skin_weight_count(SurfaceTool.SKIN_4_WEIGHTS)
	_tool.begin(Mesh.PRIMITIVE_TRIANGLES)


## A tube of `look` through `joints` (skeleton space, two or more), `radii[i]` thick at
## joint i, segment i bound to bone `bones[i]`; `widen` stretches it sideways (along
## `side`), as a torso is wider than it is deep.
func add_tube(
	look: String,
	joints: PackedVector3Array,
	radii: PackedFloat32Array,
	bones: PackedInt32Array,
	side: Vector3,
	widen := 1.0
) -> void:
	var rings: Array[Dictionary] = []
	var first_along := (joints[1] - joints[0]).normalized()
	_add_cap(rings, joints[0], -first_along, first_along, radii[0], bones[0])
	for segment in joints.size() - 1:
		var a := joints[segment]
		var b := joints[segment + 1]
		var along := (b - a).normalized()
		var last := segment == joints.size() - 2
		for i in SEGMENT_RINGS + (1 if last else 0):
			var t := float(i) / SEGMENT_RINGS
			var centre := a.lerp(b, t)
			var radius := lerpf(radii[segment], radii[segment + 1], t)
			var ring := {centre = centre, along = along, radius = radius}
			if i == 0 and segment > 0:
				ring.merge(_mitre(joints[segment - 1], a, b), true)
			elif _inside_a_bend(joints, radii, segment, centre):
				continue
			ring.merge(_binding(joints, radii, bones, segment, centre))
			rings.append(ring)
	var last_along := (joints[-1] - joints[-2]).normalized()
	var end_caps: Array[Dictionary] = []
	_add_cap(end_caps, joints[-1], last_along, last_along, radii[-1], bones[-1])
	end_caps.reverse()
	rings.append_array(end_caps)
	_emit(look, rings, side, widen)


## The finished mesh, drawn with `material` (which takes its colour from the vertices).
func build(material: Material) -> ArrayMesh:
	var mesh := _tool.commit()
	mesh.surface_set_material(0, material)
	return mesh


## The ring at an inner joint `at`, between segments from `before` and to `after`: in the
## plane that halves the bend, stretched across the bend so both tubes meet it whole (a
## mitre joint, as a bent pipe is cut).
static func _mitre(before: Vector3, at: Vector3, after: Vector3) -> Dictionary:
	var incoming := (at - before).normalized()
	var outgoing := (after - at).normalized()
	var halfway := (incoming + outgoing).normalized()
	var bend := outgoing - incoming
	if bend.length() < 1e-4:
		return {}
	var half_angle := incoming.angle_to(outgoing) / 2.0
	return {
		along = halfway,
		bend = (bend - halfway * bend.dot(halfway)).normalized(),
		stretch = 1.0 / maxf(cos(half_angle), 0.3),
	}


## Whether a ring at `centre` on `segment` would cut through the tube on the inside of the
## bend at either end of the segment (closer to an inner joint than the mitre reaches).
static func _inside_a_bend(
	joints: PackedVector3Array, radii: PackedFloat32Array, segment: int, centre: Vector3
) -> bool:
	for joint: int in [segment, segment + 1]:
		if joint == 0 or joint == joints.size() - 1:
			continue
		var incoming := (joints[joint] - joints[joint - 1]).normalized()
		var outgoing := (joints[joint + 1] - joints[joint]).normalized()
		var reach := radii[joint] * tan(minf(incoming.angle_to(outgoing) / 2.0, 1.2))
		if centre.distance_to(joints[joint]) < reach * 1.1 + 1e-4:
			return true
	return false


## The bones a ring at `point` on `segment` is bound to: the segment's own bone, shared
## with the neighbouring segment's bone within BLEND_RADII radii of an inner joint.
static func _binding(
	joints: PackedVector3Array,
	radii: PackedFloat32Array,
	bones: PackedInt32Array,
	segment: int,
	point: Vector3
) -> Dictionary:
	var own := bones[segment]
	for joint: int in [segment, segment + 1]:
		if joint == 0 or joint == joints.size() - 1:
			continue
		var reach := radii[joint] * BLEND_RADII
		var distance := point.distance_to(joints[joint])
		if distance >= reach:
			continue
		var other := bones[joint - 1] if joint == segment else bones[joint]
		# Half and half at the joint, all the segment's own bone at `reach` from it.
		var own_share := 0.5 + 0.5 * distance / reach
		return {
			bones = PackedInt32Array([own, other, 0, 0]), weights = [own_share, 1.0 - own_share]
		}
	return {bones = PackedInt32Array([own, 0, 0, 0]), weights = [1.0, 0.0]}


## Rings rounding off a tube's end at `centre`, bulging along `outward`, the tip first;
## `along` is the tube's direction, which every ring's frame shares so the strip never twists.
static func _add_cap(
	rings: Array[Dictionary],
	centre: Vector3,
	outward: Vector3,
	along: Vector3,
	radius: float,
	bone: int
) -> void:
	var caps: Array[Dictionary] = []
	for i in range(CAP_RINGS, 0, -1):
		var angle := PI / 2.0 * i / (CAP_RINGS + 1)
		(
			caps
			. append(
				{
					centre = centre + outward * radius * sin(angle),
					along = along,
					radius = radius * cos(angle),
					bones = PackedInt32Array([bone, 0, 0, 0]),
					weights = [1.0, 0.0],
				}
			)
		)
	# A ring of zero radius closes the tip.
	(
		caps
		. push_front(
			{
				centre = centre + outward * radius,
				along = along,
				radius = 0.0,
				bones = PackedInt32Array([bone, 0, 0, 0]),
				weights = [1.0, 0.0],
			}
		)
	)
	rings.append_array(caps)


## Writes `rings` (in order along the tube) as a strip of quads in `look`'s colour.
func _emit(look: String, rings: Array[Dictionary], side: Vector3, widen: float) -> void:
	var tool := _tool
	var first := _count
	var colour: Color = colours.get(look, BikeLooks.COLOURS[look])
	for ring: Dictionary in rings:
		var along := (ring.along as Vector3).normalized()
		var across := side - along * side.dot(along)
		if across.length() < 1e-3:
			across = Vector3.BACK - along * along.z
		across = across.normalized()
		var up := along.cross(across)
		var ring_weights: Array = ring.weights
		var bend: Vector3 = ring.get("bend", Vector3.ZERO)
		var stretch: float = ring.get("stretch", 1.0)
		for k in RING_VERTICES:
			var angle := TAU * k / RING_VERTICES
			var radial := across * cos(angle) * widen + up * sin(angle)
			radial += bend * radial.dot(bend) * (stretch - 1.0)
			tool.set_color(colour)
			tool.set_normal((across * cos(angle) / widen + up * sin(angle)).normalized())
			tool.set_bones(ring.bones)
			tool.set_weights(PackedFloat32Array([ring_weights[0], ring_weights[1], 0.0, 0.0]))
			tool.add_vertex((ring.centre as Vector3) + radial * float(ring.radius))
	for r in rings.size() - 1:
		for k in RING_VERTICES:
			var a := first + r * RING_VERTICES + k
			var b := first + r * RING_VERTICES + (k + 1) % RING_VERTICES
			var c := a + RING_VERTICES
			var d := b + RING_VERTICES
			for index: int in [a, c, b, b, c, d]:
				tool.add_index(index)
	_count = first + rings.size() * RING_VERTICES
