extends TestCase
## The drawn rider holds themself as riders do, over the simulated rider (RiderStance): the
## sport rider tucks in at speed, every road rider hangs off into a bend past about 30° of
## lean (the inside knee out, the head inside), the dirt rider stands on the pegs after a
## moment in the air or over rough ground; each eases in and out, and bad numbers leave the
## rider seated. Hands and feet stay on the grips and pegs whatever the stance. The dirt
## rider wears a motocross kit, the road riders leathers and a visor.

const TRACK := "res://scenes/levels/track/track.tscn"
const TEST_LEVEL := "res://scenes/levels/test_level/test_level.tscn"
const DIRT_BIKE := "res://scenes/bike/bikes/dirt_125.tres"
const NAKED := preload("res://scenes/bike/bodywork/naked.tres")
const SUPERSPORT := preload("res://scenes/bike/bodywork/supersport.tres")
const MOTOCROSS := preload("res://scenes/bike/bodywork/motocross.tres")
const FRAME_TIME := 1.0 / 60.0
## How far (m) a hand or foot may move off its grip or peg when the stance changes.
const REACH := 0.02

var _game: Game


func after_each() -> void:
	get_tree().paused = false
	for action: StringName in InputMap.get_actions():
		Input.action_release(action)
	if _game != null:
		_game.queue_free()
		_game = null
	await wait_frames(1)
	SettingsSandbox.leave()


func test_the_sport_rider_tucks_in_at_speed_and_sits_up_when_slow() -> void:
	assert_eq(RiderStance.wanted(SUPERSPORT, 80.0 / 3.6, 0.0, false).tuck, 1.0, "at 80 km/h")
	assert_eq(RiderStance.wanted(SUPERSPORT, 30.0 / 3.6, 0.0, false).tuck, 0.0, "at 30 km/h")
	var half: float = RiderStance.wanted(SUPERSPORT, 60.0 / 3.6, 0.0, false).tuck
	assert_almost_eq(half, 0.5, 0.01, "half way between 45 and 75 km/h")
	assert_gt(RiderStance.wanted(NAKED, 80.0 / 3.6, 0.0, false).tuck, 0.0, "the naked at 80")
	assert_eq(RiderStance.wanted(MOTOCROSS, 80.0 / 3.6, 0.0, false).tuck, 0.0, "a dirt rider")


func test_past_30_degrees_the_rider_hangs_off_to_the_inside_and_stops_tucking() -> void:
	var right := RiderStance.wanted(NAKED, 20.0, deg_to_rad(35.0), false)
	assert_almost_eq(right.hang, NAKED.hang_off, 1e-6, "all the way out at 35° to the right")
	assert_eq(right.tuck, 0.0, "hanging off, not tucked")
	var left := RiderStance.wanted(NAKED, 20.0, deg_to_rad(-35.0), false)
	assert_almost_eq(left.hang, -NAKED.hang_off, 1e-6, "to the left")
	assert_eq(RiderStance.wanted(NAKED, 20.0, deg_to_rad(10.0), false).hang, 0.0, "not at 10°")
	var at_25: float = RiderStance.wanted(SUPERSPORT, 20.0, deg_to_rad(25.0), false).hang
	assert_between(at_25, 0.3, 0.7, "on the way out at 25°")


func test_only_the_dirt_rider_stands_on_the_pegs() -> void:
	assert_eq(RiderStance.wanted(MOTOCROSS, 5.0, 0.0, true).stand, 1.0, "the dirt rider")
	assert_eq(RiderStance.wanted(NAKED, 5.0, 0.0, true).stand, 0.0, "a road rider stays seated")
	assert_eq(RiderStance.wanted(MOTOCROSS, 5.0, 0.0, false).stand, 0.0, "seated on the flat")


