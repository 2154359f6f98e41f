extends TestCase
## The rewind button: it puts a free ride back exactly where it was a few seconds before
## (a fall undone, the level's clock and the replay with it) and the game judges the ride
## on from there; a rewound lap runs on but is no record and makes no ghost; a lesson, the
## automatic test and a ride not begun refuse, saying why, on the button and in the menu.

const LESSON := "res://scenes/challenges/lessons/ride_off.tres"

var _game: Game
var _bot: BotRider


func after_each() -> void:
	for action: StringName in InputMap.get_actions():
		Input.action_release(action)
	if _bot != null:
		_bot.release()
		_bot.queue_free()
	if _game != null:
		_game.queue_free()
	await wait_frames(1)
	_game = null
	_bot = null
	SettingsSandbox.leave()


func test_a_rewind_undoes_a_fall_exactly_and_the_ride_is_judged_on() -> void:
	_game = await GameFixture.start(self)
	# Where the bike was after each control step, by step.
	var centres := {}
	var record := func() -> void:
		centres[_game.bike.get_step_count()] = _game.bike.get_center_of_mass()
	get_tree().physics_frame.connect(record)
	# Three seconds balanced, then nobody balancing and a nudge: it falls.
	Input.action_press(&"throttle", 0.5)
	await wait_physics_frames(180)
	await GameFixture.ride_unbalanced_and_nudge(self, _game)
	while not _game.bike.is_crashed() and _game.level.elapsed < 15.0:
		await wait_physics_frames(1)
	assert_true(_game.bike.is_crashed(), "nobody balancing: it fell")
	assert_eq(_game.falls, 1)
	# The game judges the fall in the frame after the bike's.
	await wait_physics_frames(1)
	var clock := _game.level.elapsed
	# A second on the ground: the level's clock stopped at the fall.
	await wait_physics_frames(60)
	get_tree().physics_frame.disconnect(record)
	Input.action_release(&"throttle")
	assert_eq(_game.level.elapsed, clock)
	var steps := _game.bike.get_step_count()
	var lying := 60.0 / Engine.physics_ticks_per_second
	var frames: int = _game.recorder.run().size()
	_game.rewind()
	var back := roundi(Game.REWIND_STEP / _game.bike.get_control_dt())
	assert_eq(_game.bike.get_step_count(), steps - back, "three seconds of steps undone")
	assert_false(_game.bike.is_crashed(), "the fall undone")
	var centre := _game.bike.get_center_of_mass()
	assert_eq(centre, centres[steps - back], "exactly where it was then")
	assert_almost_eq(
		_game.level.elapsed, clock - (Game.REWIND_STEP - lying), 0.05, "the clock went back"
	)
	assert_eq(_game.recorder.run().size(), frames - back, "the replay forgets the undone")
	assert_eq(_banner(), "Rewound 3.0 s")
	# Nobody balances it still: nudged, it falls again, and the game judges that fall.
	Input.action_press(&"steer_left", 0.5)
	await wait_physics_frames(10)
	Input.action_release(&"steer_left")
	while not _game.bike.is_crashed() and _game.level.elapsed < 15.0:
		await wait_physics_frames(1)
	await wait_physics_frames(1)
	assert_true(_game.bike.is_crashed())
	assert_eq(_game.falls, 2, "the ride was judged on from the rewind")


func test_the_button_rewinds_again_further_back_as_far_as_was_kept() -> void:
	_game = await GameFixture.start(self)
	await SimulatedInput.tap_action(&"rewind")
	assert_eq(_banner(), "No rewind: nothing to rewind yet: ride first")
	Input.action_press(&"throttle", 0.4)
	await wait_physics_frames(240)
	var kept := _game.bike.get_rewindable()
	assert_almost_eq(kept, 240.0 / Engine.physics_ticks_per_second, 0.1, "the ride so far")
	await SimulatedInput.tap_action(&"rewind")
	assert_eq(_banner(), "Rewound 3.0 s")
	# The tap's frames rode on a little.
	assert_almost_eq(_game.bike.get_rewindable(), kept - Game.REWIND_STEP, 0.1)
	Input.action_release(&"throttle")
	await SimulatedInput.tap_action(&"rewind")
	assert_true(_banner().begins_with("Rewound "), _banner())
	assert_lt(float(_banner().split(" ")[1]), Game.REWIND_STEP, "no more than was kept")
	assert_almost_eq(_game.bike.get_rewindable(), 0.0, 0.1, "back to the start of the ride")


