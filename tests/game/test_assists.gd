extends TestCase
## The assist levels: each a set of settings the game applies when chosen, every one rides
## the track's bot lap, Pro's full brake without ABS throws the rider where Full's stops
## standing, and the README's table is the game's.

var _game: Game
var _bot: BotRider


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	if _bot != null:
		_bot.release()
		_bot.queue_free()
	if _game != null:
		_game.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_choosing_a_level_sets_its_settings_and_the_bike_follows() -> void:
	assert_eq(Settings.get_value(&"assist"), "full", "a player starts on Full")
	Settings.set_value(&"assist", "pro")
	assert_eq(Settings.get_value(&"controller"), "arcade")
	assert_false(Settings.get_value(&"abs"))
	Settings.set_value(&"assist", "learner")
	assert_eq(Settings.get_value(&"controller"), "combined")
	assert_true(Settings.get_value(&"abs"))
	assert_almost_eq(Settings.get_value(&"lean_share"), 0.75, 1e-9)
	_game = (load("res://scenes/game/game.tscn") as PackedScene).instantiate() as Game
	_game.level_path = "res://scenes/levels/track/track.tscn"
	add_child(_game)
	await wait_physics_frames(2)
	assert_almost_eq(_game.bike.lean_share, 0.75, 1e-9, "the bike's turn is held to it")
	assert_true(_game.bike.abs)
	Settings.set_value(&"assist", "pro")
	assert_false(_game.bike.abs, "and follows a change at once")


func test_every_level_rides_the_tracks_bot_lap() -> void:
	for level: String in Assists.LEVELS:
		Settings.set_value(&"assist", level)
		var started: Array = await BotStart.start(
			self, "res://scenes/levels/track/track.tscn", Settings.get_value(&"controller")
		)
		_game = started[0]
		_bot = started[1]
		_bot.speed_kmh = 20.0
		var laps: Array[String] = []
		_game.level.announced.connect(func(text: String) -> void: laps.append(text))
		while laps.is_empty() and _game.level.elapsed < 90.0 and not _game.bike.is_crashed():
			await wait_physics_frames(1)
		assert_false(_game.bike.is_crashed(), "%s: no fall" % level)
		assert_eq(laps.size(), 1, "%s: a lap" % level)
		print("assist %s: %s" % [level, laps])
		_bot.release()
		_bot.queue_free()
		_game.queue_free()
		await wait_frames(1)
		_game = null
		_bot = null


func test_pro_throws_the_rider_on_a_full_brake_from_60_where_full_stops_standing() -> void:
	var bot := ChallengeBot.new(self)
	Settings.set_value(&"assist", "full")
	var full := await bot.full_brake(60.0, 145.0)
	assert_true(full != null and full.passed, "Full: stopped standing")
	Settings.set_value(&"assist", "pro")
	var pro := await bot.full_brake(60.0, 145.0)
	assert_not_null(pro)
	if pro != null:
		assert_false(pro.passed, "Pro: no ABS")
		assert_has(pro.why, "you fell")
		print("full brake from 60 km/h: Full %s; Pro %s" % [full.facts if full else [], pro.why])
	bot.free_all()


func test_the_readmes_table_is_the_games_own_levels() -> void:
	var readme := FileAccess.get_file_as_string("res://README.md")
	var start := readme.find("-->", readme.find("<!-- assists:")) + 4
	var block := readme.substr(start, readme.find("<!-- /assists -->") - start).strip_edges()
	assert_eq(block, Assists.markdown_table(), "README.md's assists (the table to paste)")
