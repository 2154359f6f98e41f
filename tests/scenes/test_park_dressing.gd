extends TestCase
## The skate park is built: a slab floor under the walls out to a fence round the outside,
## floodlights at its corners and benches between the wall and the fence, nothing that
## collides or stands where the bike rides, and the props' shadows follow the graphics
## quality.

const PARK := preload("res://scenes/levels/skate_park/skate_park.tscn")
## The park's walls stand on this square's edges (m, half its side), 0.4 m thick.
const WALL_HALF := 30.0
const WALL_HALF_THICKNESS := 0.2

var _park: Node3D
var _dressing: ParkDressing


func before_all() -> void:
	_park = PARK.instantiate()
	add_child(_park)
	_dressing = _park.get_node(^"Dressing") as ParkDressing


func after_all() -> void:
	_park.free()


func test_the_floor_reaches_past_the_walls_to_the_fence() -> void:
	var reach := _dressing.floor_size() / 2.0
	assert_gt(reach.x, WALL_HALF + WALL_HALF_THICKNESS, "x")
	assert_gt(reach.y, WALL_HALF + WALL_HALF_THICKNESS, "z")
	var floor_mesh := _dressing.get_node(^"Floor") as MeshInstance3D
	assert_between(floor_mesh.global_position.y, 0.001, 0.01, "just over the ground")


func test_the_fence_goes_all_round_outside_the_walls() -> void:
	var posts := _dressing.post_positions()
	assert_gt(posts.size(), 4 * WALL_HALF * 2.0 / ParkDressing.POST_SPACING - 4, "posts")
	var fence := WALL_HALF + _dressing.fence_margin
	var on_side := {west = 0, east = 0, north = 0, south = 0}
	for at in posts:
		assert_gt(maxf(absf(at.x), absf(at.z)), WALL_HALF + WALL_HALF_THICKNESS, "%s" % at)
		on_side.west += int(is_equal_approx(at.x, -fence))
		on_side.east += int(is_equal_approx(at.x, fence))
		on_side.north += int(is_equal_approx(at.z, -fence))
		on_side.south += int(is_equal_approx(at.z, fence))
	for side: String in on_side:
		assert_gt(on_side[side], 20, "posts along the %s side" % side)
	assert_eq(_dressing.floodlight_positions().size(), 4, "a floodlight a corner")


func test_benches_stand_between_the_wall_and_the_fence() -> void:
	var fence := WALL_HALF + _dressing.fence_margin
	assert_eq(_dressing.bench_positions().size(), _dressing.bench_count)
	for at in _dressing.bench_positions():
		assert_between(at.z, WALL_HALF + WALL_HALF_THICKNESS + 0.2, fence - 0.2, "%s" % at)


func test_nothing_of_the_dressing_collides() -> void:
	assert_eq(_dressing.find_children("*", "CollisionObject3D", true, false).size(), 0)


func test_the_props_shadows_follow_the_graphics_quality() -> void:
	var lights := _dressing.get_node(^"Floodlights") as GeometryInstance3D
	Graphics.apply("low")
	assert_eq(lights.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_OFF, "low")
	Graphics.apply("medium")
	assert_eq(lights.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_ON, "medium")


func test_the_floor_is_one_of_the_surfaces_the_quality_textures() -> void:
	assert_has(Graphics.SURFACES, ParkDressing.SLAB_MATERIAL.resource_path)
