class_name Horizon
extends MeshInstance3D
## The land beyond a level, drawn only: flat grass from under the level out to
## FLAT_RADIUS, then rolling hills rising towards the horizon, so a level stands in a
## landscape instead of on a plane fading into haze. It lies SINK metres below the level's
## ground, which covers it wherever the level has ground; nothing here collides. The hills'
## shape is seeded, the same every run.

## Where the flat land ends and the hills have risen to their full height (m from the
## level's middle), and the far edge, beyond the camera's fog line for the scene but not
## for the hills' own haze.
const FLAT_RADIUS := 320.0
const RISEN_RADIUS := 700.0
const FAR_RADIUS := 1600.0
## How far below the level's ground the land lies (m): low enough that the ground never
## flickers into it, too little to see.
const SINK := 0.3
## Rings and spokes of the mesh.
const RINGS := 14
const SPOKES := 96
const SHADER := preload("res://scenes/world/horizon/horizon.gdshader")

## The hills' tallest (m) and where their shape starts.
@export var hill_height := 70.0
@export var layout_seed := 7


func _ready() -> void:
	cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	mesh = build_mesh(hill_height, layout_seed)
	var material := ShaderMaterial.new()
	material.shader = SHADER
	material.set_shader_parameter(&"hill_height", hill_height)
	material_override = material
	position.y = -SINK


## The land's mesh: a disc of RINGS rings by SPOKES spokes, flat inside FLAT_RADIUS, hills
## of up to `height` m beyond, their crests from seeded noise round the circle.
static func build_mesh(height: float, seed_value: int) -> ArrayMesh:
	var noise := FastNoiseLite.new()
	noise.seed = seed_value
	noise.frequency = 2.5
	noise.fractal_octaves = 3
	var radii := PackedFloat32Array([0.0])
	for ring in RINGS:
		radii.append(
			(
				FLAT_RADIUS * 0.5
				+ (FAR_RADIUS - FLAT_RADIUS * 0.5) * pow(float(ring) / (RINGS - 1), 1.6)
			)
		)
	var tool := SurfaceTool.new()
	tool.begin(Mesh.PRIMITIVE_TRIANGLES)
	for ring in radii.size() - 1:
		for spoke in SPOKES:
			var corners: Array[Vector3] = [
				_point(radii[ring], spoke, height, noise),
				_point(radii[ring + 1], spoke, height, noise),
				_point(radii[ring + 1], spoke + 1, height, noise),
				_point(radii[ring], spoke + 1, height, noise),
			]
			for corner: int in [0, 1, 2, 0, 2, 3]:
				tool.add_vertex(corners[corner])
	tool.generate_normals()
	return tool.commit()


## The land at `radius` on spoke `spoke`: flat ground, then hills rising with distance.
static func _point(radius: float, spoke: int, height: float, noise: FastNoiseLite) -> Vector3:
	var angle := TAU * float(spoke % SPOKES) / SPOKES
	var rise := clampf((radius - FLAT_RADIUS) / (RISEN_RADIUS - FLAT_RADIUS), 0.0, 1.0)
	var around := Vector2(cos(angle), sin(angle))
	var crest := 0.5 + 0.5 * noise.get_noise_2dv(around * (1.0 + radius / FAR_RADIUS))
	var y := height * smoothstep(0.0, 1.0, rise) * crest
	return Vector3(around.x * radius, y, around.y * radius)
