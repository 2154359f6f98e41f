extends TestCase
## Tyre marks and smoke answer how fast a tyre slides and how much grip it uses: a sliding
## tyre on the ground marks it, and so does one braking near its grip; a rolling or lifted
## one does not; a hard slide smokes; a mark fades in and out and has soft edges; the
## marks kept are bounded.

var _marks: TyreMarks


func before_each() -> void:
	_marks = TyreMarks.new()
	add_child(_marks)


func after_each() -> void:
	_marks.free()


func test_a_sliding_tyre_on_the_ground_marks_it_and_a_rolling_one_does_not() -> void:
	_slide_rear(2.5, 4.0)
	assert_gt(_marks.piece_count(), 10, "2.5 m/s over 4 m: a mark")
	_marks.clear()
	_slide_rear(0.3, 4.0)
	assert_eq(_marks.piece_count(), 0, "rolling: none")


func test_a_tyre_braking_near_its_grip_marks_the_road_and_a_gentle_stop_does_not() -> void:
	_slide_rear(0.0, 4.0, 0.9)
	assert_gt(_marks.piece_count(), 10, "0.9 of the friction circle: a mark")
	assert_false(_marks.smoking(0), "gripping, not smoking")
	_marks.clear()
	_slide_rear(0.0, 4.0, 0.5)
	assert_eq(_marks.piece_count(), 0, "half of it: none")


func test_the_grip_in_use_is_the_deceleration_and_the_turns_pull_against_the_friction() -> void:
	var game: Node = load("res://scenes/game/game.tscn").instantiate()
	game.level_path = "res://scenes/levels/test_level/test_level.tscn"
	add_child(game)
	var marks := game.get_node(^"TyreMarks") as TyreMarks
	var g: float = game.bike.get_gravity()
	var friction: float = (game.bike.bike as BikeDescription).get(&"tyre_friction")
	assert_almost_eq(marks.grip_in_use(0.9 * g * friction, 0.0), 0.9, 1e-6, "a 0.9 g stop")
	assert_almost_eq(marks.grip_in_use(0.0, atan(0.6 * friction)), 0.6, 1e-6, "a lean")
	game.free()


func test_a_wheel_in_the_air_marks_nothing() -> void:
	for step in 40:
		var tyres: Array[Vector4] = [
			Vector4(step * 0.1, 0, 0, 6.0), Vector4(step * 0.1 + 1.4, 0, 0, 6.0)
		]
		var grounded: Array[bool] = [false, false]
		_marks.follow(tyres, grounded, 0.95)
	assert_eq(_marks.piece_count(), 0)
	assert_false(_marks.smoking(0), "nor smokes")


func test_a_hard_slide_smokes_and_a_light_one_does_not() -> void:
	_slide_rear(TyreMarks.SMOKE_SLIP + 1.0, 1.0)
	assert_true(_marks.smoking(0), "hard: smoke")
	assert_false(_marks.smoking(1), "the front rolls")
	_slide_rear(TyreMarks.MARK_SLIP + 0.5, 1.0)
	assert_false(_marks.smoking(0), "light: no smoke")


func test_a_mark_fades_in_at_its_start_and_out_at_its_end_and_its_edges_are_soft() -> void:
	_slide_rear(2.5, 4.0)
	_slide_rear(0.0, 0.5)
	var count := _marks.piece_count()
	assert_gt(count, 2 * TyreMarks.FADE_PIECES, "a mark")
	assert_eq(_marks.piece_opacity(0).x, 0.0, "it starts from nothing")
	assert_eq(_marks.piece_opacity(count - 1).y, 0.0, "and ends in nothing")
	var middle := _marks.piece_opacity(count / 2)
	assert_almost_eq(middle.x, middle.y, 1e-6, "full in the middle")
	assert_gt(middle.y, TyreMarks.FAINT)
	for i in range(1, count):
		var meet := _marks.piece_opacity(i).x - _marks.piece_opacity(i - 1).y
		assert_almost_eq(meet, 0.0, 1e-6, "piece %d meets the one before" % i)
	var texture := (_marks.material_override as StandardMaterial3D).albedo_texture
	var across := (texture as GradientTexture2D).gradient
	assert_eq(across.sample(0.0).a, 0.0, "an edge is soft")
	assert_eq(across.sample(0.5).a, 1.0, "the middle is dark")
	assert_eq(across.sample(1.0).a, 0.0, "so is the other edge")


func test_the_oldest_marks_go_first() -> void:
	_slide_rear(5.0, TyreMarks.SEGMENT * TyreMarks.MAX_SEGMENTS * 2.0)
	assert_eq(_marks.piece_count(), TyreMarks.MAX_SEGMENTS)


## The rear tyre sliding at `slide` m/s along x over `metres`, the front rolling beside it,
## the bike using `grip` of the friction circle.
func _slide_rear(slide: float, metres: float, grip := 0.0) -> void:
	var steps := ceili(metres / (TyreMarks.SEGMENT / 2.0))
	for step in steps + 1:
		var x := step * TyreMarks.SEGMENT / 2.0
		var tyres: Array[Vector4] = [Vector4(x, 0, 0, slide), Vector4(x + 1.4, 0, 0, 0.1)]
		var grounded: Array[bool] = [true, true]
		_marks.follow(tyres, grounded, grip)


func test_the_marks_lie_over_every_surface_drawn_above_the_ground() -> void:
	# The tyres meet the level's ground at y = 0; the road and the park's floor are drawn
	# a few millimetres over it, and a mark under them would never be seen (the track's
	# road was 20 mm thick and hid every mark on it).
	var track := (load("res://scenes/levels/track/track.tscn") as PackedScene).instantiate()
	var road := track.get_node(^"Road") as CSGPolygon3D
	var top := -INF
	for corner in road.polygon:
		top = maxf(top, corner.y)
	track.free()
	assert_lt(top + 0.003, TyreMarks.LIFT, "over the track's road (top %.3f m)" % top)
	assert_lt(ParkDressing.FLOOR_RISE + 0.003, TyreMarks.LIFT, "over the skate park's floor")
	assert_lt(DirtPatch.RISE + 0.002, TyreMarks.LIFT, "over a dirt patch")
	assert_gt(DirtPatch.RISE, top + 0.001, "a dirt patch over the road")
