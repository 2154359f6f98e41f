extends TestCase
## The world every level is ridden in: one shared outdoor environment (sky, ambient light,
## tone mapping, distance fog), a sun whose shadows the player sees, and surfaces with a
## texture (grass, asphalt, concrete), made procedurally so no image can go missing. A sun
## behind the chase camera throws the bike's shadow straight behind the bike, out of view:
## the game once rode a whole phase like that, shadows on and none to be seen. Clouds in
## the sky, and land out to hills on the horizon round every level.

const GAME := preload("res://scenes/game/game.tscn")
const ENVIRONMENT := "res://scenes/world/outdoor_environment.tres"
## How far, at most, the light's heading may be from the way a level's first spawn point
## faces before its shadows hide behind the bike from a camera behind it.
const LEAST_ANGLE_FROM_THE_HEADING := deg_to_rad(60.0)

var _game: Node3D


func before_all() -> void:
	_game = GAME.instantiate()


func after_all() -> void:
	_game.free()


func test_the_levels_share_one_outdoor_environment_with_fog() -> void:
	var world := _game.get_node(^"Environment") as WorldEnvironment
	assert_eq(world.environment.resource_path, ENVIRONMENT)
	assert_true(world.environment.fog_enabled, "distance fog")
	assert_eq(world.environment.background_mode, Environment.BG_SKY)


func test_the_sun_casts_shadows_from_a_height_that_shows_them() -> void:
	var sun := _game.get_node(^"Sun") as DirectionalLight3D
	assert_true(sun.shadow_enabled, "the sun casts shadows")
	var travels := -sun.basis.z
	var elevation := asin(-travels.y)
	assert_between(rad_to_deg(elevation), 25.0, 60.0, "the sun's height (°)")


func test_every_levels_start_has_the_bikes_shadow_in_the_chase_cameras_view() -> void:
	var sun := _game.get_node(^"Sun") as DirectionalLight3D
	var travels := -sun.basis.z
	var shadow_heading := Vector2(travels.x, travels.z).normalized()
	for key in Levels.keys():
		var level := (load(Levels.path_of(key)) as PackedScene).instantiate() as Level
		add_child(level)
		var spawn := level.spawn_points()[0].spawn_transform()
		var facing := -spawn.basis.z
		var angle := shadow_heading.angle_to(Vector2(facing.x, facing.z))
		assert_gt(
			absf(angle),
			LEAST_ANGLE_FROM_THE_HEADING,
			"%s: the shadow falls %.0f° from the bike's heading" % [key, rad_to_deg(absf(angle))]
		)
		level.free()


func test_the_levels_surfaces_are_textured() -> void:
	Graphics.apply("medium")
	for path: String in Graphics.SURFACES:
		var material := load(path)
		if material is ShaderMaterial:
			_assert_every_sampler_has_a_texture(material as ShaderMaterial, path)
			continue
		var standard := material as StandardMaterial3D
		assert_not_null(standard.albedo_texture, "%s has a texture" % path)
		assert_not_null(standard.normal_texture, "%s has relief" % path)
		assert_true(standard.uv1_world_triplanar, "%s is laid in world metres" % path)


func test_the_ramp_and_bank_pieces_are_concrete_in_their_own_colour() -> void:
	Graphics.apply("medium")
	for piece: StaticBody3D in [RampPiece.new(), BankPiece.new()]:
		piece.set(&"colour", Color(0.8, 0.3, 0.2))
		add_child(piece)
		var shown := piece.find_children("*", "MeshInstance3D", false, false)[0] as MeshInstance3D
		var material := shown.mesh.surface_get_material(0) as StandardMaterial3D
		var name := str((piece.get_script() as Script).get_global_name())
		assert_not_null(material.albedo_texture, "%s textured" % name)
		assert_true(material.vertex_color_use_as_albedo, "%s coloured by its vertices" % name)
		var colours: PackedColorArray = shown.mesh.surface_get_arrays(0)[Mesh.ARRAY_COLOR]
		var stored := Vector4(colours[0].r, colours[0].g, colours[0].b, colours[0].a)
		# Vertex colours are kept in 8 bits a channel.
		var colour := Vector4(0.8, 0.3, 0.2, 1.0)
		assert_almost_eq(stored, colour, Vector4.ONE / 255.0, "%s in its colour" % name)
		piece.free()


## A shader surface (the ground, the skate park's slabs): each of its textures is given,
## a normal map among them.
func _assert_every_sampler_has_a_texture(surface: ShaderMaterial, path: String) -> void:
	var relief := 0
	for uniform: Dictionary in surface.shader.get_shader_uniform_list():
		if uniform.type != TYPE_OBJECT:
			continue
		var texture := surface.get_shader_parameter(uniform.name) as Texture2D
		assert_not_null(texture, "%s: %s has a texture" % [path, uniform.name])
		relief += int(texture is NoiseTexture2D and (texture as NoiseTexture2D).as_normal_map)
	assert_gt(relief, 0, "%s has relief" % path)


func test_the_sky_has_clouds_and_the_land_runs_out_to_hills_on_the_horizon() -> void:
	var world := _game.get_node(^"Environment") as WorldEnvironment
	var sky := world.environment.sky.sky_material as ShaderMaterial
	assert_not_null(sky, "a sky of our own shader")
	if sky != null:
		assert_not_null(sky.get_shader_parameter(&"cloud_noise"), "clouds")
	var horizon := _game.get_node(^"Horizon") as Horizon
	assert_not_null(horizon, "the game stands every level in the land")
	var mesh := Horizon.build_mesh(70.0, 7)
	var vertices := mesh.surface_get_arrays(0)[Mesh.ARRAY_VERTEX] as PackedVector3Array
	var normals := mesh.surface_get_arrays(0)[Mesh.ARRAY_NORMAL] as PackedVector3Array
	var tallest := 0.0
	for i in vertices.size():
		var flat := Vector2(vertices[i].x, vertices[i].z).length()
		if flat <= Horizon.FLAT_RADIUS:
			assert_eq(vertices[i].y, 0.0, "flat under and round the level")
		tallest = maxf(tallest, vertices[i].y)
		assert_gt(normals[i].y, 0.0, "it faces the sky")
	assert_between(tallest, 35.0, 70.0, "hills, under the height asked")
	assert_eq(horizon.find_children("*", "CollisionObject3D").size(), 0, "drawn only")
