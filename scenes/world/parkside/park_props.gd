class_name ParkProps
extends RefCounted
## The meshes ParkDressing builds a skate park from, low-poly in the manner of Kenney's
## kits: a fence's post and rail, a floodlight mast, a bench and a bin. Built once
## (`PropMesh`) and shared by every instance.

const GALVANISED := Color(0.62, 0.64, 0.66)
const MAST_GREY := Color(0.42, 0.43, 0.45)
const LAMP := Color(1.0, 0.96, 0.86)
const WOOD := Color(0.5, 0.33, 0.18)
const CONCRETE := Color(0.55, 0.54, 0.51)
const BIN_GREEN := Color(0.12, 0.26, 0.16)

## The fence's height and its rails' heights (m).
const FENCE_HEIGHT := 1.2
const RAIL_HEIGHTS: Array[float] = [0.45, 1.15]
## A mast's height (m): the lamps hang over the park from there.
const MAST_HEIGHT := 9.0

static var _made := {}


## A fence post, standing on the ground.
static func post() -> Mesh:
	if not _made.has("post"):
		_made["post"] = PropMesh.joined(
			[
				[
					PropMesh.cylinder(0.035, 0.035, FENCE_HEIGHT, 6),
					Vector3(0, FENCE_HEIGHT / 2.0, 0),
					GALVANISED
				]
			]
		)
	return _made["post"]


## A rail a metre long along x, centred on the origin (instances stretch it along a side).
static func rail() -> Mesh:
	if not _made.has("rail"):
		_made["rail"] = PropMesh.joined(
			[[PropMesh.box(Vector3(1.0, 0.05, 0.05)), Vector3.ZERO, GALVANISED]]
		)
	return _made["rail"]


## A floodlight mast: a pole, a crossbar and two lamps facing -z, tipped down at the park.
static func floodlight() -> Mesh:
	if not _made.has("floodlight"):
		var tipped := Basis(Vector3.RIGHT, deg_to_rad(-35.0))
		var parts := [
			[
				PropMesh.cylinder(0.09, 0.15, MAST_HEIGHT, 8),
				Vector3(0, MAST_HEIGHT / 2.0, 0),
				MAST_GREY
			],
			[PropMesh.box(Vector3(1.6, 0.08, 0.08)), Vector3(0, MAST_HEIGHT, 0), MAST_GREY],
		]
		for x: float in [-0.5, 0.5]:
			var at := Vector3(x, MAST_HEIGHT + 0.1, -0.15)
			parts.append(
				[PropMesh.box(Vector3(0.55, 0.4, 0.2)), Transform3D(tipped, at), MAST_GREY]
			)
			var face := Transform3D(tipped, at + tipped * Vector3(0, 0, -0.105))
			parts.append([PropMesh.box(Vector3(0.47, 0.32, 0.01)), face, LAMP, true])
		_made["floodlight"] = PropMesh.joined(parts)
	return _made["floodlight"]


## A bench facing -z: two concrete feet, a wooden seat and a backrest.
static func bench() -> Mesh:
	if not _made.has("bench"):
		var parts := []
		for x: float in [-0.7, 0.7]:
			parts.append([PropMesh.box(Vector3(0.12, 0.42, 0.4)), Vector3(x, 0.21, 0), CONCRETE])
		parts.append([PropMesh.box(Vector3(1.8, 0.05, 0.42)), Vector3(0, 0.445, 0), WOOD])
		var leaning := Basis(Vector3.RIGHT, deg_to_rad(-12.0))
		var back := Transform3D(leaning, Vector3(0, 0.7, 0.2))
		parts.append([PropMesh.box(Vector3(1.8, 0.3, 0.04)), back, WOOD])
		_made["bench"] = PropMesh.joined(parts)
	return _made["bench"]


## A litter bin.
static func bin() -> Mesh:
	if not _made.has("bin"):
		_made["bin"] = PropMesh.joined(
			[[PropMesh.cylinder(0.24, 0.21, 0.8, 10), Vector3(0, 0.4, 0), BIN_GREEN]]
		)
	return _made["bin"]
