class_name TyreSmoke
extends RefCounted
## The puff a hard-sliding tyre gives off: pale grey smoke that swells, rises a little and
## thins out in about a second (CPU particles: the compatibility renderer draws them on any
## machine).

const LIFETIME := 1.1
const AMOUNT := 28
const COLOUR := Color(0.82, 0.8, 0.78, 0.5)


static func make() -> CPUParticles3D:
	var smoke := CPUParticles3D.new()
	smoke.emitting = false
	smoke.amount = AMOUNT
	smoke.lifetime = LIFETIME
	smoke.local_coords = false
	# A puff's or a spark's quad would cast a square shadow.
	smoke.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	smoke.mesh = puff(0.5)
	smoke.direction = Vector3.UP
	smoke.spread = 60.0
	smoke.initial_velocity_min = 0.3
	smoke.initial_velocity_max = 1.0
	smoke.gravity = Vector3(0, 0.4, 0)
	smoke.damping_min = 0.5
	smoke.damping_max = 1.0
	smoke.scale_amount_min = 0.6
	smoke.scale_amount_max = 1.2
	var swelling := Curve.new()
	swelling.add_point(Vector2(0, 0.4))
	swelling.add_point(Vector2(1, 2.2))
	smoke.scale_amount_curve = swelling
	var fading := Gradient.new()
	fading.set_color(0, COLOUR)
	fading.set_color(1, Color(COLOUR, 0.0))
	smoke.color_ramp = fading
	return smoke


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
