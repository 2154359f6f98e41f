extends TestCase
## The School in the start menu: a first launch opens on its first lesson, a later one on
## what was played last; lessons show their medals per bike, open one by one, and a lesson
## that cannot be ridden says why; a gamepad alone starts one and goes back.

const START_MENU := preload("res://scenes/ui/start_menu.tscn")

var _menu: Control


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	if _menu != null:
		_menu.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_a_first_launch_opens_on_the_first_lesson() -> void:
	await _open_menu()
	var school := _menu.get_node("%Challenges") as ChallengeMenu
	assert_true(school.visible, "the School is open")
	assert_false((_menu.get_node("Choices") as Control).visible, "the levels are not")
	assert_eq(get_viewport().gui_get_focus_owner(), school.entry_button(0), "lesson 1 in focus")
	assert_false(school.entry_button(0).disabled)
	assert_true(school.entry_button(1).disabled, "lesson 2 waits for a medal in lesson 1")


func test_a_medal_opens_the_next_lesson_and_the_menu_opens_where_the_player_left_off() -> void:
	var first := _lesson(0)
	Progress.record(first, "street_390", first.bronze)
	Progress.set_last_played(_lesson(1).key())
	await _open_menu()
	var school := _menu.get_node("%Challenges") as ChallengeMenu
	assert_true(school.visible)
	assert_false(school.entry_button(1).disabled, "lesson 2 open")
	assert_true(school.entry_button(2).disabled, "lesson 3 still locked")
	assert_eq(get_viewport().gui_get_focus_owner(), school.entry_button(1), "on lesson 2")
	var badges := school.find_children("*", "Control", true, false).filter(
		func(n: Node) -> bool: return n is MedalBadge and (n as MedalBadge).medal != 0
	)
	assert_eq(badges.size(), 1, "one medal shown: bronze on the street 390")


func test_a_levels_challenge_played_last_opens_that_levels_list_on_it() -> void:
	var first := _lesson(0)
	Progress.record(first, "street_390", first.gold)
	Progress.set_last_played("park_air")
	await _open_menu()
	var list := _menu.get_node("%Challenges") as ChallengeMenu
	assert_true(list.visible)
	assert_eq(get_viewport().gui_get_focus_owner(), list.entry_button(2), "on the air time")


func test_a_level_played_last_is_where_the_menu_opens_once_lesson_1_is_passed() -> void:
	var first := _lesson(0)
	Progress.record(first, "dirt_125", first.gold)
	Progress.set_last_played("track")
	await _open_menu()
	assert_false((_menu.get_node("%Challenges") as Control).visible)
	assert_eq(get_viewport().gui_get_focus_owner().name, &"track")


func test_a_gamepad_starts_lesson_1_and_b_goes_back_to_the_levels() -> void:
	await _open_menu()
	var chosen: Array[String] = []
	_menu.connect(&"challenge_requested", func(path: String) -> void: chosen.append(path))
	await SimulatedInput.press_joypad_button(JOY_BUTTON_A)
	assert_eq(chosen, [ChallengeCatalogue.game().lessons[0]] as Array[String])
	await SimulatedInput.press_joypad_button(JOY_BUTTON_B)
	assert_false((_menu.get_node("%Challenges") as Control).visible, "back at the levels")
	assert_eq(get_viewport().gui_get_focus_owner().name, &"School", "on the School's entry")
	assert_true(
		is_instance_valid(_menu) and _menu.is_inside_tree(), "B in the School does not quit"
	)


func test_a_lesson_whose_file_or_level_is_missing_says_so() -> void:
	var broken := Challenge.new()
	broken.title = "Nowhere"
	broken.level = "res://scenes/levels/nowhere.tscn"
	broken.judge = StopJudge.new()
	broken.area = ^"Area"
	ResourceSaver.save(broken, "user://test-broken-lesson.tres")
	var catalogue := ChallengeCatalogue.new()
	catalogue.lessons = [
		"user://test-broken-lesson.tres", "res://scenes/challenges/lessons/missing.tres"
	]
	expect_error("missing.tres is not a challenge")
	var school := ChallengeMenu.new()
	add_child(school)
	school.show_lessons(catalogue, "street_390")
	assert_has(school.entry_button(0).text, "its level res://scenes/levels/nowhere.tscn is missing")
	assert_true(school.entry_button(0).disabled)
	assert_has(school.entry_button(1).text, "its file is missing")
	school.queue_free()
	DirAccess.remove_absolute("user://test-broken-lesson.tres")


func _open_menu() -> void:
	_menu = START_MENU.instantiate()
	add_child(_menu)
	await wait_frames(2)


static func _lesson(index: int) -> Challenge:
	return ChallengeCatalogue.load_challenge(ChallengeCatalogue.game().lessons[index])
