class_name LabPanel
extends PanelContainer
## The Lab: what only researchers use, out of the player's menus. The controller by its
## own name, the planners' trajectory count (or the automatic N), the motor force, the
## learned cost-to-go, the trajectory view, the physical bodies and the planner telemetry
## overlay: every setting of the schema's "Lab" group (SettingControls), and the count.
## The start menu and the pause menu each open it; Esc / B closes it.

## The player closed the Lab.
signal closed

var _settings: SettingControls
var _trajectories: OptionButton
var _syncing := false


func _ready() -> void:
	visible = false
	var style := StyleBoxFlat.new()
	style.bg_color = Color(0.05, 0.06, 0.09, 0.95)
	style.set_corner_radius_all(10)
	style.set_content_margin_all(24)
	add_theme_stylebox_override(&"panel", style)
	set_anchors_and_offsets_preset(Control.PRESET_CENTER)
	grow_horizontal = Control.GROW_DIRECTION_BOTH
	grow_vertical = Control.GROW_DIRECTION_BOTH
	custom_minimum_size = Vector2(560, 0)
	var lines := VBoxContainer.new()
	lines.add_theme_constant_override(&"separation", 10)
	add_child(lines)
	lines.add_child(_label("Lab", 32))
	lines.add_child(
		_label("The research tools: who balances, how the planners plan, what they draw.", 17)
	)
	_settings = SettingControls.new()
	_settings.name = "Settings"
	_settings.lab = true
	lines.add_child(_settings)
	lines.add_child(_label("Trajectories", 18))
	_trajectories = OptionButton.new()
	_trajectories.name = "Trajectories"
	for label in Settings.trajectory_labels():
		_trajectories.add_item(label)
	_trajectories.item_selected.connect(
		func(i: int) -> void:
			if not _syncing:
				Settings.choose_trajectories(i)
	)
	lines.add_child(_trajectories)
	var close_button := Button.new()
	close_button.name = "Close"
	close_button.text = "Close  (Esc / B)"
	close_button.pressed.connect(close)
	lines.add_child(close_button)


## Shows the Lab with the settings' current values, the focus on its first control.
func open() -> void:
	_syncing = true
	_settings.sync()
	_trajectories.selected = Settings.trajectory_choice()
	_syncing = false
	visible = true
	var first := _settings.get_children().filter(func(n: Node) -> bool: return not n is Label)
	(first[0] if not first.is_empty() else _trajectories).grab_focus()


## Hides the Lab.
func close() -> void:
	visible = false
	closed.emit()


## The Lab's control of setting `key` (null if it has none).
func control_of(key: StringName) -> Control:
	return _settings.control_of(key)


func _unhandled_input(event: InputEvent) -> void:
	if visible and (event.is_action_pressed(&"ui_cancel") or event.is_action_pressed(&"pause")):
		get_viewport().set_input_as_handled()
		close()


static func _label(text: String, size: int) -> Label:
	var label := Label.new()
	label.text = text
	label.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	label.add_theme_font_size_override(&"font_size", size)
	return label
