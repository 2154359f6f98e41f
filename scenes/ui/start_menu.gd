extends Control
## The start menu: pick a level (that starts the ride; the backdrop shows the one in
## focus), the bike (the backdrop stands it at the start; its main figures below it), the
## controller, the trajectory count and the auto-accelerate speed; shows the track's best
## lap on that bike and what native module runs underneath. Works with a gamepad alone
## (d-pad/stick to move, A to choose).
## `--native-info` prints the native module and exits (smoke tests, bug reports).

## The player chose a level to ride (its key in `Levels.ALL`), or a lesson (its file).
signal ride_requested(level: String)
signal lesson_requested(path: String)

const GAME := "res://scenes/game/game.tscn"
const SCHOOL := "res://scenes/levels/school/school.tscn"

@onready var _version_label: Label = %VersionLabel
@onready var _status_label: Label = %StatusLabel
@onready var _tagline: Label = $Titles/Tagline
@onready var _levels: VBoxContainer = %Levels
@onready var _bike: OptionButton = %Bike
@onready var _bike_figures: Label = %BikeFigures
@onready var _controller: OptionButton = %Controller
@onready var _trajectories: OptionButton = %Trajectories
@onready var _auto_speed: OptionButton = %AutoSpeed
@onready var _best_lap: Label = %BestLap
@onready var _backdrop: MenuBackdrop = $Backdrop
@onready var _choices: Control = $Choices
@onready var _school: SchoolMenu = %School


func _ready() -> void:
	if NativeModule.info_requested():
		_print_native_info_and_quit()
		return
	_version_label.text = NativeModule.describe()
	# Only the menu that is the running scene navigates; embedded ones just report.
	if get_tree().current_scene == self:
		ride_requested.connect(_ride)
		lesson_requested.connect(func(path: String) -> void: ChallengeRun.ride(get_tree(), path))
	_build_choices()
	if not NativeModule.is_loaded():
		_status_label.text = "The native simulation is missing; the game cannot start."
		_status_label.add_theme_color_override(&"font_color", Color(1.0, 0.45, 0.4))
		for button: Button in _levels.get_children():
			button.disabled = true
		return
	_focus_where_the_player_left_off()


func _unhandled_input(event: InputEvent) -> void:
	if not event.is_action_pressed(&"ui_cancel"):
		return
	get_viewport().set_input_as_handled()
	if _school.visible:
		close_school()
	else:
		get_tree().quit()


## Shows the School's lessons in place of the levels, the focus on lesson `index`.
func open_school(index := 0) -> void:
	_choices.visible = false
	_school.visible = true
	# The lessons take the room of the tagline and the hint (the Back button says it).
	_tagline.visible = false
	_status_label.visible = false
	_school.show_lessons(ChallengeCatalogue.game(), str(Settings.get_value(&"bike")))
	var button := _school.lesson_button(index)
	if button != null and not button.disabled:
		button.grab_focus()
	elif _school.lesson_button(0) != null:
		_school.lesson_button(0).grab_focus()


## Back from the School to the levels, the focus on its entry.
func close_school() -> void:
	_school.visible = false
	_choices.visible = true
	_tagline.visible = true
	_status_label.visible = true
	(_levels.get_node(^"School") as Button).grab_focus()


## Where the menu opens: on the first lesson until it has a medal, else on what was played
## last (a lesson in the School, or a level).
func _focus_where_the_player_left_off() -> void:
	var catalogue := ChallengeCatalogue.game()
	var last := Progress.last_played()
	var lessons := catalogue.lessons.map(
		func(path: String) -> String: return path.get_file().get_basename()
	)
	var first := (
		ChallengeCatalogue.load_challenge(catalogue.lessons[0])
		if not catalogue.lessons.is_empty()
		else null
	)
	if first != null and Progress.best_medal(first.key()) == Challenge.Medal.NONE:
		open_school(0)
	elif lessons.has(last):
		open_school(lessons.find(last))
	else:
		var chosen := (
			_levels.get_node_or_null(
				NodePath(last if Levels.ALL.has(last) else str(Settings.get_value(&"level")))
			)
			as Button
		)
		(chosen if chosen != null else _levels.get_child(0) as Button).grab_focus()


func _build_choices() -> void:
	var school := Button.new()
	school.name = "School"
	school.text = "School: learn to ride"
	school.add_theme_font_size_override(&"font_size", 26)
	school.pressed.connect(open_school)
	school.focus_entered.connect(func() -> void: _backdrop.show_level(SCHOOL))
	_levels.add_child(school)
	_school.lesson_chosen.connect(func(path: String) -> void: lesson_requested.emit(path))
	_school.closed.connect(close_school)
	_school.lesson_focused.connect(_backdrop.show_challenge)
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
	Progress.set_last_played(level)
	get_tree().change_scene_to_file(GAME)
