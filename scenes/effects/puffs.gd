class_name Puffs
extends RefCounted
## Billowing clouds of soft puffs that swell, drift and thin out: a hard-sliding tyre's
## smoke and the dust a tyre raises on dirt. CPU particles, so the compatibility renderer
## draws them on any machine; they cast no shadow (a puff's quad would cast a square one).

## A tyre's smoke: pale grey, rising a little, gone in about a second.
const SMOKE := {
	colour = Color(0.82, 0.8, 0.78, 0.5),
	amount = 28,
	lifetime = 1.1,
	size = 0.5,
	spread = 60.0,
	speed = Vector2(0.3, 1.0),
	rise = 0.4,
	damping = Vector2(0.5, 1.0),
	scale = Vector2(0.6, 1.2),
	swell = Vector2(0.4, 2.2),
}
## Dust off dirt: brown, low and lingering.
const DUST := {
	colour = Color(0.62, 0.52, 0.4, 0.7),
	amount = 36,
	lifetime = 1.6,
	size = 0.9,
	spread = 70.0,
	speed = Vector2(0.3, 0.6),
	rise = 0.15,
	damping = Vector2(0.8, 1.5),
	scale = Vector2(0.7, 1.0),
	swell = Vector2(0.5, 2.6),
}


## A cloud of `look`'s puffs (SMOKE, DUST), not yet emitting, in world coordinates.
static func cloud(look: Dictionary) -> CPUParticles3D:
	var cloud := CPUParticles3D.new()
	cloud.emitting = false
	cloud.amount = look.amount
	cloud.lifetime = look.lifetime
	cloud.local_coords = false
	cloud.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	cloud.mesh = puff(look.size)
	cloud.direction = Vector3.UP
	cloud.spread = look.spread
	cloud.initial_velocity_min = look.speed.x
	cloud.initial_velocity_max = look.speed.y
	cloud.gravity = Vector3(0, look.rise, 0)
	cloud.damping_min = look.damping.x
	cloud.damping_max = look.damping.y
	cloud.scale_amount_min = look.scale.x
	cloud.scale_amount_max = look.scale.y
	var swelling := Curve.new()
	swelling.add_point(Vector2(0, look.swell.x))
	swelling.add_point(Vector2(1, look.swell.y))
	cloud.scale_amount_curve = swelling
	var fading := Gradient.new()
	fading.set_color(0, look.colour)
	fading.set_color(1, Color(look.colour, 0.0))
	cloud.color_ramp = fading
	return cloud


## A soft round puff `size` metres across, facing the camera and coloured by its particle:
## a radial fade from the middle, so puffs overlap into a cloud rather than into squares.
static func puff(size: float) -> QuadMesh:
	var quad := QuadMesh.new()
	quad.size = Vector2(size, size)
	var fade := Gradient.new()
	fade.set_color(0, Color.WHITE)
	fade.set_color(1, Color(1, 1, 1, 0))
	var round_texture := GradientTexture2D.new()
	round_texture.gradient = fade
	round_texture.fill = GradientTexture2D.FILL_RADIAL
	round_texture.fill_from = Vector2(0.5, 0.5)
	round_texture.fill_to = Vector2(1.0, 0.5)
	round_texture.width = 64
	round_texture.height = 64
	var material := StandardMaterial3D.new()
	material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	material.billboard_mode = BaseMaterial3D.BILLBOARD_PARTICLES
	material.vertex_color_use_as_albedo = true
	material.albedo_texture = round_texture
	quad.material = material
	return quad
