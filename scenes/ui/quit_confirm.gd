class_name QuitConfirm
extends PanelContainer
## "Quit Counter-Steer?" over the start menu, the focus on staying: Esc / B at the top of
## the menu asks it rather than quitting at once. A second Esc / B stays.

## The player chose to quit.
signal quit_confirmed

var _stay: Button


func _ready() -> void:
	visible = false
	var style := StyleBoxFlat.new()
	style.bg_color = Color(0.06, 0.07, 0.1, 0.92)
	style.set_corner_radius_all(10)
	style.set_content_margin_all(26)
	add_theme_stylebox_override(&"panel", style)
	set_anchors_and_offsets_preset(Control.PRESET_CENTER)
	var lines := VBoxContainer.new()
	lines.add_theme_constant_override(&"separation", 18)
	add_child(lines)
	var question := Label.new()
	question.text = "Quit Counter-Steer?"
	question.horizontal_alignment = HORIZONTAL_ALIGNMENT_CENTER
	question.add_theme_font_size_override(&"font_size", 30)
	lines.add_child(question)
	var buttons := HBoxContainer.new()
	buttons.alignment = BoxContainer.ALIGNMENT_CENTER
	buttons.add_theme_constant_override(&"separation", 20)
	lines.add_child(buttons)
	_stay = _button("Stay", close)
	var quit := _button("Quit", quit_confirmed.emit)
	buttons.add_child(_stay)
	buttons.add_child(quit)
	# The focus stays on the question: the menu behind it is not to be reached from here.
	for button: Button in [_stay, quit]:
		var other := quit if button == _stay else _stay
		for side: Side in [SIDE_LEFT, SIDE_RIGHT]:
			button.set_focus_neighbor(side, button.get_path_to(other))
		for side: Side in [SIDE_TOP, SIDE_BOTTOM]:
			button.set_focus_neighbor(side, ^".")
	grow_horizontal = Control.GROW_DIRECTION_BOTH
	grow_vertical = Control.GROW_DIRECTION_BOTH


## Asks, the focus on staying.
func ask() -> void:
	visible = true
	_stay.grab_focus()


## Goes away: the player stays.
func close() -> void:
	visible = false


func _unhandled_input(event: InputEvent) -> void:
	if visible and event.is_action_pressed(&"ui_cancel"):
		get_viewport().set_input_as_handled()
		close()


func _button(text: String, action: Callable) -> Button:
	var button := Button.new()
	button.name = text
	button.text = text
	button.custom_minimum_size.x = 140.0
	button.add_theme_font_size_override(&"font_size", 24)
	button.pressed.connect(action)
	return button
