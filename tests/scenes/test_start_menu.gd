extends TestCase
## The start menu shows the game's name and native version, offers the School and every
## level, and can be worked with a gamepad alone.

const START_MENU := preload("res://scenes/ui/start_menu.tscn")

var _menu: Control


func before_each() -> void:
	SettingsSandbox.enter()
	_menu = START_MENU.instantiate()
	add_child(_menu)
	await wait_frames(1)
	# A first launch opens on the School (test_school_menu.gd); these tests start at the levels.
	_menu.call(&"close_list")


func after_each() -> void:
	_menu.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_shows_the_game_name_and_native_version() -> void:
	assert_eq((_menu.get_node("Titles/GameTitle") as Label).text, "COUNTER-STEER")
	var version: Label = _menu.get_node("%VersionLabel")
	assert_has(version.text, "native %s" % NativeModule.version())
	assert_has(version.text, "Godot 4.6")


func test_offers_the_school_then_every_level() -> void:
	var levels: VBoxContainer = _menu.get_node("%Levels")
	assert_eq(levels.get_child_count(), Levels.keys().size() + 1)
	assert_eq(levels.get_child(0).name, &"School", "the School first")
	for key in Levels.keys():
		assert_not_null(levels.get_node_or_null(NodePath(key)), "a button for %s" % key)


func test_a_gamepad_alone_rides_the_second_level_freely() -> void:
	var chosen: Array[String] = []
	_menu.connect(&"ride_requested", func(level: String) -> void: chosen.append(level))
	var levels: VBoxContainer = _menu.get_node("%Levels")
	(levels.get_child(0) as Button).grab_focus()
	await SimulatedInput.press_joypad_button(JOY_BUTTON_DPAD_DOWN)
	assert_eq(get_viewport().gui_get_focus_owner(), levels.get_child(1), "d-pad down moves focus")
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	var list := _menu.get_node("%Challenges") as ChallengeMenu
	assert_true(list.visible, "the level's free ride and challenges")
	assert_eq(get_viewport().gui_get_focus_owner(), list.entry_button(-1), "on its free ride")
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	assert_eq(chosen, [levels.get_child(1).name as String] as Array[String])
	assert_ne(get_tree().current_scene, _menu, "an embedded menu does not navigate")


func test_a_levels_challenges_show_their_medals_per_bike() -> void:
	var gates := ChallengeCatalogue.load_challenge("res://scenes/challenges/levels/park_gates.tres")
	Progress.record(gates, "dirt_125", gates.gold)
	_menu.call(&"open_level", "skate_park", 0)
	var list := _menu.get_node("%Challenges") as ChallengeMenu
	assert_eq(list.entry_button(0).text, gates.title)
	assert_eq(get_viewport().gui_get_focus_owner(), list.entry_button(0))
	assert_not_null(list.entry_button(2), "the skate park's three challenges")
	var golds := list.find_children("*", "Control", true, false).filter(
		func(n: Node) -> bool:
			return n is MedalBadge and (n as MedalBadge).medal == Challenge.Medal.GOLD
	)
	assert_eq(golds.size(), 1, "gold on the dirt 125")


func test_the_backdrop_is_the_level_in_focus_in_the_games_light() -> void:
	var backdrop := _menu.get_node("Backdrop") as MenuBackdrop
	var viewport := backdrop.get_child(0) as SubViewport
	assert_true(viewport.own_world_3d, "a world of its own")
	var suns := viewport.find_children("*", "DirectionalLight3D", false, false)
	assert_eq(suns.size(), 1, "the game's sun")
	assert_true((suns[0] as DirectionalLight3D).shadow_enabled)
	var levels: VBoxContainer = _menu.get_node("%Levels")
	(levels.get_node("track") as Button).grab_focus()
	await wait_frames(1)
	var shown := viewport.get_children().filter(
		func(n: Node) -> bool: return n is Level and not n.is_queued_for_deletion()
	)
	assert_eq(shown.size(), 1, "one level")
	assert_eq((shown[0] as Node).scene_file_path, Levels.path_of("track"))


func test_b_asks_before_quitting_and_b_again_stays() -> void:
	var quits: Array[bool] = []
	_menu.connect(&"quit_requested", func() -> void: quits.append(true))
	var confirm := _menu.get_node("QuitConfirm") as QuitConfirm
	await SimulatedInput.press_joypad_button(JOY_BUTTON_B)
	assert_true(confirm.visible, "asked")
	assert_eq(get_viewport().gui_get_focus_owner().name, &"Stay", "the focus on staying")
	await SimulatedInput.press_joypad_button(JOY_BUTTON_B)
	assert_false(confirm.visible, "B again stays")
	assert_eq(quits, [] as Array[bool])
	await SimulatedInput.press_joypad_button(JOY_BUTTON_B)
	await SimulatedInput.press_joypad_button(JOY_BUTTON_DPAD_RIGHT)
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	assert_eq(quits, [true] as Array[bool], "Quit chosen")
	assert_true(is_instance_valid(_menu), "an embedded menu does not quit the game itself")
