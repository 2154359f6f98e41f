class_name TracksideProps
extends RefCounted
## The meshes Trackside stands beside a track, low-poly in the manner of Kenney's kits:
## a conifer, a stack of tyres, a traffic cone. Built once (`PropMesh`) and shared by
## every instance.

const BARK := Color(0.36, 0.25, 0.17)
const NEEDLES := Color(0.11, 0.23, 0.1)
const RUBBER := Color(0.08, 0.08, 0.09)
const CONE_ORANGE := Color(0.95, 0.38, 0.08)
const CONE_WHITE := Color(0.92, 0.92, 0.9)

static var _made := {}


## A conifer about 6 m tall: a trunk and two tiers of needles.
static func tree() -> Mesh:
	if not _made.has("tree"):
		var trunk := PropMesh.cylinder(0.14, 0.2, 1.6, 6)
		var lower := PropMesh.cylinder(0.0, 1.9, 3.2, 7)
		var upper := PropMesh.cylinder(0.0, 1.3, 2.6, 7)
		_made["tree"] = (
			PropMesh
			. joined(
				[
					[trunk, Vector3(0, 0.8, 0), BARK],
					[lower, Vector3(0, 2.9, 0), NEEDLES],
					[upper, Vector3(0, 4.4, 0), NEEDLES.lightened(0.08)],
				]
			)
		)
	return _made["tree"]


## Three tyres stacked, as tyre walls round a bend are built.
static func tyre_stack() -> Mesh:
	if not _made.has("tyres"):
		var parts := []
		for level in 3:
			var tyre := TorusMesh.new()
			tyre.inner_radius = 0.2
			tyre.outer_radius = 0.42
			tyre.rings = 12
			tyre.ring_segments = 6
			parts.append([tyre, Vector3(0, 0.11 + 0.22 * level, 0), RUBBER])
		_made["tyres"] = PropMesh.joined(parts)
	return _made["tyres"]


## A traffic cone on its square foot, with a white band.
static func cone() -> Mesh:
	if not _made.has("cone"):
		var foot := PropMesh.box(Vector3(0.36, 0.03, 0.36))
		var body := PropMesh.cylinder(0.0, 0.15, 0.5, 10)
		var band := PropMesh.cylinder(0.075, 0.095, 0.08, 10)
		_made["cone"] = (
			PropMesh
			. joined(
				[
					[foot, Vector3(0, 0.015, 0), CONE_ORANGE],
					[body, Vector3(0, 0.28, 0), CONE_ORANGE],
					[band, Vector3(0, 0.33, 0), CONE_WHITE],
				]
			)
		)
	return _made["cone"]
