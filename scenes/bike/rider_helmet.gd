class_name RiderHelmet
extends RefCounted
## The rider's helmet on the head bone (-z forward, y up), a shell a little longer than it is
## wide with a stripe over the crown in the bike's paint, so it reads as a helmet from
## behind, where the chase camera sees it, and not as a ball. A road helmet has a rounded
## chin bar, a dark glossy visor and a small spoiler; a motocross helmet a long chin bar
## jutting forward, a peak over the eye port and goggles on a strap instead of a visor.

## The shell's radius (m): an adult's head and the shell's foam.
const RADIUS := 0.135
## How much longer front to back than across.
const LENGTH := 1.08
## The stripe's share of the shell's width.
const STRIPE_WIDTH := 0.3


## The helmet's pieces for `gear` (RiderSkin.ROAD or MOTOCROSS) as [mesh, look, transform]
## each; `look` "paint" is the bike's colour.
static func pieces(gear := RiderSkin.ROAD) -> Array:
	var shell_and_stripe := _shell()
	if gear == RiderSkin.MOTOCROSS:
		return shell_and_stripe + _motocross_face()
	return shell_and_stripe + _road_face()


## The shell, and the stripe over its crown.
static func _shell() -> Array:
	var shell := SphereMesh.new()
	shell.radius = RADIUS
	shell.height = RADIUS * 2.0
	var stripe := SphereMesh.new()
	stripe.radius = RADIUS * 1.012
	stripe.height = RADIUS * 1.012
	stripe.is_hemisphere = true
	var longer := Basis.from_scale(Vector3(1.0, 1.0, LENGTH))
	return [
		[shell, "helmet", Transform3D(longer, Vector3.ZERO)],
		[
			stripe,
			"paint",
			Transform3D(longer.scaled(Vector3(STRIPE_WIDTH, 1.0, 1.0)), Vector3.ZERO)
		],
	]


## A road helmet's chin bar, visor and spoiler.
static func _road_face() -> Array:
	var chin := SphereMesh.new()
	chin.radius = 0.075
	chin.height = 0.15
	var visor := SphereMesh.new()
	visor.radius = 0.5
	visor.height = 1.0
	var spoiler := BoxMesh.new()
	spoiler.size = Vector3(0.11, 0.018, 0.05)
	return [
		[
			chin,
			"helmet",
			Transform3D(Basis.from_scale(Vector3(1.35, 0.75, 0.9)), Vector3(0, -0.075, -0.07))
		],
		[
			visor,
			"visor",
			Transform3D(Basis.from_scale(Vector3(0.21, 0.1, 0.11)), Vector3(0, 0.005, -0.095))
		],
		[
			spoiler,
			"paint",
			Transform3D(Basis(Vector3.RIGHT, deg_to_rad(-20.0)), Vector3(0, 0.07, 0.13))
		],
	]


## A motocross helmet's long chin bar, its peak in the paint, and goggles: a dark lens in a
## frame over the eye port and a strap round the shell.
static func _motocross_face() -> Array:
	var chin := SphereMesh.new()
	chin.radius = 0.5
	chin.height = 1.0
	var peak := BoxMesh.new()
	peak.size = Vector3(0.2, 0.012, 0.13)
	var lens := SphereMesh.new()
	lens.radius = 0.5
	lens.height = 1.0
	var strap := TorusMesh.new()
	strap.inner_radius = RADIUS * 0.99
	strap.outer_radius = RADIUS * 1.04
	strap.rings = 24
	var nose_down := Basis(Vector3.RIGHT, deg_to_rad(-12.0))
	return [
		[
			chin,
			"helmet",
			Transform3D(nose_down.scaled_local(Vector3(0.13, 0.1, 0.22)), Vector3(0, -0.085, -0.1))
		],
		[peak, "paint", Transform3D(nose_down, Vector3(0, 0.075, -0.15))],
		[
			lens,
			"visor",
			Transform3D(Basis.from_scale(Vector3(0.19, 0.075, 0.08)), Vector3(0, 0.0, -0.12))
		],
		[
			strap,
			"rubber",
			Transform3D(Basis.from_scale(Vector3(1.0, 1.0, LENGTH)), Vector3(0, 0.0, 0.0))
		],
	]
