class_name ControlsMenu
extends PanelContainer
## The Controls screen: every action a player may rebind, with its keyboard and pad
## bindings (Controls). Choose a binding, then press the key, button, stick or trigger for
## it; one already on another action swaps with it, and the screen says so. Reset puts
## every binding back. Esc / B goes back (while waiting for a key, it cancels instead).

## The player left the screen.
signal closed

const COLUMN_WIDTH := 230.0

var _rows: GridContainer
var _message: Label
## What a press is awaited for: the action and the kind of binding (empty: nothing).
var _waiting_action := &""
var _waiting_kind := ""


func _ready() -> void:
	visible = false
	var style := StyleBoxFlat.new()
	style.bg_color = Color(0.05, 0.06, 0.09, 0.96)
	style.set_corner_radius_all(10)
	style.set_content_margin_all(22)
	add_theme_stylebox_override(&"panel", style)
	set_anchors_and_offsets_preset(Control.PRESET_FULL_RECT)
	offset_left = 60.0
	offset_top = 30.0
	offset_right = -60.0
	offset_bottom = -30.0
	var lines := VBoxContainer.new()
	lines.add_theme_constant_override(&"separation", 10)
	add_child(lines)
	var title := Label.new()
	title.text = "Controls"
	title.add_theme_font_size_override(&"font_size", 32)
	lines.add_child(title)
	_message = Label.new()
	_message.name = "Message"
	_message.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	_message.add_theme_font_size_override(&"font_size", 18)
	lines.add_child(_message)
	var scroll := ScrollContainer.new()
	scroll.size_flags_vertical = Control.SIZE_EXPAND_FILL
	scroll.follow_focus = true
	scroll.horizontal_scroll_mode = ScrollContainer.SCROLL_MODE_DISABLED
	lines.add_child(scroll)
	_rows = GridContainer.new()
	_rows.columns = 3
	_rows.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	_rows.add_theme_constant_override(&"h_separation", 16)
	scroll.add_child(_rows)
	var buttons := HBoxContainer.new()
	buttons.add_theme_constant_override(&"separation", 16)
	lines.add_child(buttons)
	buttons.add_child(_button("Reset", "Reset to defaults", _reset))
	buttons.add_child(_button("Back", "Back  (Esc / B)", close))
	Controls.changed.connect(_fill)
	_fill()


## Shows the screen, the focus on the first binding.
func open() -> void:
	_waiting_action = &""
	_message.text = "Choose a binding, then press the key or pad control for it."
	_fill()
	visible = true
	binding_button(Controls.ACTIONS.keys()[0], Controls.KEYBOARD).grab_focus()


## Hides the screen.
func close() -> void:
	visible = false
	_waiting_action = &""
	closed.emit()


## The button of `action`'s binding of `kind` (Controls.KEYBOARD or PAD).
func binding_button(action: StringName, kind: String) -> Button:
	return _rows.get_node_or_null(NodePath("%s_%s" % [action, kind])) as Button


## Whether a press is awaited.
func is_waiting() -> bool:
	return not _waiting_action.is_empty()


func _input(event: InputEvent) -> void:
	if not visible or not is_waiting():
		return
	if event is InputEventKey and (event as InputEventKey).keycode == KEY_ESCAPE:
		get_viewport().set_input_as_handled()
		if event.is_pressed():
			_stop_waiting("Nothing changed.")
		return
	var taken := _press_of(event)
	if taken == null:
		return
	get_viewport().set_input_as_handled()
	var action := _waiting_action
	var note := Controls.bind(action, taken)
	_stop_waiting(
		(
			"%s: %s.%s"
			% [
				Controls.ACTIONS[action],
				Controls.event_text(taken),
				"  " + note if not note.is_empty() else ""
			]
		)
	)


func _unhandled_input(event: InputEvent) -> void:
	if visible and not is_waiting() and event.is_action_pressed(&"ui_cancel"):
		get_viewport().set_input_as_handled()
		close()


## The binding `event` gives the awaited kind: a key pressed for the keyboard; a button
## pressed, or a stick or trigger pushed past half way, for the pad (null: not one).
func _press_of(event: InputEvent) -> InputEvent:
	if _waiting_kind == Controls.KEYBOARD and event is InputEventKey and event.is_pressed():
		var key := InputEventKey.new()
		key.physical_keycode = (event as InputEventKey).physical_keycode
		if key.physical_keycode == KEY_NONE:
			key.physical_keycode = (event as InputEventKey).keycode
		return key
	if _waiting_kind != Controls.PAD:
		return null
	if event is InputEventJoypadButton and event.is_pressed():
		var button := InputEventJoypadButton.new()
		button.button_index = (event as InputEventJoypadButton).button_index
		button.pressed = true
		return button
	if event is InputEventJoypadMotion and absf((event as InputEventJoypadMotion).axis_value) > 0.5:
		var motion := InputEventJoypadMotion.new()
		motion.axis = (event as InputEventJoypadMotion).axis
		motion.axis_value = signf((event as InputEventJoypadMotion).axis_value)
		return motion
	return null


func _wait_for(action: StringName, kind: String) -> void:
	_waiting_action = action
	_waiting_kind = kind
	var what := "a key" if kind == Controls.KEYBOARD else "a pad button, stick or trigger"
	_message.text = "Press %s for %s (Esc: cancel)." % [what, Controls.ACTIONS[action]]
	binding_button(action, kind).text = "…"


func _stop_waiting(text: String) -> void:
	var action := _waiting_action
	var kind := _waiting_kind
	_waiting_action = &""
	_message.text = text
	_fill()
	if not action.is_empty():
		binding_button(action, kind).grab_focus()


func _reset() -> void:
	Controls.reset_to_defaults()
	_message.text = "Every binding is back to the game's own."


func _fill() -> void:
	if _rows == null:
		return
	if _rows.get_child_count() == 0:
		for header: String in ["", "keyboard", "pad"]:
			var label := Label.new()
			label.text = header
			label.add_theme_font_size_override(&"font_size", 17)
			_rows.add_child(label)
		for action: StringName in Controls.ACTIONS:
			var name := Label.new()
			name.text = Controls.ACTIONS[action]
			name.size_flags_horizontal = Control.SIZE_EXPAND_FILL
			_rows.add_child(name)
			for kind: String in [Controls.KEYBOARD, Controls.PAD]:
				var button := Button.new()
				button.name = "%s_%s" % [action, kind]
				button.custom_minimum_size.x = COLUMN_WIDTH
				button.pressed.connect(_wait_for.bind(action, kind))
				_rows.add_child(button)
	for action: StringName in Controls.ACTIONS:
		for kind: String in [Controls.KEYBOARD, Controls.PAD]:
			binding_button(action, kind).text = Controls.binding_text(action, kind)


static func _button(name: String, text: String, action: Callable) -> Button:
	var button := Button.new()
	button.name = name
	button.text = text
	button.add_theme_font_size_override(&"font_size", 20)
	button.pressed.connect(action)
	return button
