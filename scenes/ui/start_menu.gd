extends Control
## The start menu: the School's lessons, or a level to ride freely or take on its
## challenges (a list with the medals won on every bike; the backdrop shows the one in
## focus), the bike (the backdrop stands it at the start; its main figures below it) and
## the Lab (the research tools: the controller, the trajectory count, what the planners
## draw); shows the track's best lap on that bike and what native module runs underneath.
## Works with a gamepad alone (d-pad/stick to move, A to choose).
## `--native-info` prints the native module and exits (smoke tests, bug reports).

## The player chose a level to ride freely (its key in `Levels.keys()`), or a lesson or
## challenge (its file).
signal ride_requested(level: String)
signal challenge_requested(path: String)
## The player confirmed they want to quit the game.
signal quit_requested

const GAME := "res://scenes/game/game.tscn"
const SCHOOL := "res://scenes/levels/school/school.tscn"
## The start menu's entry of the School (a level's is its key).
const SCHOOL_ENTRY := "School"

## Whose list is open: SCHOOL_ENTRY or a level's key.
var _list_owner := ""
var _quit_confirm: QuitConfirm
var _lab: LabPanel
var _controls_menu: ControlsMenu

@onready var _version_label: Label = %VersionLabel
@onready var _status_label: Label = %StatusLabel
@onready var _tagline: Label = $Titles/Tagline
@onready var _levels: VBoxContainer = %Levels
@onready var _bike: OptionButton = %Bike
@onready var _bike_figures: Label = %BikeFigures
@onready var _best_lap: Label = %BestLap
@onready var _backdrop: MenuBackdrop = $Backdrop
@onready var _choices: Control = $Choices
@onready var _list: ChallengeMenu = %Challenges


func _ready() -> void:
	if NativeModule.info_requested():
		_print_native_info_and_quit()
		return
	_version_label.text = NativeModule.describe()
	# Only the menu that is the running scene navigates; embedded ones just report.
	_quit_confirm = QuitConfirm.new()
	_quit_confirm.name = "QuitConfirm"
	add_child(_quit_confirm)
	_quit_confirm.quit_confirmed.connect(quit_requested.emit)
	if get_tree().current_scene == self:
		ride_requested.connect(_ride)
		quit_requested.connect(get_tree().quit)
		challenge_requested.connect(func(path: String) -> void: ChallengeRun.ride(get_tree(), path))
	_build_choices()
	if not NativeModule.is_loaded():
		_status_label.text = "The native simulation is missing; the game cannot start."
		_status_label.add_theme_color_override(&"font_color", Color(1.0, 0.45, 0.4))
		for button: Button in _levels.get_children():
			button.disabled = true
		return
	_focus_where_the_player_left_off()
	_show_file_problems()


func _unhandled_input(event: InputEvent) -> void:
	if not event.is_action_pressed(&"ui_cancel") or _lab.visible or _controls_menu.visible:
		return
	get_viewport().set_input_as_handled()
	if _list.visible:
		close_list()
	else:
		_quit_confirm.ask()


## Shows the School's lessons in place of the levels, the focus on lesson `index`.
func open_school(index := 0) -> void:
	_open_list(SCHOOL_ENTRY)
	_list.show_lessons(ChallengeCatalogue.game(), str(Settings.get_value(&"bike")))
	_focus_entry(index)


## Shows level `key`'s free ride and challenges, the focus on challenge `index` (−1: the
## free ride); a level without challenges is ridden at once.
func open_level(key: String, index := -1) -> void:
	var paths := ChallengeCatalogue.game().challenges_on(Levels.path_of(key))
	if paths.is_empty():
		ride_requested.emit(key)
		return
	_open_list(key)
	_list.show_level(key, paths, str(Settings.get_value(&"bike")))
	_focus_entry(index)


## Back from a list to the levels, the focus on the entry that opened it.
func close_list() -> void:
	_list.visible = false
	_choices.visible = true
	_tagline.visible = true
	_status_label.visible = true
	(_levels.get_node(NodePath(_list_owner)) as Button).grab_focus()


func _open_list(owner_entry: String) -> void:
	_list_owner = owner_entry
	_choices.visible = false
	_list.visible = true
	# The list takes the room of the tagline and the hint (its Back button says it).
	_tagline.visible = false
	_status_label.visible = false


func _focus_entry(index: int) -> void:
	var button := _list.entry_button(index)
	if button == null or button.disabled:
		button = _list.entry_button(-1) if _list.entry_button(-1) != null else _list.entry_button(0)
	if button != null:
		button.grab_focus()


## Says what was wrong with the player's medals or controls files when they were read
## (each kept aside as *.broken, the game going on without them).
func _show_file_problems() -> void:
	var problems := PackedStringArray()
	for problem: String in [Progress.problem, Controls.problem]:
		if not problem.is_empty():
			problems.append(problem.left(1).to_upper() + problem.substr(1) + ".")
	if problems.is_empty():
		return
	%FileProblems.text = " ".join(problems)
	%FileProblems.visible = true


