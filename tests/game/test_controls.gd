extends TestCase
## The player's controls: a key or pad control rebound on the Controls screen holds after
## a restart; one already on another action swaps with it and the screen says so; reset
## brings the game's own back; a broken or hand-edited file gives the defaults with a
## message; the README's table is the game's own bindings.

const START_MENU := preload("res://scenes/ui/start_menu.tscn")

var _menu: ControlsMenu


func before_each() -> void:
	SettingsSandbox.enter()
	_menu = ControlsMenu.new()
	add_child(_menu)
	await wait_frames(1)


func after_each() -> void:
	_menu.queue_free()
	await wait_frames(1)
	SettingsSandbox.leave()


func test_a_key_rebound_on_the_screen_holds_after_a_restart() -> void:
	_menu.open()
	_menu.binding_button(&"throttle", Controls.KEYBOARD).emit_signal(&"pressed")
	assert_true(_menu.is_waiting())
	await _press_key(KEY_G)
	assert_false(_menu.is_waiting())
	assert_eq(Controls.binding_text(&"throttle", Controls.KEYBOARD), "G, ↑", "W gave way to G")
	Controls.reload()
	assert_eq(Controls.binding_text(&"throttle", Controls.KEYBOARD), "G, ↑", "read back")
	assert_true(_action_has_key(&"throttle", KEY_G), "the game reads it")
	assert_false(_action_has_key(&"throttle", KEY_W))


func test_a_key_taken_from_another_action_swaps_and_says_so() -> void:
	_menu.open()
	_menu.binding_button(&"throttle", Controls.KEYBOARD).emit_signal(&"pressed")
	await _press_key(KEY_S)
	assert_eq(Controls.binding_text(&"throttle", Controls.KEYBOARD), "S, ↑")
	assert_eq(
		Controls.binding_text(&"brake", Controls.KEYBOARD), "W, ↓", "brake took W in its place"
	)
	assert_has(_message().text, "S was brake (analog; both wheels): W now")


func test_a_pad_control_rebound_and_reset_to_the_defaults() -> void:
	_menu.open()
	_menu.binding_button(&"lift_bike", Controls.PAD).emit_signal(&"pressed")
	var motion := InputEventJoypadMotion.new()
	motion.axis = JOY_AXIS_TRIGGER_LEFT
	motion.axis_value = 0.9
	Input.parse_input_event(motion)
	await wait_frames(2)
	assert_eq(Controls.binding_text(&"lift_bike", Controls.PAD), "LT")
	assert_eq(Controls.binding_text(&"brake", Controls.PAD), "A", "brake took A")
	motion.axis_value = 0.0
	Input.parse_input_event(motion)
	(_menu.find_child("Reset", true, false) as Button).emit_signal(&"pressed")
	assert_eq(Controls.binding_text(&"lift_bike", Controls.PAD), "A")
	assert_eq(Controls.binding_text(&"brake", Controls.PAD), "LT")
	Controls.reload()
	assert_eq(Controls.binding_text(&"brake", Controls.PAD), "LT", "the file holds the defaults")


func test_esc_cancels_a_binding_and_then_leaves_the_screen() -> void:
	_menu.open()
	_menu.binding_button(&"pause", Controls.KEYBOARD).emit_signal(&"pressed")
	await _press_key(KEY_ESCAPE)
	assert_false(_menu.is_waiting(), "cancelled")
	assert_eq(Controls.binding_text(&"pause", Controls.KEYBOARD), "Esc, P", "nothing changed")
	assert_true(_menu.visible)
	await SimulatedInput.press_joypad_button(JOY_BUTTON_B)
	assert_false(_menu.visible, "B leaves")


func test_a_broken_file_gives_the_defaults_and_a_message() -> void:
	var file := FileAccess.open(Controls.controls_path, FileAccess.WRITE)
	file.store_string("[bindings\nthrottle = [")
	file.close()
	expect_error("ConfigFile parse error")
	Controls.reload()
	assert_eq(Controls.binding_text(&"throttle", Controls.KEYBOARD), "W, ↑", "the defaults")
	assert_has(Controls.problem, "could not be read")
	assert_true(FileAccess.file_exists(Controls.controls_path + ".broken"), "kept aside")
	var menu := START_MENU.instantiate()
	add_child(menu)
	await wait_frames(1)
	assert_has(
		(menu.get_node("%FileProblems") as Label).text, "Your controls file could not be read"
	)
	menu.queue_free()


func test_a_hand_edited_file_drops_what_it_cannot_bind() -> void:
	var file := FileAccess.open(Controls.controls_path, FileAccess.WRITE)
	file.store_string(
		(
			'[bindings]\nthrottle=PackedStringArray("key:NoSuchKey", "key:G")\n'
			+ 'fly=PackedStringArray("key:F")\nbrake=7\n'
		)
	)
	file.close()
	Controls.reload()
	assert_eq(Controls.binding_text(&"throttle", Controls.KEYBOARD), "G", "the key that exists")
	assert_eq(Controls.binding_text(&"brake", Controls.KEYBOARD), "S, ↓", "7 is no binding")
	assert_false(InputMap.has_action(&"fly"), "no action made up")


func test_the_readmes_table_is_the_games_own_bindings() -> void:
	var readme := FileAccess.get_file_as_string("res://README.md")
	var start := readme.find("-->", readme.find("<!-- controls:")) + 4
	var block := readme.substr(start, readme.find("<!-- /controls -->") - start).strip_edges()
	assert_eq(block, Controls.markdown_table(), "README.md's controls (the table to paste)")


func _message() -> Label:
	return _menu.find_child("Message", true, false) as Label


func _press_key(code: Key) -> void:
	for pressed: bool in [true, false]:
		var key := InputEventKey.new()
		key.physical_keycode = code
		key.keycode = code
		key.pressed = pressed
		Input.parse_input_event(key)
		await wait_frames(2)


static func _action_has_key(action: StringName, code: Key) -> bool:
	for event in InputMap.action_get_events(action):
		if event is InputEventKey and (event as InputEventKey).physical_keycode == code:
			return true
	return false
