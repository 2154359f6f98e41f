extends TestCase
## The replay of the last run: it keeps at most its ring's length, plays the recorded bike
## from the pause menu with the game paused underneath, pauses, slows down, scrubs and
## shows the player's inputs as they were; leaving it brings the live bike back.

## Longest a brake from riding pace to a foot put down may take (physics frames).
const MOST_FRAMES_TO_STOP := 600

var _game: Game


func before_each() -> void:
	_game = await GameFixture.start(self)


func after_each() -> void:
	for action: StringName in [&"throttle", &"brake", &"steer_left", &"steer_right"]:
		Input.action_release(action)
	get_tree().paused = false
	_game.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func _ride(seconds: float) -> void:
	Input.action_press(&"throttle", 0.6)
	await wait_physics_frames(roundi(seconds * Engine.physics_ticks_per_second))
	Input.action_release(&"throttle")


func test_a_run_plays_back_with_its_inputs_and_the_live_bike_returns() -> void:
	await _ride(3.0)
	var at_end := _game.bike.get_body_transform(BikeSimulation.FRAME).origin
	_game.watch_replay()
	var replay := _game.replay
	assert_true(replay.visible, "the replay is on")
	assert_true(get_tree().paused, "the game is paused underneath")
	assert_false((_game.bike.get_node(^"VisualBikeView") as Node3D).visible, "live bike hidden")
	assert_between(replay.duration(), 2.7, 3.1, "the whole run since the throttle opened")
	await wait_frames(30)
	assert_between(replay.time(), 0.4, 0.6, "plays at 1x")
	var hands := replay.find_child("Inputs", true, false) as InputDisplay
	assert_almost_eq(hands.throttle, 0.6, 1e-6, "the throttle as the player held it")
	_tap(&"ui_accept")
	await wait_frames(2)
	var paused_at := replay.time()
	await wait_frames(20)
	assert_false(replay.is_playing())
	assert_eq(replay.time(), paused_at, "paused")
	Input.action_press(&"steer_right")
	await wait_frames(60)
	Input.action_release(&"steer_right")
	assert_almost_eq(replay.time(), replay.duration(), 1e-6, "scrubbed to the end")
	var drawn := replay.find_child("ReplayBike", true, false) as VisualBikeView
	assert_lt(drawn.eye_point().distance_to(at_end), 2.5, "the recorded bike ends where it rode")
	_tap(&"pause")
	await wait_frames(2)
	assert_false(replay.visible, "left the replay")
	assert_true((_game.bike.get_node(^"VisualBikeView") as Node3D).visible, "live bike back")
	assert_true((_game.get_node(^"PauseMenu") as PauseMenu).visible, "back in the pause menu")


func test_slow_motion_plays_at_a_quarter_speed() -> void:
	await _ride(2.0)
	_game.watch_replay()
	_tap(&"previous_spawn")
	_tap(&"previous_spawn")
	await wait_frames(60)
	assert_between(_game.replay.time(), 0.2, 0.3, "a second at a quarter of the speed")


func test_the_ring_keeps_only_its_length_and_a_respawn_keeps_the_run_before() -> void:
	_game.recorder.capacity_seconds = 1.0
	await _ride(2.0)
	var run := _game.recorder.run()
	assert_eq(run.size(), roundi(_game.recorder.rate()), "a second of frames, no more")
	var last: PackedFloat32Array = run[-1].poses
	_game.restart()
	assert_eq(_game.recorder.run()[-1].poses, last, "right after a respawn: the run before")


func test_a_stop_on_a_foot_is_replayed_with_that_foot_down() -> void:
	# The arcade controller's stop repeats exactly, however busy the machine.
	Settings.set_value(&"controller", "arcade")
	await _ride(2.0)
	Input.action_press(&"brake")
	var live := _game.bike.get_node(^"VisualBikeView") as VisualBikeView
	var frames := 0
	while not _a_leg_down(live) and frames < MOST_FRAMES_TO_STOP:
		await wait_physics_frames(1)
		frames += 1
	assert_true(_a_leg_down(live), "braked to a stop on a foot (%d frames)" % frames)
	await wait_physics_frames(30)
	var legs_down := [live.is_leg_down(-1.0), live.is_leg_down(1.0)]
	_game.watch_replay()
	_tap(&"ui_accept")
	Input.action_press(&"steer_right")
	await wait_frames(60)
	Input.action_release(&"steer_right")
	var drawn := _game.replay.find_child("ReplayBike", true, false) as VisualBikeView
	assert_true(_a_leg_down(drawn), "at the end: a leg drawn down")
	assert_eq([drawn.is_leg_down(-1.0), drawn.is_leg_down(1.0)], legs_down, "as it was live")
	Input.action_press(&"steer_left")
	await wait_frames(60)
	Input.action_release(&"steer_left")
	assert_almost_eq(_game.replay.time(), 0.0, 1e-6, "scrubbed to the start")
	assert_false(_a_leg_down(drawn), "riding off: both feet up")


func _a_leg_down(view: VisualBikeView) -> bool:
	return view.is_leg_down(-1.0) or view.is_leg_down(1.0)


func test_nothing_to_replay_says_so() -> void:
	_game.watch_replay()
	assert_false(_game.replay.visible)
	assert_true((_game.get_node(^"PauseMenu") as PauseMenu).visible)


func _tap(action: StringName) -> void:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	Input.parse_input_event(event)
	var release := InputEventAction.new()
	release.action = action
	Input.parse_input_event(release)
