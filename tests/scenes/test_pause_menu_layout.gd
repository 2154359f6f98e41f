extends TestCase
## The pause menu fits every window at every UI scale: its buttons, the settings' and the
## controls' lists stay on the screen (the lists scroll), with the rewind's longest refusal
## on its button.

const PAUSE_MENU := preload("res://scenes/ui/pause_menu.tscn")


func test_the_menu_fits_every_window_at_every_ui_scale() -> void:
	var largest: float = Settings.entries[&"ui_scale"].max / 100.0
	for window in LayoutCheck.WINDOWS:
		for scale: float in [1.0, largest]:
			var canvas := LayoutCheck.canvas(window, scale)
			var viewport := SubViewport.new()
			viewport.size = Vector2i(canvas)
			add_child(viewport)
			var menu := PAUSE_MENU.instantiate() as PauseMenu
			viewport.add_child(menu)
			menu.show_bike("Street 390   ·   150 kg · 26.7 kW · 45° lean · 150 mm travel")
			menu.offer_rewind(3.0, "a lesson is judged whole (right stick click / Backspace)")
			menu.visible = true
			await wait_frames(3)
			var parts: Array[Control] = [menu.get_node(^"Panel") as Control]
			for part in menu.get_node(^"Panel/Margin/Columns/Options").get_children():
				parts.append(part as Control)
			parts.append(menu.get_node(^"Panel/Margin/Columns/ControlsScroll") as Control)
			var problems := LayoutCheck.problems(parts, Rect2(Vector2.ZERO, canvas))
			# The panel holds the rest: only a part leaving the screen is a problem.
			problems = Array(problems).filter(
				func(line: String) -> bool: return "overlaps" not in line
			)
			assert_eq(problems, PackedStringArray(), "%s window at %d %%" % [window, scale * 100])
			var scroll := menu.get_node(^"Panel/Margin/Columns/Options/SettingsScroll") as Control
			assert_gt(
				scroll.size.y, 90.0, "some settings show at %s, %d %%" % [window, scale * 100]
			)
			viewport.queue_free()
			await wait_frames(1)
