extends TestCase
## The player chooses the bike: the start menu offers the three with their figures and
## stands the chosen one in its backdrop, the game rides the bike the settings hold, the
## HUD and the pause menu name it, best laps and ghosts are kept per bike (the street
## bike's under the keys they had before there was a choice), and a bike that cannot be
## built is refused, naming the bike and the field (a field this build does not know too).

const START_MENU := preload("res://scenes/ui/start_menu.tscn")
const GAME := preload("res://scenes/game/game.tscn")
const TRACK := "res://scenes/levels/track/track.tscn"

var _node: Node


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	if _node != null:
		_node.queue_free()
		_node = null
	await wait_frames(1)
	SettingsSandbox.leave()


func test_the_bikes_are_the_settings_choices_and_each_can_be_built() -> void:
	assert_eq(Bikes.keys(), ["street_390", "dirt_125", "sport_600"] as Array[String])
	assert_eq(Bikes.rideable(), Bikes.keys())
	var names: Array[String] = []
	for key: String in Bikes.keys():
		var bike := Bikes.description(key)
		names.append(bike.name)
		assert_eq(bike.problem(), "", "%s builds" % key)
	assert_eq(names, ["Street 390", "Dirt 125", "Sport 600"] as Array[String])
	assert_eq(
		Bikes.figures_text(Bikes.description("dirt_125")),
		"94 kg · 26.7 kW · 38.5° lean · 315 mm travel"
	)


func test_a_bike_that_cannot_be_built_is_refused_naming_the_bike_and_the_field() -> void:
	var broken := (
		(load(Bikes.path_of("sport_600")) as BikeDescription).duplicate() as BikeDescription
	)
	broken.set(&"engine/max_power_kw", 900.0)
	assert_has(broken.problem(), "Sport 600")
	assert_has(broken.problem(), "engine/max_power_kw")
	assert_eq(broken.figures(), {}, "no figures for a bike that cannot be built")
	expect_error("no bike is called moped")
	assert_null(Bikes.description("moped"))


func test_a_bike_file_with_a_field_this_build_does_not_know_is_refused_naming_it() -> void:
	# Godot drops a property no class has without a word: a misspelled field, or one
	# from a newer build, would ride as the reference's value.
	var text := FileAccess.get_file_as_string(Bikes.path_of("sport_600"))
	text = text.replace("rider/wrists_follow_bar", "rider/wrist_follows_bar")
	var path := "user://test-bikes/misspelled.tres"
	DirAccess.make_dir_recursive_absolute(path.get_base_dir())
	FileAccess.open(path, FileAccess.WRITE).store_string(text)
	var misspelled := ResourceLoader.load(path, "", ResourceLoader.CACHE_MODE_IGNORE)
	assert_has(misspelled.problem(), "Sport 600")
	assert_has(misspelled.problem(), "'rider/wrist_follows_bar' is not a bike field")
	assert_eq(misspelled.figures(), {}, "no figures for a bike that cannot be built")
	DirAccess.remove_absolute(path)
	var shipped := load(Bikes.path_of("sport_600")) as BikeDescription
	assert_eq(shipped.problem(), "", "the shipped file's fields are all known")
	shipped = shipped.duplicate() as BikeDescription
	shipped.set(&"metadata/note", "a level designer's note")
	assert_eq(shipped.problem(), "", "metadata is Godot's, not a field")


func test_the_start_menu_offers_every_bike_with_its_figures_and_stands_it_in_the_backdrop() -> void:
	_node = START_MENU.instantiate()
	add_child(_node)
	await wait_physics_frames(3)
	var choice := _node.get_node("%Bike") as OptionButton
	assert_eq(choice.item_count, 3)
	assert_eq(choice.get_item_text(choice.selected), "Street 390", "the default bike")
	var backdrop := _node.get_node("Backdrop") as MenuBackdrop
	assert_eq(backdrop.bike().bike.name, "Street 390", "the backdrop stands the chosen bike")
	choice.select(1)
	choice.item_selected.emit(1)
	await wait_physics_frames(3)
	assert_eq(Settings.get_value(&"bike"), "dirt_125", "the choice is saved")
	assert_has((_node.get_node("%BikeFigures") as Label).text, "38.5° lean")
	assert_eq(backdrop.bike().bike.name, "Dirt 125")
	assert_eq(backdrop.bike().process_mode, Node.PROCESS_MODE_DISABLED, "drawn, then stopped")
	assert_has((_node.get_node("%BestLap") as Label).text, "Best lap on the track")


func test_the_game_rides_the_chosen_bike_names_it_and_keeps_its_records_apart() -> void:
	Settings.set_value(&"bike", "sport_600")
	var game := GAME.instantiate() as Game
	game.level_path = TRACK
	_node = game
	add_child(game)
	await wait_physics_frames(3)
	await wait_frames(2)
	assert_eq(game.bike_key, "sport_600")
	assert_eq(game.bike.bike.name, "Sport 600")
	assert_has((game.get_node("Hud/%Status") as Label).text, "Sport 600", "the HUD names it")
	assert_has((game.get_node("PauseMenu/%BikeSummary") as Label).text, "Sport 600 ")
	var track := game.level as Track
	assert_eq(track.record_key, "track@sport_600")
	assert_eq(Settings.ghost_path(track.record_key).get_file(), "track@sport_600.ghost")
	assert_true(Settings.record_lap(track.record_key, 61.0))
	assert_eq(Settings.best_lap("track"), INF, "the street bike's best lap is its own")
	assert_eq(Bikes.record_key("track", "street_390"), "track", "the street bike's old key")
