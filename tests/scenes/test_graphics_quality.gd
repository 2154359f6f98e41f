extends TestCase
## The graphics quality: each preset draws what it says (textures, shadow filter, edge
## smoothing, antialiasing), the setting chooses it, and auto settles on the richest preset the
## measured frame time holds without swinging between two.

const ROAD := "res://scenes/levels/materials/road.tres"
const GROUND := "res://scenes/levels/materials/ground.tres"


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	SettingsSandbox.leave()


func test_low_draws_the_surfaces_plain_and_high_gives_their_textures_back() -> void:
	var road := load(ROAD) as StandardMaterial3D
	var ground := load(GROUND) as ShaderMaterial
	Settings.set_value(&"graphics_quality", "low")
	assert_eq(Graphics.preset, "low")
	assert_null(road.albedo_texture, "the road is plain")
	assert_false(road.normal_enabled, "without relief")
	assert_false(ground.get_shader_parameter(&"textured"), "the ground is plain")
	assert_eq(get_tree().root.msaa_3d, Viewport.MSAA_DISABLED)
	Settings.set_value(&"graphics_quality", "high")
	assert_not_null(road.albedo_texture, "the road's texture is back")
	assert_true(road.normal_enabled, "and its relief")
	assert_true(ground.get_shader_parameter(&"textured"))
	assert_eq(get_tree().root.msaa_3d, Viewport.MSAA_4X)


func test_every_preset_the_setting_offers_is_defined() -> void:
	var choices := Array(Settings.entries[&"graphics_quality"].choices)
	assert_eq(choices, ["auto"] + Array(Graphics.ORDER), "auto, then the presets plainest first")
	assert_eq(Graphics.PRESETS.keys().size(), Graphics.ORDER.size())


func test_auto_steps_up_on_fast_frames_and_settles_after_stepping_down() -> void:
	assert_true(Graphics.automatic, "auto by default")
	assert_eq(Graphics.preset, Graphics.AUTO_START)
	_frames(Graphics.FAST_FRAME_S * 0.5)
	assert_eq(Graphics.preset, "high", "fast frames: one step up")
	_frames(Graphics.SLOW_FRAME_S * 2.0)
	assert_eq(Graphics.preset, "medium", "slow frames: one step down")
	_frames(Graphics.FAST_FRAME_S * 0.5)
	assert_eq(Graphics.preset, "medium", "and never up again: no swinging between two")
	_frames(Graphics.SLOW_FRAME_S * 2.0)
	assert_eq(Graphics.preset, "low", "down again when it is still too slow")


func test_the_pause_menu_names_the_preset_auto_chose() -> void:
	var menu: PauseMenu = load("res://scenes/ui/pause_menu.tscn").instantiate()
	add_child(menu)
	var list := menu.control_of(&"graphics_quality") as OptionButton
	assert_eq(list.get_item_text(0), "Auto (Medium)")
	_frames(Graphics.FAST_FRAME_S * 0.5)
	assert_eq(list.get_item_text(0), "Auto (High)", "after auto stepped up")
	assert_eq(list.get_item_text(1), "Low")
	menu.free()


func test_a_chosen_preset_is_kept_whatever_the_frame_time() -> void:
	Settings.set_value(&"graphics_quality", "medium")
	_frames(Graphics.SLOW_FRAME_S * 4.0)
	assert_eq(Graphics.preset, "medium")


func test_an_unknown_preset_is_refused() -> void:
	Graphics.apply("high")
	expect_error("no preset is called 'ultra'")
	Graphics.apply("ultra")
	assert_eq(Graphics.preset, "high", "kept")


## Feeds auto a settling period and a full measurement of frames taking `frame_s`.
func _frames(frame_s: float) -> void:
	for i in Graphics.SETTLING_FRAMES + Graphics.MEASURED_FRAMES:
		Graphics.measure_frame(frame_s)


func test_medium_smooths_the_edges_below_the_hud_and_low_and_high_do_not() -> void:
	var smoothed := {}
	for preset: String in Graphics.ORDER:
		Settings.set_value(&"graphics_quality", preset)
		smoothed[preset] = Graphics.is_smoothing_edges()
	assert_eq(smoothed, {low = false, medium = true, high = false}, "high has MSAA instead")
	var layer := Graphics.get_node(^"EdgeSmoothing") as CanvasLayer
	assert_eq(layer.layer, -128, "below every menu and HUD (the lowest layer there is)")
	var pass_rect := layer.get_node(^"Pass") as ColorRect
	assert_eq(pass_rect.mouse_filter, Control.MOUSE_FILTER_IGNORE, "clicks go through")
	var shader := (pass_rect.material as ShaderMaterial).shader
	assert_true(shader.code.contains("hint_screen_texture"), "it reads the drawn picture")
