class_name SchoolMenu
extends VBoxContainer
## The School: the lessons in the order they teach, each with the medal won on every bike
## (the chosen bike's best score beside them), locked until the one before has a medal.
## A lesson that cannot be ridden (its file or level missing) says so instead.

## The player chose the lesson at `path`, or went back.
signal lesson_chosen(path: String)
signal closed
## The focus moved to the lesson at `path` (the menu's backdrop shows it).
signal lesson_focused(path: String)

var _catalogue: ChallengeCatalogue
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
	var intro := Label.new()
	intro.text = "School: short lessons, one idea each; a medal opens the next."
	intro.add_theme_font_size_override(&"font_size", 20)
	head.add_child(intro)
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


## Lists the lessons of `catalogue` with their medals, the bike `bike` (a `Bikes` key)
## shown first among the bikes.
func show_lessons(catalogue: ChallengeCatalogue, bike: String) -> void:
	_catalogue = catalogue
	_bike = bike
	for old in _rows.get_children():
		old.free()
	var bikes := Bikes.rideable()
	_rows.columns = 2 + bikes.size()
	_rows.add_child(Control.new())
	for key in bikes:
		_rows.add_child(_small_label(Bikes.description(key).name, key == bike))
	_rows.add_child(
		_small_label(
			(
				"best on %s" % Bikes.description(bike).name
				if Bikes.description(bike) != null
				else "best"
			),
			true
		)
	)
	for index in catalogue.lessons.size():
		_add_row(index, bikes)


## The button of lesson `index` (for focus and tests).
func lesson_button(index: int) -> Button:
	return _rows.get_node_or_null(NodePath("Lesson%d" % (index + 1))) as Button


func _add_row(index: int, bikes: Array[String]) -> void:
	var path := _catalogue.lessons[index]
	var lesson := ChallengeCatalogue.load_challenge(path)
	var button := Button.new()
	button.name = "Lesson%d" % (index + 1)
	button.alignment = HORIZONTAL_ALIGNMENT_LEFT
	button.add_theme_font_size_override(&"font_size", 20)
	button.custom_minimum_size.x = 380.0
	var problem := "its file is missing" if lesson == null else lesson.problem()
	var open := _catalogue.lesson_open(index)
	if not problem.is_empty():
		button.text = (
			"%d  %s: %s" % [index + 1, path.get_file().get_basename().capitalize(), problem]
		)
		button.disabled = true
	else:
		button.text = "%d  %s" % [index + 1, lesson.title]
		button.disabled = not open
		button.tooltip_text = lesson.brief
		button.pressed.connect(func() -> void: lesson_chosen.emit(path))
	button.focus_entered.connect(
		func() -> void:
			_about.text = _about_text(lesson, problem, open)
			lesson_focused.emit(path)
	)
	_rows.add_child(button)
	for key in bikes:
		var badge := MedalBadge.new(30.0 if key == _bike else 22.0)
		badge.size_flags_vertical = Control.SIZE_SHRINK_CENTER
		badge.size_flags_horizontal = Control.SIZE_SHRINK_CENTER
		badge.locked = problem.is_empty() and not open
		if lesson != null:
			badge.medal = Progress.medal(lesson.key(), key)
		_rows.add_child(badge)
	var best := _small_label("", true)
	if lesson != null and problem.is_empty():
		best.text = lesson.format(Progress.best(lesson.key(), _bike)) if open else "locked"
	_rows.add_child(best)


## What the lesson in focus asks and what its medals need (or why it cannot be ridden).
static func _about_text(lesson: Challenge, problem: String, open: bool) -> String:
	if lesson == null or not problem.is_empty():
		return (
			"This lesson cannot be ridden: %s."
			% (problem if lesson != null else "its file is missing")
		)
	var text := "%s\n%s: %s" % [lesson.brief, lesson.score_label(), lesson.thresholds_text()]
	return text if open else "Locked: a medal in the lesson before opens it.\n" + lesson.brief


static func _small_label(text: String, bright: bool) -> Label:
	var label := Label.new()
	label.text = text
	label.vertical_alignment = VERTICAL_ALIGNMENT_CENTER
	label.horizontal_alignment = HORIZONTAL_ALIGNMENT_CENTER
	label.add_theme_font_size_override(&"font_size", 17)
	label.add_theme_color_override(&"font_color", Color(1, 0.96, 0.88, 1.0 if bright else 0.6))
	return label
