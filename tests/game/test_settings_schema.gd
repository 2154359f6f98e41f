extends TestCase
## A setting is one entry of the native schema: a throwaway one added at run time reaches
## the game node's properties, the player's settings file, the pause menu and the tools'
## JSON, with its range and default, and nothing else is written for it.

const PAUSE_MENU := preload("res://scenes/ui/pause_menu.tscn")
const THROWAWAY := {
	name = &"throwaway_setting",
	label = "Throwaway",
	description = "A test's setting, in no build.",
	unit = "cm",
	default = 2.5,
	min = 0.0,
	max = 10.0,
	step = 0.5,
	owner = "planner",
	player = true,
	menu = "Planner",
}
## A name setting with choices, a display's.
const THROWAWAY_CHOICE := {
	name = &"throwaway_choice",
	label = "Throwaway choice",
	description = "A test's list, in no build.",
	default = "calm",
	choices = ["calm", "rough_sea"],
	owner = "display",
	player = true,
	menu = "View",
}


func before_all() -> void:
	for entry: Dictionary in [THROWAWAY, THROWAWAY_CHOICE]:
		var refusal := SettingsSchema.extend(entry)
		assert_true(refusal.is_empty() or refusal.contains("already"), refusal)


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	SettingsSandbox.leave()


func test_the_node_has_it_as_a_property_with_its_range_and_default() -> void:
	var bike := BikeSimulation.new()
	var found := bike.get_property_list().filter(
		func(p: Dictionary) -> bool: return p.name == "throwaway_setting"
	)
	assert_eq(found.size(), 1)
	assert_eq(found[0].type, TYPE_FLOAT)
	assert_eq(found[0].hint, PROPERTY_HINT_RANGE)
	assert_eq(found[0].hint_string, "0,10,0.5,suffix:cm")
	assert_eq(bike.get(&"throwaway_setting"), 2.5)
	bike.set(&"throwaway_setting", 4.0)
	assert_eq(bike.get(&"throwaway_setting"), 4.0)
	assert_eq(bike.property_get_revert(&"throwaway_setting"), 2.5)
	bike.free()


func test_the_players_file_keeps_it() -> void:
	Settings.reload()
	assert_eq(Settings.get_value(&"throwaway_setting"), 2.5)
	Settings.set_value(&"throwaway_setting", 3.0)
	var saved := ConfigFile.new()
	assert_eq(saved.load(SettingsSandbox.SETTINGS), OK)
	assert_eq(saved.get_value(Settings.SECTION, "throwaway_setting"), 3.0)
	expect_error("it is within 0–10 cm")
	Settings.set_value(&"throwaway_setting", 11.0)
	assert_eq(Settings.get_value(&"throwaway_setting"), 3.0)


func test_the_pause_menu_shows_a_slider_over_its_range() -> void:
	Settings.reload()
	var menu: PauseMenu = PAUSE_MENU.instantiate()
	add_child(menu)
	var slider := menu.control_of(&"throwaway_setting") as HSlider
	assert_not_null(slider)
	assert_eq([slider.min_value, slider.max_value, slider.step], [0.0, 10.0, 0.5])
	slider.value = 6.5
	assert_eq(Settings.get_value(&"throwaway_setting"), 6.5, "moving it saves it")
	menu.free()


func test_a_name_with_choices_is_a_list_in_the_pause_menu_and_holds_only_them() -> void:
	Settings.reload()
	var menu: PauseMenu = PAUSE_MENU.instantiate()
	add_child(menu)
	var list := menu.control_of(&"throwaway_choice") as OptionButton
	assert_not_null(list)
	assert_eq(list.item_count, 2)
	assert_eq(list.get_item_text(1), "Rough Sea")
	list.select(1)
	list.item_selected.emit(1)
	assert_eq(Settings.get_value(&"throwaway_choice"), "rough_sea", "picking it saves it")
	expect_error("it is one of calm, rough_sea")
	Settings.set_value(&"throwaway_choice", "storm")
	assert_eq(Settings.get_value(&"throwaway_choice"), "rough_sea")
	menu.free()


func test_a_default_that_is_not_one_of_the_choices_is_refused() -> void:
	var entry := THROWAWAY_CHOICE.duplicate()
	entry.name = &"throwaway_bad_choice"
	entry.default = "storm"
	var refusal := SettingsSchema.extend(entry)
	assert_true(refusal.contains("is one of calm, rough_sea"), refusal)


func test_the_tools_json_lists_it() -> void:
	var schema: Dictionary = JSON.parse_string(SettingsSchema.to_json())
	var found: Array = schema.settings.filter(
		func(e: Dictionary) -> bool: return e.name == "throwaway_setting"
	)
	assert_eq(found.size(), 1)
	assert_eq(found[0].range, [0.0, 10.0, 0.5])
	assert_eq(found[0].owner, "planner")


func test_the_game_starts_from_the_players_default_the_node_from_the_tools() -> void:
	var entry := THROWAWAY.duplicate()
	entry.name = &"throwaway_player_start"
	entry.player_default = 7.5
	var refusal := SettingsSchema.extend(entry)
	assert_true(refusal.is_empty() or refusal.contains("already"), refusal)
	Settings.reload()
	assert_eq(Settings.get_value(&"throwaway_player_start"), 7.5)
	var bike := BikeSimulation.new()
	assert_eq(bike.get(&"throwaway_player_start"), 2.5)
	assert_eq(bike.property_get_revert(&"throwaway_player_start"), 2.5)
	bike.free()
	Settings.set_value(&"throwaway_player_start", 1.0)
	Settings.reload()
	assert_eq(Settings.get_value(&"throwaway_player_start"), 1.0, "a player's choice is kept")


func test_the_learned_cost_to_go_is_a_switch_in_the_pause_menu() -> void:
	Settings.reload()
	assert_eq(Settings.get_value(&"terminal_value"), true, "on for a player")
	var bike := BikeSimulation.new()
	assert_eq(bike.terminal_value, false, "off for the node and the tools: bit-exact rows")
	bike.free()
	var menu: PauseMenu = PAUSE_MENU.instantiate()
	add_child(menu)
	assert_true(menu.control_of(&"terminal_value") is CheckButton, "a switch in the menu")
	menu.free()


func test_a_players_default_is_a_value_of_a_player_setting() -> void:
	var entry := THROWAWAY.duplicate()
	entry.name = &"throwaway_bad_player_start"
	entry.player_default = 12.0
	assert_true(SettingsSchema.extend(entry).contains("within 0–10"))
	entry.player_default = 4.0
	entry.player = false
	assert_true(SettingsSchema.extend(entry).contains("only a player setting"))
