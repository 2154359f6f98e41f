extends TestCase
## The levels are the `level` setting's choices, each a scene at its folder's name, named
## in menus by its title. Every level loads, its geometry becomes the bike's terrain
## without a problem, and the bike spawned at each of its spawn points comes to rest on
## both wheels.

const BIKE := preload("res://scenes/bike/bike.tscn")
## Control steps to settle onto the wheels: 0.5 s. Nobody can balance a bike standing
## still, so it starts to tip soon after; the game holds it until the first throttle.
const SETTLE_STEPS := 15


func test_the_levels_are_the_level_settings_choices_each_a_scene_named_by_its_title() -> void:
	assert_eq(Levels.keys(), ["test_level", "track", "skate_park"], "the schema's order")
	assert_eq(Levels.path_of("track"), "res://scenes/levels/track/track.tscn")
	assert_eq(Levels.key_of("res://scenes/levels/skate_park/skate_park.tscn"), "skate_park")
	var names := Levels.keys().map(Levels.name_of)
	assert_eq(names, ["Thesis test (rides itself)", "Track", "Skate park"], "by their titles")
	assert_eq(Levels.path_of("school"), "", "the School is not a level to ride freely")
	assert_eq(Levels.path_of("../track"), "", "nor a path")
	assert_eq(Levels.key_of("res://scenes/levels/nowhere.tscn"), "")
	var default_level: String = Settings.schema_entry(&"level").default
	assert_has(Levels.keys(), default_level, "the default is one of them")


func test_every_level_converts_to_terrain_without_problems() -> void:
	for key in Levels.keys():
		var level := _load(key)
		add_child(level)
		assert_eq(
			TerrainCheck.problems(level), PackedStringArray(), "%s has no terrain problems" % key
		)
		assert_gt(TerrainCheck.usable_shape_count(level), 0, "%s has terrain" % key)
		assert_false(level.spawn_points().is_empty(), "%s has spawn points" % key)
		level.free()


func test_the_bike_rests_on_its_wheels_at_every_spawn_point() -> void:
	for key in Levels.keys():
		var level := _load(key)
		add_child(level)
		var spawns := level.spawn_points()
		assert_gt(spawns.size(), 1 if key != "test_level" else 0, "%s spawn points" % key)
		for spawn in spawns:
			var bike: BikeSimulation = BIKE.instantiate()
			bike.terrain_root = NodePath("../" + level.name)
			bike.transform = spawn.spawn_transform()
			add_child(bike)
			bike.set_physics_process(false)
			bike.advance(SETTLE_STEPS)
			var where := "%s at %s" % [key, spawn.name]
			assert_true(bike.is_running(), where)
			assert_true(
				bike.is_rear_wheel_grounded() and bike.is_front_wheel_grounded(),
				"%s: both wheels down" % where
			)
			assert_false(bike.is_crashed(), "%s: standing" % where)
			assert_almost_eq(bike.get_lean(), 0.0, deg_to_rad(4.0), "%s: upright" % where)
			bike.free()
		level.free()


func test_lap_gates_face_the_way_the_lap_is_ridden() -> void:
	# A gate counts crossings towards its −z only: turned the other way, no lap could ever
	# count (the track's two bend gates once were, found by the bot's first lap).
	var gates := 0
	for key in Levels.keys():
		var level := _load(key)
		add_child(level)
		var lap := level.get_node_or_null("Lap") as Path3D
		for gate: LapGate in level.find_children("*", "LapGate", true, false):
			assert_not_null(lap, "%s has gates but no Lap path" % key)
			var local := lap.to_local(gate.global_position)
			var along := lap.curve.get_closest_offset(local)
			var here := lap.curve.sample_baked(along, true)
			var ahead := lap.curve.sample_baked(along + 1.0, true)
			var direction := (lap.global_basis * (ahead - here)).normalized()
			var forward := -gate.global_basis.z.normalized()
			assert_gt(direction.dot(forward), 0.9, "%s: %s faces along the lap" % [key, gate.name])
			gates += 1
		level.free()
	assert_gt(gates, 3, "the track's gates were checked")


func test_a_level_warns_about_shapes_the_simulation_cannot_use() -> void:
	var level := _load("skate_park")
	var body := StaticBody3D.new()
	var shape := CollisionShape3D.new()
	shape.shape = SeparationRayShape3D.new()
	body.add_child(shape)
	level.add_child(body)
	add_child(level)
	var warnings := level._get_configuration_warnings()
	assert_eq(warnings.size(), 1)
	assert_has(warnings[0], "SeparationRayShape3D is not supported")
	level.free()


func test_a_level_without_spawn_points_warns() -> void:
	var level := Level.new()
	add_child(level)
	var warnings := level._get_configuration_warnings()
	assert_has(warnings[0], "SpawnPoint")
	assert_has(warnings[1], "no static collision shapes")
	level.free()


func _load(key: String) -> Level:
	return (load(Levels.path_of(key)) as PackedScene).instantiate() as Level
