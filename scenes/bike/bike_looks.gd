class_name BikeLooks
extends RefCounted
## The materials the drawn bike and rider are made of, by name: one shared material per
## look, made on first use, and a see-through one for ghosts. The paint is each bike's own
## (BikeDescription.paint): a look can be given its colour.

const COLOURS := {
	tyre = Color(0.06, 0.06, 0.07),
	rim = Color(0.2, 0.2, 0.22),
	metal = Color(0.7, 0.7, 0.72),
	frame = Color(0.12, 0.12, 0.13),
	engine = Color(0.25, 0.25, 0.27),
	seat = Color(0.08, 0.08, 0.09),
	tail_light = Color(0.9, 0.05, 0.05),
	exhaust = Color(0.55, 0.55, 0.58),
	spring = Color(0.95, 0.75, 0.1),
	rubber = Color(0.05, 0.05, 0.05),
	lamp = Color(1.0, 0.97, 0.85),
	chain = Color(0.3, 0.28, 0.26),
	caliper = Color(0.85, 0.55, 0.1),
	plate = Color(0.95, 0.85, 0.2),
	trousers = Color(0.12, 0.13, 0.17),
	boots = Color(0.05, 0.05, 0.05),
	jacket = Color(0.13, 0.32, 0.7),
	gloves = Color(0.08, 0.08, 0.08),
	helmet = Color(0.95, 0.95, 0.95),
	visor = Color(0.05, 0.06, 0.1),
}

## What a ghost's pieces look like: their colour washed towards this, at this opacity.
const GHOST_TINT := Color(0.55, 0.8, 1.0)
const GHOST_ALPHA := 0.35

static var _made := {}
static var _ghosts := {}
static var _skins := {}


## The material of `look`, in `colour` when one is given (magenta for a look nobody
## defined and no colour, so it shows).
static func material(look: String, colour := Color(0, 0, 0, 0)) -> StandardMaterial3D:
	var key := _key(look, colour)
	if _made.has(key):
		return _made[key]
	var made := StandardMaterial3D.new()
	made.albedo_color = colour if colour.a > 0.0 else COLOURS.get(look, Color.MAGENTA)
	made.roughness = (
		0.35
		if look in ["paint", "helmet", "visor", "metal", "exhaust", "chain", "caliper"]
		else 0.8
	)
	made.metallic = 0.6 if look in ["metal", "exhaust", "visor"] else 0.0
	if look == "visor":
		# A tinted visor is glass: it mirrors the sky rather than scattering it.
		made.roughness = 0.08
	if look in ["lamp", "tail_light"]:
		made.emission_enabled = true
		made.emission = made.albedo_color
	_made[key] = made
	return made


## The see-through version of `look` a ghost is drawn in: lit, tinted, casting no shadow.
static func ghost_material(look: String, colour := Color(0, 0, 0, 0)) -> StandardMaterial3D:
	var key := _key(look, colour)
	if _ghosts.has(key):
		return _ghosts[key]
	var made := material(look, colour).duplicate() as StandardMaterial3D
	made.albedo_color = made.albedo_color.lerp(GHOST_TINT, 0.5)
	made.albedo_color.a = GHOST_ALPHA
	made.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	made.metallic = 0.0
	_ghosts[key] = made
	return made


## Dresses `node` in `look` (`colour` for the paint): see-through and casting no shadow
## for a ghost, so every piece of a ghost is drawn alike.
static func dress(node: GeometryInstance3D, look: String, colour: Color, ghost: bool) -> void:
	node.material_override = ghost_material(look, colour) if ghost else material(look, colour)
	if ghost:
		node.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF


## The material of a mesh coloured by its vertices (the skinned rider, whose vertices
## carry their look's colour), see-through for a ghost.
static func skin_material(ghost: bool) -> StandardMaterial3D:
	if _skins.has(ghost):
		return _skins[ghost]
	var made := StandardMaterial3D.new()
	made.vertex_color_use_as_albedo = true
	made.roughness = 0.8
	if ghost:
		made.albedo_color = Color(GHOST_TINT.lightened(0.4), GHOST_ALPHA)
		made.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	_skins[ghost] = made
	return made


static func _key(look: String, colour: Color) -> String:
	return look if colour.a <= 0.0 else "%s#%s" % [look, colour.to_html()]
