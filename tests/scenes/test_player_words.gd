extends TestCase
## What a player reads speaks riding, not research: every label, button, list item and
## tooltip of the start menu (its levels, the School and every level's list), the pause
## menu and the default HUD, the Lab panels aside, holds none of the research words.

const START_MENU := preload("res://scenes/ui/start_menu.tscn")
## Words only the Lab and the telemetry overlay may use (lower case; "trajector" and
## "resampl" stand for their word families).
const RESEARCH_WORDS: Array[String] = [
	"c-pbp", "trajector", "resampl", "planning", "late/s", "planner", "mppi"
]


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	SettingsSandbox.leave()


func test_the_start_menu_and_its_lists_speak_riding() -> void:
	var menu := START_MENU.instantiate()
	add_child(menu)
	await wait_frames(2)
	var read := _texts(menu)
	menu.call(&"open_school", 0)
	read.append_array(_texts(menu))
	for key in Levels.keys():
		menu.call(&"open_level", key, -1)
		read.append_array(_texts(menu))
	assert_gt(read.size(), 30, "the menus' texts were read")
	_assert_no_research_words(read, "the start menu")
	menu.queue_free()
	await wait_frames(1)


func test_the_pause_menu_and_the_default_hud_speak_riding() -> void:
	var game := await GameFixture.start(self)
	await wait_frames(2)
	_assert_no_research_words(_texts(game.get_node("Hud")), "the HUD")
	var pause := game.get_node("PauseMenu") as PauseMenu
	pause.open()
	await wait_frames(1)
	_assert_no_research_words(_texts(pause), "the pause menu")
	pause.close()
	game.queue_free()
	await wait_frames(1)


func test_the_research_tools_are_in_the_lab() -> void:
	var game := await GameFixture.start(self)
	var pause := game.get_node("PauseMenu") as PauseMenu
	for key: StringName in [&"controller", &"show_trajectories", &"physical_model", &"telemetry"]:
		var control := pause.control_of(key)
		assert_not_null(control, "%s in a menu" % key)
		if control != null:
			assert_true(pause.get_node("Lab").is_ancestor_of(control), "%s in the Lab" % key)
	game.queue_free()
	await wait_frames(1)


## Every text of the visible controls below `root` but a Lab's: labels, buttons, list
## items and tooltips.
static func _texts(root: Node) -> PackedStringArray:
	var texts := PackedStringArray()
	for node in root.find_children("*", "Control", true, false):
		var control := node as Control
		if not control.is_visible_in_tree() or _in_a_lab(control):
			continue
		texts.append(control.tooltip_text)
		if control is Label:
			texts.append((control as Label).text)
		elif control is OptionButton:
			for i in (control as OptionButton).item_count:
				texts.append((control as OptionButton).get_item_text(i))
		elif control is Button:
			texts.append((control as Button).text)
	return texts


static func _in_a_lab(control: Control) -> bool:
	var node: Node = control
	while node != null:
		if node is LabPanel:
			return true
		node = node.get_parent()
	return false


func _assert_no_research_words(texts: PackedStringArray, where: String) -> void:
	for text in texts:
		for word in RESEARCH_WORDS:
			assert_false(text.to_lower().contains(word), "%s says '%s': %s" % [where, word, text])