func test_the_dirt_rider_stands_after_a_moment_in_the_air_and_sits_on_landing() -> void:
	var stance := RiderStance.new()
	stance.advance(FRAME_TIME, MOTOCROSS, 8.0, 0.0, true)
	assert_eq(stance.stand, 0.0, "a crest that lifts the wheels for a frame is no jump")
	for frame in 30:
		stance.advance(FRAME_TIME, MOTOCROSS, 8.0, 0.0, true)
	assert_gt(stance.stand, 0.9, "standing half a second into the jump")
	var first_frame := stance.stand
	stance.advance(FRAME_TIME, MOTOCROSS, 8.0, 0.0, false)
	assert_gt(stance.stand, first_frame * 0.8, "sits down over a few frames, not at once")
	for frame in 40:
		stance.advance(FRAME_TIME, MOTOCROSS, 8.0, 0.0, false)
	assert_lt(stance.stand, 0.05, "seated again after landing")


func test_rough_ground_stands_the_dirt_rider_and_smooth_ground_does_not() -> void:
	var rough := RiderStance.new()
	var smooth := RiderStance.new()
	for frame in 60:
		# The suspension working 3 cm at 8 Hz, as over rollers and roots.
		var travel := 0.03 * sin(TAU * 8.0 * frame * FRAME_TIME)
		rough.advance(FRAME_TIME, MOTOCROSS, 6.0, 0.0, false, Vector2(travel, -travel))
		smooth.advance(FRAME_TIME, MOTOCROSS, 6.0, 0.0, false, Vector2(0.01, 0.012))
	assert_gt(rough.stand, 0.9, "standing over rough ground")
	assert_eq(smooth.stand, 0.0, "seated on smooth ground")


func test_bad_numbers_leave_the_rider_seated() -> void:
	var wanted := RiderStance.wanted(SUPERSPORT, NAN, NAN, false)
	assert_eq([wanted.tuck, wanted.hang, wanted.stand], [0.0, 0.0, 0.0], "NaN speed and lean")
	var stance := RiderStance.new()
	stance.advance(NAN, SUPERSPORT, 30.0, 0.5, false)
	stance.advance(-1.0, SUPERSPORT, 30.0, 0.5, false)
	stance.advance(FRAME_TIME, SUPERSPORT, INF, 0.0, false, Vector2(NAN, NAN))
	assert_eq([stance.tuck, stance.hang, stance.stand], [0.0, 0.0, 0.0], "nothing moved")


func test_in_a_bend_past_30_degrees_the_inside_knee_goes_out_and_the_head_inside() -> void:
	_game = await GameFixture.start(self, TRACK)
	_game.bike.controller = "arcade"
	Input.action_press(&"throttle", 0.7)
	await wait_physics_frames(120)
	Input.action_press(&"steer_right", 1.0)
	for frame in 240:
		await wait_physics_frames(1)
		if rad_to_deg(_game.bike.get_lean()) > 32.0 and _view().stance().hang > 0.6:
			break
	assert_false(_game.bike.is_crashed(), "rode into the bend")
	assert_gt(rad_to_deg(_game.bike.get_lean()), 30.0, "leaning past 30°")
	get_tree().paused = true
	var hung := await _posed(true)
	var sat := await _posed(false)
	var right := _level_right()
	var knee_out: float = (hung.shin_R - sat.shin_R).dot(right)
	assert_gt(knee_out, 0.1, "the inside knee out by %.2f m" % knee_out)
	var head_in: float = (hung.head - sat.head).dot(right)
	assert_gt(head_in, 0.04, "the head %.2f m further inside" % head_in)
	assert_lt(absf((hung.shin_L - sat.shin_L).dot(right)), 0.1, "the outside knee stays in")
	_assert_on_grips_and_pegs(hung, sat)


func test_tucked_the_back_bends_down_and_standing_lifts_the_hips_over_the_pegs() -> void:
	_game = await _game_on(DIRT_BIKE)
	var seated := await _posed_in(RiderStance.new())
	var tucked := RiderStance.new()
	tucked.tuck = 1.0
	var tuck := await _posed_in(tucked)
	var up := _game.bike.get_body_transform(BikeSimulation.FRAME).basis.y.normalized()
	var head_down: float = (seated.head - tuck.head).dot(up)
	assert_gt(head_down, 0.08, "the head %.2f m lower tucked" % head_down)
	_assert_on_grips_and_pegs(tuck, seated)
	var standing := RiderStance.new()
	standing.stand = 1.0
	var stand := await _posed_in(standing)
	var rise: float = (stand.hips - seated.hips).dot(up)
	assert_gt(rise, 0.15, "the hips %.2f m higher standing" % rise)
	assert_gt(
		stand.shin_L.distance_to(stand.foot_L),
		seated.shin_L.distance_to(seated.foot_L) - 1e-3,
		"the shin as long as seated"
	)
	_assert_on_grips_and_pegs(stand, seated)


