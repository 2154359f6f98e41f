class_name ChallengeCard
extends CanvasLayer
## What a player reads around a lesson or challenge: before the ride, its briefing (what
## to do in one line, the controls that matter, the medals' thresholds, the best so far);
## riding, the HUD says how it stands and draws the player's hands; after, the result
## (the medal, the score, what the ride measured, or what went wrong) with retry, next
## and menu.

## The player asked to try again, to go on to the next lesson, or back to the menu.
signal retry_requested
signal next_requested
signal menu_requested

## The controls, as the briefing names them, by the names a challenge's `inputs` use.
const CONTROLS := {
	"throttle": "throttle: RT / W",
	"brake": "brake: LT / S",
	"turn": "turn: left stick / A D",
	"weight": "the rider's weight: right stick / I J K L",
}
const PANEL_WIDTH := 760.0
const FAIL_COLOUR := Color(1.0, 0.72, 0.35)

var _run: ChallengeRun
var _bike: BikeSimulation
## "Lesson 3" or "Challenge", above the title.
var _kind := ""
var _has_next := false

var _briefing: PanelContainer
var _result: PanelContainer
var _result_badge: MedalBadge
var _result_title: Label
var _result_lines: Label
var _next_button: Button
var _retry_button: Button


## Shows `run` ridden on `bike`; `kind` heads the card ("Lesson 2"), and `has_next`
## offers the next lesson after a medal.
func setup(run: ChallengeRun, bike: BikeSimulation, kind: String, has_next: bool) -> void:
	_run = run
	_bike = bike
	_kind = kind
	_has_next = has_next
	_build()
	run.finished.connect(_show_result)


## Shows the briefing again (a new attempt is about to start).
func show_briefing() -> void:
	_result.visible = false
	_briefing.visible = true
	_fill_briefing()


## Whether the result is showing, and its text (for tests and screenshots).
func is_result_shown() -> bool:
	return _result.visible


func result_text() -> String:
	return "%s\n%s" % [_result_title.text, _result_lines.text]


func briefing_text() -> String:
	return (
		(_briefing.get_child(0) as VBoxContainer)
		. get_children()
		. map(func(node: Node) -> String: return (node as Label).text if node is Label else "")
		. reduce(func(all: String, line: String) -> String: return all + "\n" + line, "")
	)


func _process(_delta: float) -> void:
	if _run != null and _briefing.visible and not _bike.is_waiting_for_throttle():
		_briefing.visible = false


func _fill_briefing() -> void:
	var challenge := _run.challenge
	var lines := _briefing.get_child(0) as VBoxContainer
	(lines.get_node(^"Kind") as Label).text = _kind.to_upper()
	(lines.get_node(^"Title") as Label).text = challenge.title
	(lines.get_node(^"Brief") as Label).text = challenge.brief
	var controls := PackedStringArray()
	for input in challenge.inputs:
		controls.append(CONTROLS.get(input, input))
	(lines.get_node(^"Controls") as Label).text = "   ·   ".join(controls)
	(lines.get_node(^"Medals") as Label).text = (
		"%s: %s" % [challenge.score_label(), challenge.thresholds_text()]
	)
	var best := _run.best_so_far()
	(lines.get_node(^"Best") as Label).text = (
		(
			"your best on this bike: %s (%s)"
			% [challenge.format(best), Challenge.MEDAL_NAMES[_run.medal_so_far()]]
		)
		if is_finite(best)
		else "not ridden on this bike yet"
	)


