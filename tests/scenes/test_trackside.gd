extends TestCase
## What stands beside the track: trees off the road, tyre walls round the outside of the
## bends and cones on their inside, the same every run, nothing that collides, and fewer
## trees at a lower graphics quality.

const TRACK := preload("res://scenes/levels/track/track.tscn")

var _track: Node3D
var _side: Trackside
var _lap: PackedVector2Array


func before_all() -> void:
	_track = TRACK.instantiate()
	add_child(_track)
	_side = _track.get_node(^"Trackside") as Trackside
	var lap := _track.get_node(^"Lap") as Path3D
	for point in lap.curve.get_baked_points():
		var at := lap.global_transform * point
		_lap.append(Vector2(at.x, at.z))


func after_all() -> void:
	_track.free()


func test_the_track_is_dressed() -> void:
	assert_gt(_side.tree_positions().size(), 100, "trees")
	assert_gt(_side.tyre_positions().size(), 20, "tyre walls")
	assert_gt(_side.cone_positions().size(), 8, "cones")


func test_no_tree_stands_on_or_by_the_road() -> void:
	for at in _side.tree_positions():
		assert_gt(_distance_to_lap(at), _side.tree_band.x - 0.1, "a tree at %s" % at)


func test_tyre_walls_stand_outside_the_bends_and_cones_inside_them_off_the_road() -> void:
	for at in _side.tyre_positions():
		assert_false(Geometry2D.is_point_in_polygon(Vector2(at.x, at.z), _lap), "%s" % at)
		assert_gt(_distance_to_lap(at), _side.road_half_width + 1.0, "off the road")
	for at in _side.cone_positions():
		assert_true(Geometry2D.is_point_in_polygon(Vector2(at.x, at.z), _lap), "%s" % at)
		assert_gt(_distance_to_lap(at), _side.road_half_width, "off the road")


func test_nothing_beside_the_track_collides() -> void:
	assert_eq(_side.find_children("*", "CollisionObject3D", true, false).size(), 0)


func test_the_same_seed_lays_the_same_wood() -> void:
	var again := TRACK.instantiate()
	add_child(again)
	var side := again.get_node(^"Trackside") as Trackside
	assert_eq(side.tree_positions(), _side.tree_positions())
	again.free()


func test_a_lower_graphics_quality_shows_fewer_trees_without_shadows() -> void:
	Graphics.apply("low")
	var low := _side.trees_shown()
	var trees := _side.get_node(^"Trees") as GeometryInstance3D
	assert_eq(trees.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_OFF, "low: no shadows")
	Graphics.apply("high")
	assert_lt(low, _side.trees_shown())
	assert_eq(_side.trees_shown(), _side.tree_positions().size(), "high shows them all")
	assert_eq(trees.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_ON, "with shadows")


func _distance_to_lap(at: Vector3) -> float:
	var nearest := INF
	for i in _lap.size():
		var a := _lap[i]
		var b := _lap[(i + 1) % _lap.size()]
		var closest := Geometry2D.get_closest_point_to_segment(Vector2(at.x, at.z), a, b)
		nearest = minf(nearest, closest.distance_to(Vector2(at.x, at.z)))
	return nearest
