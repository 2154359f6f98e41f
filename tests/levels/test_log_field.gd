extends TestCase
## The test level's logs come from the native core (`LogFieldDescription.layout`), which the
## trainer and the scenario tool share. Every committed experiment ride met the logs the
## level's script once laid with Godot's RandomNumberGenerator: the core lays those same
## logs, number for number, so those rides still repeat.

const FIELD := preload("res://scenes/levels/test_level/log_field.tres")


## The logs as the level's script laid them before the core did.
func _laid_by_godots_generator(field: LogFieldDescription, seed_value: int) -> Array:
	var rng := RandomNumberGenerator.new()
	rng.seed = seed_value
	var logs := []
	for i in field.count:
		var radius := rng.randf_range(field.radius_range.x, field.radius_range.y)
		var length := rng.randf_range(field.length_range.x, field.length_range.y)
		var angle := deg_to_rad(rng.randf_range(-field.max_angle_deg, field.max_angle_deg))
		var centre := Vector3(
			rng.randf_range(-field.area.x / 2.0, field.area.x / 2.0),
			0.0,
			rng.randf_range(-field.area.y / 2.0, field.area.y / 2.0)
		)
		logs.append({radius = radius, length = length, angle = angle, centre = centre})
	return logs


func test_the_core_lays_the_logs_godots_generator_laid() -> void:
	for seed_value: int in [1, 999, 1000, 1042, 1199, 20001, -3]:
		assert_eq(
			FIELD.layout(seed_value),
			_laid_by_godots_generator(FIELD, seed_value),
			"seed %d" % seed_value
		)


func test_a_field_of_other_numbers_too() -> void:
	var field := LogFieldDescription.new()
	field.area = Vector2(3.3, 41.7)
	field.count = 57
	field.radius_range = Vector2(0.031, 0.29)
	field.length_range = Vector2(0.5, 4.25)
	field.max_angle_deg = 62.5
	assert_eq(field.layout(77), _laid_by_godots_generator(field, 77))


func test_the_level_lays_its_field_from_its_file() -> void:
	var level: Node3D = preload("res://scenes/levels/test_level/test_level.tscn").instantiate()
	add_child(level)
	var bumps: BumpField = level.get_node("Bumps")
	assert_eq(bumps.field.resource_path, FIELD.resource_path)
	bumps.regenerate(1005)
	var logs := FIELD.layout(1005)
	assert_eq(bumps.get_child_count(), 20)
	for i in logs.size():
		var body: StaticBody3D = bumps.get_child(i)
		var cylinder: CylinderShape3D = body.get_node("Shape").shape
		assert_eq(body.position, logs[i].centre)
		assert_eq(cylinder.radius, logs[i].radius)
	level.free()


func test_a_field_without_a_description_lays_nothing() -> void:
	var bumps := BumpField.new()
	add_child(bumps)
	bumps.regenerate(3)
	assert_eq(bumps.get_child_count(), 0)
	bumps.free()
