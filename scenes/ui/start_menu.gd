extends Control
## The start menu: pick a level (that starts the ride; the backdrop shows the one in
## focus), the bike (the backdrop stands it at the start; its main figures below it), the
## controller, the trajectory count and the auto-accelerate speed; shows the track's best
## lap on that bike and what native module runs underneath. Works with a gamepad alone
## (d-pad/stick to move, A to choose).
## `--native-info` prints the native module and exits (smoke tests, bug reports).

## The player chose a level to ride (its key in `Levels.ALL`).
signal ride_requested(level: String)

const GAME := "res://scenes/game/game.tscn"

@onready var _version_label: Label = %VersionLabel
@onready var _status_label: Label = %StatusLabel
@onready var _levels: VBoxContainer = %Levels
@onready var _bike: OptionButton = %Bike
@onready var _bike_figures: Label = %BikeFigures
@onready var _controller: OptionButton = %Controller
@onready var _trajectories: OptionButton = %Trajectories
@onready var _auto_speed: OptionButton = %AutoSpeed
@onready var _best_lap: Label = %BestLap
@onready var _backdrop: MenuBackdrop = $Backdrop


func _ready() -> void:
	if NativeModule.info_requested():
		_print_native_info_and_quit()
		return
	_version_label.text = NativeModule.describe()
	# Only the menu that is the running scene navigates; embedded ones just report.
	if get_tree().current_scene == self:
		ride_requested.connect(_ride)
	_build_choices()
	if not NativeModule.is_loaded():
		_status_label.text = "The native simulation is missing; the game cannot start."
		_status_label.add_theme_color_override(&"font_color", Color(1.0, 0.45, 0.4))
		for button: Button in _levels.get_children():
			button.disabled = true
		return
	var chosen := _levels.get_node_or_null(NodePath(str(Settings.get_value(&"level")))) as Button
	(chosen if chosen != null else _levels.get_child(0) as Button).grab_focus()


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"ui_cancel"):
		get_tree().quit()


func _build_choices() -> void:
	for key: String in Levels.ALL:
		var button := Button.new()
		button.name = key
		button.text = Levels.NAMES[key]
		button.add_theme_font_size_override(&"font_size", 26)
		button.pressed.connect(func() -> void: ride_requested.emit(key))
		# The backdrop shows the level the focus is on.
		button.focus_entered.connect(func() -> void: _backdrop.show_level(key))
		_levels.add_child(button)
	_build_bike_choice()
	for name in NativeModule.controller_names():
		_controller.add_item(NativeModule.controller_label(name))
	_controller.selected = maxi(
		NativeModule.controller_names().find(Settings.get_value(&"controller")), 0
	)
	_controller.item_selected.connect(
		func(i: int) -> void: Settings.set_value(&"controller", NativeModule.controller_names()[i])
	)
	for label in Settings.trajectory_labels():
		_trajectories.add_item(label)
	_trajectories.selected = Settings.trajectory_choice()
	_trajectories.item_selected.connect(Settings.choose_trajectories)
	for speed in Settings.offered(&"auto_speed_kmh"):
		_auto_speed.add_item("test speed %d km/h" % speed)
	_auto_speed.selected = maxi(
		Settings.offered(&"auto_speed_kmh").find(Settings.get_value(&"auto_speed_kmh")), 0
	)
	_auto_speed.item_selected.connect(
		func(i: int) -> void:
			Settings.set_value(&"auto_speed_kmh", Settings.offered(&"auto_speed_kmh")[i])
	)
	_show_best_lap()


## The bikes that can be ridden (one that cannot is left out, its error naming the bike
## and the field), the chosen one selected.
func _build_bike_choice() -> void:
	var keys := Bikes.rideable()
	for key: String in keys:
		_bike.add_item(Bikes.description(key).name)
	var chosen := keys.find(str(Settings.get_value(&"bike")))
	_bike.selected = maxi(chosen, 0)
	if chosen < 0 and not keys.is_empty():
		Settings.set_value(&"bike", keys[0])
	_show_bike_figures()
	_bike.item_selected.connect(
		func(i: int) -> void:
			Settings.set_value(&"bike", keys[i])
			_show_bike_figures()
			_show_best_lap()
			_backdrop.show_bike(keys[i])
	)


func _show_bike_figures() -> void:
	var bike := Bikes.description(str(Settings.get_value(&"bike")))
	_bike_figures.text = Bikes.figures_text(bike) if bike != null else ""


func _show_best_lap() -> void:
	var key := Bikes.record_key("track", str(Settings.get_value(&"bike")))
	_best_lap.text = "Best lap on the track: %s" % Level.format_time(Settings.best_lap(key))


## `--native-info`: print what native module is loaded and exit; non-zero when it is missing
## or unsuitable. Used to check an exported build and for bug reports.
func _print_native_info_and_quit() -> void:
	print(NativeModule.describe())
	var platform := NativeModule.platform()
	for key: String in platform:
		print("  %s: %s" % [key, platform[key]])
	# Quitting before the first frame has run makes the release template's containers
	# report spurious signal errors while they are torn down.
	await get_tree().process_frame
	get_tree().quit(0 if NativeModule.ode_is_suitable() else 1)


func _ride(level: String) -> void:
	Settings.set_value(&"level", level)
	get_tree().change_scene_to_file(GAME)
