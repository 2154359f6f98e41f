extends TestCase
## Dust answers a tyre on dirt: rolling fast over a dirt patch raises it, thicker the
## faster; on other ground, in the air or at walking pace it does not; the track's gravel
## stretch is dirt and its asphalt is not.

var _dust: Dust
var _patch: DirtPatch


func before_each() -> void:
	_dust = Dust.new()
	add_child(_dust)
	_patch = DirtPatch.new()
	_patch.size = Vector2(4.0, 10.0)
	add_child(_patch)


func after_each() -> void:
	_dust.free()
	_patch.free()


func test_a_patch_holds_the_points_over_it() -> void:
	assert_true(_patch.contains(Vector3(1.9, 0, -4.9)), "inside")
	assert_false(_patch.contains(Vector3(2.1, 0, 0)), "beside")
	assert_true(DirtPatch.on_dirt(get_tree(), Vector3(0, 0, 3)), "found through the group")
	assert_false(DirtPatch.on_dirt(get_tree(), Vector3(0, 0, 6)), "past its end")


func test_rolling_fast_over_dirt_raises_dust_and_faster_raises_more() -> void:
	var tyres: Array[Vector4] = [Vector4(0, 0, 1, 0), Vector4(0, 0, -0.4, 0)]
	_dust.follow(tyres, [true, true], 5.0, [true, true])
	assert_true(_dust.raising(0), "rear")
	assert_true(_dust.raising(1), "front")
	var cloud := _dust.get_node(^"Dust0") as CPUParticles3D
	var slow := cloud.initial_velocity_max
	_dust.follow(tyres, [true, true], 14.0, [true, true])
	assert_gt(cloud.initial_velocity_max, slow)


func test_no_dust_off_dirt_in_the_air_or_at_walking_pace() -> void:
	var tyres: Array[Vector4] = [Vector4(0, 0, 1, 0), Vector4(0, 0, -0.4, 0)]
	_dust.follow(tyres, [true, true], 8.0, [false, false])
	assert_false(_dust.raising(0), "asphalt")
	_dust.follow(tyres, [false, false], 8.0, [true, true])
	assert_false(_dust.raising(0), "in the air")
	_dust.follow(tyres, [true, true], 1.0, [true, true])
	assert_false(_dust.raising(0), "walking pace")
	_dust.follow(tyres, [true, true], NAN, [true, true])
	assert_false(_dust.raising(0), "a speed that is not a number")


func test_a_sliding_tyre_raises_dust_even_slowly() -> void:
	var tyres: Array[Vector4] = [Vector4(0, 0, 1, 3.0), Vector4(0, 0, -0.4, 0)]
	_dust.follow(tyres, [true, true], 1.0, [true, true])
	assert_true(_dust.raising(0), "the spinning rear")
	assert_false(_dust.raising(1), "the rolling front")


func test_the_tracks_gravel_stretch_is_dirt_and_its_start_is_not() -> void:
	var track := (load("res://scenes/levels/track/track.tscn") as PackedScene).instantiate()
	add_child(track)
	assert_true(DirtPatch.on_dirt(get_tree(), Vector3(-40, 0, -55)), "the back straight")
	assert_false(DirtPatch.on_dirt(get_tree(), Vector3(0, 0, 9)), "the start line")
	track.free()