func _show_result(result: ChallengeResult, medal: Challenge.Medal, new_best: bool) -> void:
	var challenge := _run.challenge
	_briefing.visible = false
	_result.visible = true
	_result_badge.medal = medal
	var lines := PackedStringArray()
	if result.passed:
		_result_title.text = (
			Challenge.MEDAL_NAMES[medal].to_upper()
			if medal != Challenge.Medal.NONE
			else "Done, no medal yet"
		)
		_result_title.remove_theme_color_override(&"font_color")
		lines.append(
			(
				"%s: %s%s"
				% [
					challenge.score_label(),
					challenge.format(result.score),
					"   ·   new best" if new_best else ""
				]
			)
		)
		if medal < Challenge.Medal.GOLD:
			var next_medal := (medal + 1) as Challenge.Medal
			lines.append(
				(
					"%s needs %s"
					% [
						Challenge.MEDAL_NAMES[next_medal],
						challenge.format(challenge.threshold(next_medal))
					]
				)
			)
	else:
		_result_title.text = "Not yet"
		_result_title.add_theme_color_override(&"font_color", FAIL_COLOUR)
		lines.append(result.why.left(1).to_upper() + result.why.substr(1))
	lines.append_array(result.facts)
	_result_lines.text = "\n".join(lines)
	_next_button.visible = _has_next and _run.medal_so_far() > Challenge.Medal.NONE
	_retry_button.text = "Retry  (%s)" % Controls.prompt(&"reset_bike")
	(_next_button if _next_button.visible else _retry_button).grab_focus()


func _build() -> void:
	_briefing = _panel("Briefing")
	var brief_lines := _briefing.get_child(0) as VBoxContainer
	for spec: Array in [
		["Kind", 18, 0.7],
		["Title", 38, 1.0],
		["Brief", 24, 0.95],
		["Controls", 19, 0.8],
		["Medals", 19, 0.85],
		["Best", 18, 0.7]
	]:
		brief_lines.add_child(_label(spec[0], spec[1], spec[2]))
	brief_lines.add_child(_label("Start", 20, 0.9))
	(brief_lines.get_node(^"Start") as Label).text = "RT / W to ride   ·   Back / Esc: pause"
	_result = _panel("Result")
	var result_lines := _result.get_child(0) as VBoxContainer
	var head := HBoxContainer.new()
	head.add_theme_constant_override(&"separation", 18)
	_result_badge = MedalBadge.new(64.0)
	head.add_child(_result_badge)
	_result_title = _label("Title", 34, 1.0)
	_result_title.size_flags_horizontal = Control.SIZE_EXPAND_FILL
	head.add_child(_result_title)
	result_lines.add_child(head)
	_result_lines = _label("Lines", 21, 0.92)
	result_lines.add_child(_result_lines)
	var buttons := HBoxContainer.new()
	buttons.alignment = BoxContainer.ALIGNMENT_CENTER
	buttons.add_theme_constant_override(&"separation", 16)
	_retry_button = _button("Retry", retry_requested)
	_next_button = _button("Next lesson", next_requested)
	buttons.add_child(_retry_button)
	buttons.add_child(_next_button)
	buttons.add_child(_button("Menu", menu_requested))
	result_lines.add_child(buttons)
	_result.visible = false
	show_briefing()


func _panel(panel_name: String) -> PanelContainer:
	var panel := PanelContainer.new()
	panel.name = panel_name
	var style := StyleBoxFlat.new()
	style.bg_color = Color(0.06, 0.07, 0.1, 0.82)
	style.set_corner_radius_all(10)
	style.set_content_margin_all(22)
	panel.add_theme_stylebox_override(&"panel", style)
	panel.set_anchors_and_offsets_preset(Control.PRESET_CENTER_TOP)
	panel.offset_left = -PANEL_WIDTH / 2.0
	panel.offset_right = PANEL_WIDTH / 2.0
	panel.offset_top = 110.0
	var lines := VBoxContainer.new()
	lines.add_theme_constant_override(&"separation", 8)
	panel.add_child(lines)
	add_child(panel)
	return panel


func _label(label_name: String, font_size: int, alpha: float) -> Label:
	var label := Label.new()
	label.name = label_name
	label.autowrap_mode = TextServer.AUTOWRAP_WORD_SMART
	label.add_theme_font_size_override(&"font_size", font_size)
	label.add_theme_color_override(&"font_color", Color(1.0, 0.97, 0.9, alpha))
	return label


func _button(text: String, pressed: Signal) -> Button:
	var button := Button.new()
	button.text = text
	button.add_theme_font_size_override(&"font_size", 22)
	button.pressed.connect(func() -> void: pressed.emit())
	return button