## Where the menu opens: on the first lesson until it has a medal, else on what was played
## last (a lesson, a level's challenge, or a level).
func _focus_where_the_player_left_off() -> void:
	var catalogue := ChallengeCatalogue.game()
	var last := Progress.last_played()
	var first := (
		ChallengeCatalogue.load_challenge(catalogue.lessons[0])
		if not catalogue.lessons.is_empty()
		else null
	)
	var lesson := _index_of(catalogue.lessons, last)
	var challenge := _index_of(catalogue.challenges, last)
	if first != null and Progress.best_medal(first.key()) == Challenge.Medal.NONE:
		open_school(0)
		return
	if lesson >= 0:
		open_school(lesson)
		return
	if challenge >= 0 and _open_level_at(catalogue.challenges[challenge]):
		return
	var key := last if Levels.keys().has(last) else str(Settings.get_value(&"level"))
	var chosen := _levels.get_node_or_null(NodePath(key)) as Button
	(chosen if chosen != null else _levels.get_child(0) as Button).grab_focus()


## Opens the list of the level the challenge at `path` is ridden on, the focus on it;
## false when that is none of the game's levels.
func _open_level_at(path: String) -> bool:
	var challenge := ChallengeCatalogue.load_challenge(path)
	var key := Levels.key_of(challenge.level) if challenge != null else ""
	if key.is_empty():
		return false
	open_level(key, ChallengeCatalogue.game().challenges_on(challenge.level).find(path))
	return true


## Where the file named `key` (a challenge's key) stands in `paths`; −1: not there.
static func _index_of(paths: Array[String], key: String) -> int:
	for i in paths.size():
		if paths[i].get_file().get_basename() == key:
			return i
	return -1


func _build_choices() -> void:
	var school := Button.new()
	school.name = SCHOOL_ENTRY
	school.text = "School: learn to ride"
	school.add_theme_font_size_override(&"font_size", 26)
	school.pressed.connect(open_school)
	school.focus_entered.connect(func() -> void: _backdrop.show_level(SCHOOL))
	_levels.add_child(school)
	_list.challenge_chosen.connect(func(path: String) -> void: challenge_requested.emit(path))
	_list.free_ride_chosen.connect(func(key: String) -> void: ride_requested.emit(key))
	_list.closed.connect(close_list)
	_list.challenge_focused.connect(_show_in_backdrop)
	for key in Levels.keys():
		var button := Button.new()
		button.name = key
		button.text = Levels.name_of(key)
		button.add_theme_font_size_override(&"font_size", 26)
		button.pressed.connect(open_level.bind(key, -1))
		# The backdrop shows the level the focus is on.
		button.focus_entered.connect(func() -> void: _backdrop.show_level(key))
		_levels.add_child(button)
	_build_bike_choice()
	_build_assist_choice()
	_lab = LabPanel.new()
	_lab.name = "Lab"
	add_child(_lab)
	_lab.closed.connect(func() -> void: %OpenLab.grab_focus())
	%OpenLab.pressed.connect(_lab.open)
	_controls_menu = ControlsMenu.new()
	_controls_menu.name = "ControlsMenu"
	add_child(_controls_menu)
	_controls_menu.closed.connect(func() -> void: %EditControls.grab_focus())
	%EditControls.pressed.connect(_controls_menu.open)
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


## The assist levels, the chosen one selected, with what it does below.
func _build_assist_choice() -> void:
	var levels: Array = Assists.LEVELS.keys()
	for level: String in levels:
		%Assist.add_item("Assist: %s" % Assists.LEVELS[level].name)
	%Assist.selected = maxi(levels.find(Settings.get_value(&"assist")), 0)
	%Assist.item_selected.connect(
		func(i: int) -> void:
			Settings.set_value(&"assist", levels[i])
			_show_assist()
	)
	_show_assist()


func _show_assist() -> void:
	var about: String = Assists.LEVELS[Settings.get_value(&"assist")].about
	%AssistAbout.text = about.left(1).to_upper() + about.substr(1) + "."


func _show_bike_figures() -> void:
	var bike := Bikes.description(str(Settings.get_value(&"bike")))
	_bike_figures.text = Bikes.figures_text(bike) if bike != null else ""


func _show_best_lap() -> void:
	var key := Bikes.record_key("track", str(Settings.get_value(&"bike")))
	_best_lap.text = "Best lap on the track: %s" % Level.format_time(Settings.best_lap(key))


## The challenge at `path` in the backdrop, or the level whose list is open (empty path).
func _show_in_backdrop(path: String) -> void:
	if path.is_empty():
		_backdrop.show_level(SCHOOL if _list_owner == SCHOOL_ENTRY else _list_owner)
	else:
		_backdrop.show_challenge(path)


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
