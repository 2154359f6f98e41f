extends TestCase
## Sparks answer the bike scraping the road: a fast scrape throws them, a slow one or none
## does not, each scraping body has its emitter and no more, and a speed that is not a
## number throws nothing.

var _sparks: Sparks


func before_each() -> void:
	_sparks = Sparks.new()
	add_child(_sparks)


func after_each() -> void:
	_sparks.free()


func test_a_fast_scrape_throws_sparks_from_where_it_touches() -> void:
	_sparks.follow([Vector4(1, 0, 2, 6.0)])
	assert_eq(_sparks.throwing(), 1)
	var emitter := _sparks.get_node(^"Sparks0") as CPUParticles3D
	assert_eq(emitter.global_position, Vector3(1, 0, 2))


func test_a_slow_scrape_or_none_throws_nothing() -> void:
	_sparks.follow([Vector4(0, 0, 0, 6.0)])
	_sparks.follow([Vector4(0, 0, 0, Sparks.SLIDE_SPARKS * 0.5)])
	assert_eq(_sparks.throwing(), 0, "slow")
	_sparks.follow([Vector4(0, 0, 0, 6.0)])
	_sparks.follow([])
	assert_eq(_sparks.throwing(), 0, "none")


func test_faster_slides_throw_faster_sparks() -> void:
	var emitter := _sparks.get_node(^"Sparks0") as CPUParticles3D
	_sparks.follow([Vector4(0, 0, 0, 2.0)])
	var slow := emitter.initial_velocity_max
	_sparks.follow([Vector4(0, 0, 0, 12.0)])
	assert_gt(emitter.initial_velocity_max, slow)


func test_more_scrapes_than_emitters_and_a_bad_speed_are_bounded() -> void:
	var many: Array[Vector4] = []
	for i in Sparks.EMITTERS + 3:
		many.append(Vector4(i, 0, 0, 5.0))
	_sparks.follow(many)
	assert_eq(_sparks.throwing(), Sparks.EMITTERS)
	_sparks.follow([Vector4(0, 0, 0, NAN), Vector4(0, 0, 0, INF)])
	assert_eq(_sparks.throwing(), 0)
