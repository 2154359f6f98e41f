class_name SettingControls
extends VBoxContainer
## The controls of every player setting the schema puts in a menu (`SettingsSchema`
## entries with a `menu` group), built from the entries: a switch for a true/false
## setting, a list for one with offered values or choices or the controller, a slider over
## the range for any other number. Each control is named after its setting and saves at once.
## The player's groups, or with `lab` the Lab's (the research tools).

## The group of the research tools, shown only in the Lab.
const LAB := "Lab"

## Shows the Lab's settings instead of the player's.
@export var lab := false

var _syncing := false


func _ready() -> void:
	for key: StringName in Settings.entries:
		var entry: Dictionary = Settings.entries[key]
		if not entry.menu.is_empty() and (entry.menu == LAB) == lab:
			_add_control(entry)
	Graphics.applied.connect(_show_graphics_preset)


## The graphics list's auto names the preset auto chose.
func _show_graphics_preset(_preset: String) -> void:
	var list := control_of(&"graphics_quality") as OptionButton
	if list != null:
		var entry: Dictionary = Settings.entries[&"graphics_quality"]
		list.set_item_text(0, _choice_label(entry, _choices(&"graphics_quality")[0]))


## The control of setting `key` (null if the menu has none).
func control_of(key: StringName) -> Control:
	return get_node_or_null(NodePath(String(key))) as Control


## Shows the settings' current values.
func sync() -> void:
	_syncing = true
	for key: StringName in Settings.entries:
		var control := control_of(key)
		var value: Variant = Settings.get_value(key)
		if control is OptionButton:
			(control as OptionButton).selected = maxi(_choices(key).find(value), 0)
		elif control is BaseButton:
			(control as BaseButton).button_pressed = value
		elif control is Range:
			(control as Range).value = value
		if control != null:
			_show_value(key)
	_syncing = false


func _add_control(entry: Dictionary) -> void:
	var key: StringName = entry.name
	var control: Control
	if typeof(entry.default) == TYPE_BOOL:
		var check := CheckButton.new()
		check.text = entry.label
		check.toggled.connect(_save.bind(key))
		control = check
	elif key == &"controller" or not entry.offered.is_empty() or not entry.choices.is_empty():
		var list := OptionButton.new()
		for choice: Variant in _choices(key):
			list.add_item(_choice_label(entry, choice))
		list.item_selected.connect(func(i: int) -> void: _save(_choices(key)[i], key))
		control = list
	else:
		var slider := HSlider.new()
		slider.min_value = entry.min
		slider.max_value = entry.max
		slider.step = entry.step
		slider.value_changed.connect(
			func(v: float) -> void:
				_save(roundi(v) if typeof(entry.default) == TYPE_INT else v, key)
		)
		control = slider
	if not control is CheckButton:
		var label := Label.new()
		label.name = String(key) + "_label"
		add_child(label)
	control.name = String(key)
	control.tooltip_text = entry.description
	add_child(control)


## The values a list offers for setting `key`: the controllers players pick, a name
## setting's choices, or the offered values in the setting's type.
func _choices(key: StringName) -> Array:
	if key == &"controller":
		return Array(NativeModule.controller_names())
	var entry: Dictionary = Settings.entries[key]
	if not entry.choices.is_empty():
		return Array(entry.choices)
	var choices := []
	for value: float in entry.offered:
		choices.append(roundi(value) if typeof(entry.default) == TYPE_INT else value)
	return choices


static func _choice_label(entry: Dictionary, choice: Variant) -> String:
	if entry.name == &"controller":
		return NativeModule.controller_label(choice)
	if entry.name == &"graphics_quality" and choice == "auto":
		return "Auto (%s)" % Graphics.preset.capitalize()
	if typeof(choice) == TYPE_STRING:
		return String(choice).capitalize()
	return "%s %s" % [Settings.number_text(choice), entry.unit]


func _save(value: Variant, key: StringName) -> void:
	if _syncing:
		return
	Settings.set_value(key, value)
	_show_value(key)


## A slider's label shows its value in the setting's unit ("share": a percentage).
func _show_value(key: StringName) -> void:
	var label := get_node_or_null(NodePath(String(key) + "_label")) as Label
	if label == null:
		return
	var entry: Dictionary = Settings.entries[key]
	var value: Variant = Settings.get_value(key)
	if control_of(key) is OptionButton:
		label.text = entry.label
	elif entry.unit == "share":
		label.text = "%s: %d %%" % [entry.label, roundi(value * 100.0)]
	else:
		var shown := "%d" % value if fmod(entry.step, 1.0) == 0.0 else "%.2f" % value
		label.text = "%s: %s %s" % [entry.label, shown, entry.unit]
