extends TestCase
## The HUD laid out with the longest text each of its labels can hold (the telemetry
## overlay on, 64 trajectories, four-digit planning times, a controller's failure in the
## banner, the
## longest level, challenge and bike names, a split) on every canvas a window gives it:
## 1280 × 720, 1920 × 1080 and 800 × 600 windows at UI scale 100 % and at the largest. No
## two labels, dials or pads may overlap, and none may leave the screen.

const HUD := preload("res://scenes/ui/hud.tscn")

const LONGEST := {
	"Status":
	(
		"The thesis's test, steered by you   ·   checkpoint 12 of 12   ·   lap 12:34.5"
		+ "   ·   99:59.9\nStreet 390"
	),
	"Performance":
	(
		"999 fps  ·  1.2 s ahead (no cost-to-go for this bike)  ·  resamples 99  ·  fallen "
		+ "steps 99  ·  disagreement 0.99  ·  effective samples 63.99"
	),
	"Speed": "199 km/h",
	"Lean": "lean -75°   wanted +75°",
}
## The banner's longest: a fall's cause, then what the player can do (`Hud.fallen_hint`,
## which is the hint's longest too).
const FALL := "Fell: low-side, the tyres slid out: the rider's head or body hit the ground"


func test_the_longest_texts_fit_every_window_at_every_ui_scale() -> void:
	var largest: float = Settings.entries[&"ui_scale"].max / 100.0
	var least_gap := INF
	for window in LayoutCheck.WINDOWS:
		for scale: float in [1.0, largest]:
			var canvas := LayoutCheck.canvas(window, scale)
			var hud := await _laid_out(canvas)
			var drawn := LayoutCheck.drawn(hud)
			assert_gt(drawn.size(), 8, "the HUD's labels, dial and pads are drawn")
			var problems := LayoutCheck.problems(drawn, Rect2(Vector2.ZERO, canvas))
			assert_eq(problems, PackedStringArray(), "%s window at %d %%" % [window, scale * 100])
			least_gap = minf(least_gap, LayoutCheck.smallest_gap(drawn))
			hud.get_parent().queue_free()
			await wait_frames(1)
	print(
		"HUD layout: the smallest gap between two of its labels, dials or pads %.1f px" % least_gap
	)


func test_the_ui_scale_setting_sizes_the_canvas_and_telemetry_starts_off() -> void:
	SettingsSandbox.enter()
	assert_false(Settings.get_value(&"telemetry"), "a player's HUD has no planner numbers")
	Settings.set_value(&"ui_scale", 125.0)
	assert_almost_eq(get_tree().root.content_scale_factor, 1.25, 1e-6)
	SettingsSandbox.leave()
	assert_almost_eq(
		get_tree().root.content_scale_factor, Settings.get_value(&"ui_scale") / 100.0, 1e-6
	)


func test_a_label_moved_onto_another_is_caught() -> void:
	var hud := await _laid_out(LayoutCheck.BASE)
	var speed := hud.get_node("%Speed") as Label
	var moved := Label.new()
	moved.text = "on the speed"
	hud.add_child(moved)
	moved.global_position = speed.get_global_rect().get_center()
	await wait_frames(1)
	var problems := LayoutCheck.problems(
		LayoutCheck.drawn(hud), Rect2(Vector2.ZERO, LayoutCheck.BASE)
	)
	assert_eq(problems.size(), 1, "one overlap: %s" % problems)
	if not problems.is_empty():
		assert_has(problems[0], "overlaps")
	hud.get_parent().queue_free()


## The overlay's first line at its longest: the longest controller's name planning with
## the most trajectories and the slowest plans.
static func _longest_controller_line() -> String:
	var longest := ""
	for name in NativeModule.controller_names():
		var label := NativeModule.controller_label(name)
		longest = label if label.length() > longest.length() else longest
	return "%s  ·  auto: 64 trajectories  ·  planning 9999.9 ms  ·  30 late/s" % longest


## The HUD in a viewport of `size` with the longest texts in every label, laid out.
func _laid_out(size: Vector2) -> Hud:
	var viewport := SubViewport.new()
	viewport.size = Vector2i(size)
	add_child(viewport)
	var hud := HUD.instantiate() as Hud
	viewport.add_child(hud)
	hud.telemetry = true
	hud.show_inputs(true)
	for label: String in LONGEST:
		(hud.get_node("%" + label) as Label).text = LONGEST[label]
	(hud.get_node("%Controller") as Label).text = _longest_controller_line()
	(hud.get_node("%Hint") as Label).text = Hud.fallen_hint()
	hud.announce(FALL + "\n" + Hud.fallen_hint())
	hud.show_split(12, 99.99)
	await wait_frames(3)
	return hud