func test_a_rewound_lap_runs_on_but_is_no_record() -> void:
	SettingsSandbox.enter()
	var started: Array = await BotStart.start(self, GameFixture.TRACK, "arcade")
	_game = started[0]
	_bot = started[1]
	_bot.speed_kmh = 25.0
	var track := _game.level as Track
	var announced: Array[String] = []
	track.announced.connect(announced.append)
	var finished := []
	track.lap_finished.connect(func(time: float, _best: bool) -> void: finished.append(time))
	while track.lap_time() < 5.0 and track.elapsed < 30.0:
		await wait_physics_frames(1)
	assert_true(_game.ghost_race.is_recording(), "the lap is recorded for a ghost")
	var lap := track.lap_time()
	await SimulatedInput.tap_action(&"rewind")
	assert_true(track.is_lap_rewound())
	assert_almost_eq(track.lap_time(), lap - Game.REWIND_STEP, 0.05, "its clock went back")
	assert_false(_game.ghost_race.is_recording(), "no ghost is made of it")
	assert_has(track.status_line(), "rewound")
	while announced.size() < 2 and track.elapsed < 120.0 and not _game.bike.is_crashed():
		await wait_physics_frames(1)
	print("rewound lap: %s" % [announced])
	assert_eq(announced[0], "Rewound: this lap will not count as a record")
	assert_eq(announced.size(), 2, "the lap came round")
	assert_true(announced[-1].ends_with("(rewound: not a record)"), announced[-1])
	assert_eq(finished, [], "no lap finished for the records")
	assert_eq(Settings.best_lap(track.record_key), INF, "no best lap")
	assert_false(FileAccess.file_exists(Settings.ghost_path(track.record_key)), "no ghost file")
	assert_true(_game.ghost_race.is_recording(), "the next lap is a lap like any")


func test_a_lesson_the_automatic_test_and_the_pause_menu_say_why_not() -> void:
	SettingsSandbox.enter()
	_game = GameFixture.GAME.instantiate() as Game
	_game.challenge_path = LESSON
	add_child(_game)
	await wait_physics_frames(2)
	Input.action_press(&"throttle")
	await wait_physics_frames(60)
	Input.action_release(&"throttle")
	await SimulatedInput.tap_action(&"rewind")
	assert_eq(_banner(), "No rewind: a lesson is judged whole (B / R to try again)")
	await SimulatedInput.tap_action(&"pause")
	var button := _game.get_node(^"PauseMenu/%Rewind") as Button
	assert_true(button.disabled)
	assert_eq(button.text, "No rewind: a lesson is judged whole (B / R to try again)")
	await SimulatedInput.tap_action(&"pause")
	_game.queue_free()
	await wait_frames(1)
	_game = await GameFixture.start(self, "res://scenes/levels/test_level/test_level.tscn")
	assert_eq(_game.rewind_refusal(), "the automatic test rides itself")


func test_the_pause_menus_rewind_closes_the_menu_and_rewinds() -> void:
	_game = await GameFixture.start(self)
	await SimulatedInput.tap_action(&"pause")
	var button := _game.get_node(^"PauseMenu/%Rewind") as Button
	assert_true(button.disabled, "nothing ridden yet")
	await SimulatedInput.tap_action(&"pause")
	Input.action_press(&"throttle", 0.5)
	await wait_physics_frames(240)
	Input.action_release(&"throttle")
	var steps := _game.bike.get_step_count()
	await SimulatedInput.tap_action(&"pause")
	assert_false(button.disabled)
	assert_eq(button.text, "Rewind 3 s")
	button.pressed.emit()
	await wait_physics_frames(1)
	assert_false(get_tree().paused, "back to the ride")
	assert_lt(_game.bike.get_step_count(), steps - 80, "rewound")


func _banner() -> String:
	return (_game.get_node(^"Hud/%Banner") as Label).text
