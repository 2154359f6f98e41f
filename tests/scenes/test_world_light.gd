extends TestCase
## The world every level is ridden in: one shared outdoor environment (sky, ambient light,
## tone mapping, distance fog) and a sun whose shadows the player sees. A sun behind the
## chase camera throws the bike's shadow straight behind the bike, out of view: the game
## once rode a whole phase like that, shadows on and none to be seen.

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
	for key: String in Levels.ALL:
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
