class_name ChallengeMenu
extends VBoxContainer
## A list of lessons or challenges with the medal won on every bike (the chosen bike's
## best score beside them): the School's lessons, each locked until the one before has a
## medal, or a level's challenges after a free ride of it. One that cannot be ridden (its
## file or level missing) says so instead.

## The player chose the challenge at `path`, a free ride of the level `level_key`, or went
## back.
signal challenge_chosen(path: String)
signal free_ride_chosen(level_key: String)
signal closed
## The focus moved to the challenge at `path` (empty: the free ride); the menu's backdrop
## shows it.
signal challenge_focused(path: String)

const FREE_RIDE := "FreeRide"

var _paths: Array[String] = []
var _progressive := false
var _intro: Label
var _rows: GridContainer
var _about: Label
var _bike := ""


func _ready() -> void:
	add_theme_constant_override(&"separation", 10)
	var head := HBoxContainer.new()
	head.add_theme_constant_override(&"separation", 20)
	add_child(head)
	var back := Button.new()
	back.name = "Back"
	back.text = "Back  (Esc / B)"
	back.custom_minimum_size.x = 160.0
	back.add_theme_font_size_override(&"font_size", 20)
	back.pressed.connect(func() -> void: closed.emit())
	head.add_child(back)
	_intro = Label.new()
	_intro.add_theme_font_size_override(&"font_size", 20)
	head.add_child(_intro)
	_rows = GridContainer.new()
	_rows.add_theme_constant_override(&"h_separation", 14)
	_rows.add_theme_constant_override(&"v_separation", 4)
	add_child(_rows)
	_about = Label.new()
	_about.name = "About"
	_about.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	_about.custom_minimum_size.y = 56.0
	_about.add_theme_font_size_override(&"font_size", 18)
	_about.add_theme_color_override(&"font_color", Color(1, 0.96, 0.88, 0.9))
	add_child(_about)


## The School: `catalogue`'s lessons in order, each opened by a medal in the one before;
## the medals of bike `bike` (a `Bikes` key) shown first.
func show_lessons(catalogue: ChallengeCatalogue, bike: String) -> void:
	_intro.text = "School: short lessons, one idea each; a medal opens the next."
	_show(catalogue.lessons, true, "", bike)


## Level `level_key`'s challenges (`paths`, all open) after a free ride of it.
func show_level(level_key: String, paths: Array[String], bike: String) -> void:
	_intro.text = "%s: ride it freely, or take on its challenges." % Levels.name_of(level_key)
	_show(paths, false, level_key, bike)


## The button of entry `index` (a lesson or challenge; -1: the free ride), for focus and tests.
func entry_button(index: int) -> Button:
	var name := FREE_RIDE if index < 0 else "Entry%d" % (index + 1)
	return _rows.get_node_or_null(NodePath(name)) as Button


func _show(paths: Array[String], progressive: bool, level_key: String, bike: String) -> void:
	_paths = paths
	_progressive = progressive
	_bike = bike
	for old in _rows.get_children():
		old.free()
	var bikes := Bikes.rideable()
	_rows.columns = 2 + bikes.size()
	_rows.add_child(Control.new())
	for key in bikes:
		_rows.add_child(_small_label(Bikes.description(key).name, key == bike))
	var chosen := Bikes.description(bike)
	_rows.add_child(_small_label("best on %s" % chosen.name if chosen != null else "best", true))
	if not level_key.is_empty():
		_add_free_ride(level_key, bikes.size())
	for index in paths.size():
		_add_row(index, bikes)


func _add_free_ride(level_key: String, bike_count: int) -> void:
	var button := _row_button(FREE_RIDE, "Free ride")
	button.pressed.connect(func() -> void: free_ride_chosen.emit(level_key))
	button.focus_entered.connect(
		func() -> void:
			_about.text = "Ride the level as you like: no goal, no clock but the level's own."
			challenge_focused.emit("")
	)
	_rows.add_child(button)
	for _i in bike_count + 1:
		_rows.add_child(Control.new())


func _add_row(index: int, bikes: Array[String]) -> void:
	var path := _paths[index]
	var challenge := ChallengeCatalogue.load_challenge(path)
	var problem := "its file is missing" if challenge == null else challenge.problem()
	var open := not _progressive or _open(index)
	var number := "%d  " % (index + 1) if _progressive else ""
	var button := _row_button("Entry%d" % (index + 1), "")
	if not problem.is_empty():
		button.text = "%s%s: %s" % [number, path.get_file().get_basename().capitalize(), problem]
		button.disabled = true
	else:
		button.text = number + challenge.title
		button.disabled = not open
		button.tooltip_text = challenge.brief
		button.pressed.connect(func() -> void: challenge_chosen.emit(path))
	button.focus_entered.connect(
		func() -> void:
			_about.text = _about_text(challenge, problem, open)
			challenge_focused.emit(path)
	)
	_rows.add_child(button)
	for key in bikes:
		var badge := MedalBadge.new(30.0 if key == _bike else 22.0)
		badge.size_flags_vertical = Control.SIZE_SHRINK_CENTER
		badge.size_flags_horizontal = Control.SIZE_SHRINK_CENTER
		badge.locked = problem.is_empty() and not open
		if challenge != null:
			badge.medal = Progress.medal(challenge.key(), key)
		_rows.add_child(badge)
	var best := _small_label("", true)
	if challenge != null and problem.is_empty():
		best.text = challenge.format(Progress.best(challenge.key(), _bike)) if open else "locked"
	_rows.add_child(best)


## Whether entry `index` of a progressive list is open: the first always, each other once
## the one before has a medal on any bike (or cannot be ridden, so it locks nothing).
func _open(index: int) -> bool:
	if index <= 0:
		return true
	var before := ChallengeCatalogue.load_challenge(_paths[index - 1])
	return before == null or Progress.best_medal(before.key()) > Challenge.Medal.NONE


## What the challenge in focus asks and what its medals need (or why it cannot be ridden).
static func _about_text(challenge: Challenge, problem: String, open: bool) -> String:
	if challenge == null or not problem.is_empty():
		var why := problem if challenge != null else "its file is missing"
		return "This cannot be ridden: %s." % why
	var text := (
		"%s\n%s: %s" % [challenge.brief, challenge.score_label(), challenge.thresholds_text()]
	)
	return text if open else "Locked: a medal in the lesson before opens it.\n" + challenge.brief


static func _row_button(node_name: String, text: String) -> Button:
	var button := Button.new()
	button.name = node_name
	button.text = text
	button.alignment = HORIZONTAL_ALIGNMENT_LEFT
	button.add_theme_font_size_override(&"font_size", 20)
	button.custom_minimum_size.x = 380.0
	return button


static func _small_label(text: String, bright: bool) -> Label:
	var label := Label.new()
	label.text = text
	label.vertical_alignment = VERTICAL_ALIGNMENT_CENTER
	label.horizontal_alignment = HORIZONTAL_ALIGNMENT_CENTER
	label.add_theme_font_size_override(&"font_size", 17)
	label.add_theme_color_override(&"font_color", Color(1, 0.96, 0.88, 1.0 if bright else 0.6))
	return label