func test_the_dirt_rider_wears_a_motocross_kit_and_the_road_rider_leathers() -> void:
	_game = await _game_on(DIRT_BIKE)
	var dirt := _kit()
	assert_true(dirt.strap, "goggles on a strap")
	assert_true(dirt.pants, "light motocross pants")
	_game.queue_free()
	await wait_frames(1)
	_game = await _game_on("res://scenes/bike/bikes/street_390.tres")
	var road := _kit()
	assert_false(road.strap, "a visor, no goggles")
	assert_false(road.pants, "leathers, not motocross pants")


func _game_on(bike_path: String) -> Game:
	SettingsSandbox.enter()
	var game := GameFixture.GAME.instantiate() as Game
	game.level_path = TEST_LEVEL
	game.bike_path = bike_path
	add_child(game)
	await wait_physics_frames(2)
	return game


func _view() -> VisualBikeView:
	return _game.bike.get_node(^"VisualBikeView") as VisualBikeView


## The drawn rider's joints (global) posed on the simulation now, the stance drawn or not.
func _posed(stance_drawn: bool) -> Dictionary:
	_view().stance_drawn = stance_drawn
	_view().follow()
	await _drawn()
	return _joints()


## The drawn rider's joints (global) posed on the bodies as they are, in `stance`.
func _posed_in(stance: RiderStance) -> Dictionary:
	var bodies: Array[Transform3D] = []
	for body in _game.bike.get_body_count():
		bodies.append(_game.bike.get_body_transform(body))
	_view().rider().pose(bodies, [], stance)
	await _drawn()
	return _joints()


## Lets the skeleton update (deferred to the frame's end) with the game paused, so the view
## does not pose the rider again first.
func _drawn() -> void:
	get_tree().paused = true
	await get_tree().process_frame


func _joints() -> Dictionary:
	var rider := _view().rider()
	var joints := {}
	for bone: String in [
		"hips", "head", "shin_L", "shin_R", "foot_L", "foot_R", "hand_L", "hand_R"
	]:
		joints[bone] = rider.bone_transform(bone).origin
	return joints


## The bike's right, level with the ground.
func _level_right() -> Vector3:
	var right := _game.bike.get_body_transform(BikeSimulation.FRAME).basis.z
	return (right - Vector3.UP * right.dot(Vector3.UP)).normalized()


func _assert_on_grips_and_pegs(posed: Dictionary, seated: Dictionary) -> void:
	for end: String in ["hand_L", "hand_R", "foot_L", "foot_R"]:
		var moved: float = (posed[end] as Vector3).distance_to(seated[end])
		assert_lt(moved, REACH, "%s stays where it was (%.3f m)" % [end, moved])


## What the rider wears: whether the helmet has a goggle strap, and the legs motocross pants.
func _kit() -> Dictionary:
	var head := _view().rider().find_child("Head", true, false) as Node3D
	var strap := false
	for piece: MeshInstance3D in head.find_children("*", "MeshInstance3D", false, false):
		strap = strap or piece.mesh is TorusMesh
	var body := _view().rider().skeleton().get_node(^"Body") as MeshInstance3D
	var colours := body.mesh.surface_get_arrays(0)[Mesh.ARRAY_COLOR] as PackedColorArray
	var pants := false
	for colour in colours:
		var off := RiderSkin.MOTOCROSS_PANTS
		pants = (
			pants or Vector3(colour.r - off.r, colour.g - off.g, colour.b - off.b).length() < 0.01
		)
	return {strap = strap, pants = pants}
