class_name RiderHelmet
extends RefCounted
## A full-face road helmet on the rider's head bone (-z forward, y up): a shell a little
## longer than it is wide, a chin bar, a dark glossy visor, and a stripe over the crown and a
## small spoiler in the bike's paint, so it reads as a helmet from behind, where the chase
## camera sees it, and not as a ball.

## The shell's radius (m): an adult's head and the shell's foam.
const RADIUS := 0.135
## How much longer front to back than across.
const LENGTH := 1.08
## The stripe's share of the shell's width.
const STRIPE_WIDTH := 0.3


## The helmet's pieces as [mesh, look, transform] each; `look` "paint" is the bike's colour.
static func pieces() -> Array:
	var shell := SphereMesh.new()
	shell.radius = RADIUS
	shell.height = RADIUS * 2.0
	var stripe := SphereMesh.new()
	stripe.radius = RADIUS * 1.012
	stripe.height = RADIUS * 1.012
	stripe.is_hemisphere = true
	var chin := SphereMesh.new()
	chin.radius = 0.075
	chin.height = 0.15
	var visor := SphereMesh.new()
	visor.radius = 0.5
	visor.height = 1.0
	var spoiler := BoxMesh.new()
	spoiler.size = Vector3(0.11, 0.018, 0.05)
	var longer := Basis.from_scale(Vector3(1.0, 1.0, LENGTH))
	return [
		[shell, "helmet", Transform3D(longer, Vector3.ZERO)],
		[
			stripe,
			"paint",
			Transform3D(longer.scaled(Vector3(STRIPE_WIDTH, 1.0, 1.0)), Vector3.ZERO)
		],
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
