class_name BikeWheels
extends RefCounted
## The drawn wheels and brakes, sized by the simulated wheel: a tyre on its rim, cast
## spokes (a road bike's) or laced wire spokes (a dirt bike's), brake discs that turn with
## the wheel (one or two up front as the bodywork says, one at the back on the right, the
## chain's side being the left), and a caliper on each disc that stays with the fork's lower
## leg or the swingarm. The spokes of a wheel are one mesh: one draw instead of a dozen.

const WHEELS: Array[int] = [BikeSimulation.REAR_WHEEL, BikeSimulation.FRONT_WHEEL]
## The tyre and rim as shares of the simulated wheel's radius.
const TYRE_INNER := 0.75
const RIM := Vector2(0.63, 0.78)
## A brake disc's radius and the carrier's in its middle, as shares of the wheel's radius.
const DISC := 0.5
const DISC_CARRIER := 0.3
## How far out from the wheel's middle (m) the discs and the calipers over them sit.
const DISC_OUT := 0.075
const CALIPER_OUT := 0.088
## Wire spokes per wheel, laced from the hub's two flanges (m either side) to the rim.
const WIRE_SPOKES := 24
const FLANGE := 0.035
const CAST_SPOKES := 5


## Adds the wheels and their brakes to `parts` for a wheel of `radius` (m) and the wheels
## and discs `bodywork` (BikeBodywork) names.
static func build(parts: BikeParts, radius: float, bodywork: BikeBodywork) -> void:
	var frame := parts.frame()
	for body in WHEELS:
		var hub := frame.bike_of(frame.rest_of(body).origin)
		var facing := BikeParts.basis_with_y(frame.right(), Vector3.UP)
		var tyre := TorusMesh.new()
		tyre.inner_radius = TYRE_INNER * radius
		tyre.outer_radius = radius
		tyre.rings = 48
		parts.add(body, tyre, "tyre", Transform3D(facing, frame.world_of(hub)))
		var rim := TorusMesh.new()
		rim.inner_radius = RIM.x * radius
		rim.outer_radius = RIM.y * radius
		parts.add(body, rim, "rim", Transform3D(facing, frame.world_of(hub)))
		parts.disc(body, hub, 0.05, 0.16 if bodywork.wheels == "cast" else 2.0 * FLANGE, "metal")
		var spokes := _wire_spokes(radius) if bodywork.wheels == "spoked" else _cast_spokes(radius)
		# The spokes make the wheel's turning visible.
		parts.add(body, spokes, "rim", Transform3D(frame.basis(), frame.world_of(hub)))
		var front := body == BikeSimulation.FRONT_WHEEL
		var sides: Array[float] = [1.0]
		if front and bodywork.front_discs == 2:
			sides = [-1.0, 1.0]
		elif front and bodywork.front_discs == 0:
			sides = []
		for side in sides:
			_brake(parts, body, hub, radius, side)


## A disc on `wheel` at `hub` (bike frame) on `side` (−1 left, 1 right), and its caliper on
## the part that carries the wheel: behind the fork leg up front, ahead of the axle on top
## of the swingarm at the back.
static func _brake(parts: BikeParts, wheel: int, hub: Vector3, radius: float, side: float) -> void:
	var out := Vector3(0, 0, side * DISC_OUT)
	parts.disc(wheel, hub + out, DISC * radius, 0.006, "metal")
	parts.disc(wheel, hub + out * 1.04, DISC_CARRIER * radius, 0.008, "rim")
	var front := wheel == BikeSimulation.FRONT_WHEEL
	var carrier := BikeSimulation.FORK_LOWER if front else BikeSimulation.SWINGARM
	var angle := deg_to_rad(150.0 if front else 60.0)
	var on_disc := Vector3(cos(angle), sin(angle), 0.0) * (DISC - 0.06) * radius
	var caliper := hub + on_disc + Vector3(0, 0, side * CALIPER_OUT)
	parts.box(carrier, caliper, Vector3(0.05, 0.1, 0.035), angle - PI / 2.0, "caliper")


## Five broad cast spokes, in the wheel's plane (x forward, y up; as a mesh in Godot's
## axes, x right and z backwards, about the hub).
static func _cast_spokes(radius: float) -> Mesh:
	var tool := SurfaceTool.new()
	tool.begin(Mesh.PRIMITIVE_TRIANGLES)
	var spoke := BoxMesh.new()
	spoke.size = Vector3(0.02, 0.67 * radius, 0.035)
	for i in CAST_SPOKES:
		var turn := Basis(Vector3.RIGHT, TAU * i / CAST_SPOKES)
		var middle := turn * Vector3(0, radius / 3.0, 0)
		tool.append_from(spoke, 0, Transform3D(turn, middle))
	return tool.commit()


## Wire spokes laced from the hub's flanges to the rim, alternately from each flange and
## each leaving its flange a little off the radial, as a tangent-laced wheel's do.
static func _wire_spokes(radius: float) -> Mesh:
	var tool := SurfaceTool.new()
	tool.begin(Mesh.PRIMITIVE_TRIANGLES)
	var wire := CylinderMesh.new()
	wire.top_radius = 0.004
	wire.bottom_radius = 0.004
	wire.radial_segments = 4
	wire.rings = 1
	for i in WIRE_SPOKES:
		var side := FLANGE if i % 2 == 0 else -FLANGE
		var at_hub := Basis(Vector3.RIGHT, TAU * (i + 1.5) / WIRE_SPOKES) * Vector3(0, 0.05, 0)
		var at_rim := Basis(Vector3.RIGHT, TAU * i / WIRE_SPOKES) * Vector3(0, RIM.x * radius, 0)
		var from := at_hub + Vector3(side, 0, 0)
		wire.height = from.distance_to(at_rim)
		var along := BikeParts.basis_with_y((at_rim - from).normalized(), Vector3.RIGHT)
		tool.append_from(wire, 0, Transform3D(along, (from + at_rim) / 2.0))
	return tool.commit()
