extends Node
## The graphics quality (autoload `Graphics`, setting `graphics_quality`): how richly the
## world is drawn. Each preset sets the sun's shadow map and its filter, the edges'
## antialiasing and whether the levels' surfaces carry their textures; **low** is the
## game as a software renderer draws it at its best frame time, **high** what a graphics
## card affords. **auto** starts at medium and, while a level is ridden, measures the
## frame time: it steps up while frames come faster than FAST_FRAME_S and down (for good)
## when they come slower than SLOW_FRAME_S, so it settles on the richest preset that
## holds a playable rate and never swings between two.

## The preset now in force (never "auto").
signal applied(preset: String)

## What each preset draws. `textured`: the surfaces' textures and relief (off, they keep
## their colour); `shadow_size`: the directional shadow map's side (px); `shadow_filter`:
## RenderingServer's soft shadow quality; `msaa`: the 3D antialiasing (a graphics card
## does it almost for free; in software 2× multiplies the frame time by five, so only high
## has it); `tree_share`: the share of the trees beside a track that stand (`Trackside`);
## `prop_shadows`: whether the things beside the track cast shadows (in software, most of
## what the trees cost); `edge_smoothing`: a pass over the drawn picture that smooths its
## jagged edges (scenes/world/edge_smoothing.gdshader: antialiasing a software renderer
## affords, for the preset without MSAA that has textures).
const PRESETS := {
	low =
	{
		textured = false,
		shadow_size = 4096,
		shadow_filter = RenderingServer.SHADOW_QUALITY_SOFT_LOW,
		msaa = Viewport.MSAA_DISABLED,
		tree_share = 0.25,
		prop_shadows = false,
		edge_smoothing = false,
	},
	medium =
	{
		textured = true,
		shadow_size = 4096,
		shadow_filter = RenderingServer.SHADOW_QUALITY_SOFT_MEDIUM,
		msaa = Viewport.MSAA_DISABLED,
		tree_share = 0.7,
		prop_shadows = true,
		edge_smoothing = true,
	},
	high =
	{
		textured = true,
		shadow_size = 8192,
		shadow_filter = RenderingServer.SHADOW_QUALITY_SOFT_HIGH,
		msaa = Viewport.MSAA_4X,
		tree_share = 1.0,
		prop_shadows = true,
		edge_smoothing = false,
	},
}
## The presets from the plainest to the richest (the order auto steps in).
const ORDER: Array[String] = ["low", "medium", "high"]
const AUTO_START := "medium"
## Mean frame times (s) auto steps down above (under 40 frames a second) and up below
## (a 60 Hz display's frames with room to spare are just under 1/60 s).
const SLOW_FRAME_S := 1.0 / 40.0
const FAST_FRAME_S := 1.0 / 55.0
## Frames auto lets pass after a change (shaders compile, the shadow map is rebuilt)
## before it measures, and the frames it averages.
const SETTLING_FRAMES := 30
const MEASURED_FRAMES := 120
## The edge smoothing pass, drawn on the lowest canvas layer: above the 3D picture, below
## every menu and HUD, whose text it would blur.
const EDGE_SMOOTHING := preload("res://scenes/world/edge_smoothing.gdshader")
const EDGE_SMOOTHING_LAYER := -128

## The surfaces whose textures `textured` turns on and off: the levels' materials.
const SURFACES: Array[String] = [
	"res://scenes/levels/materials/ground.tres",
	"res://scenes/levels/materials/road.tres",
	"res://scenes/levels/materials/wall.tres",
	"res://scenes/levels/materials/piece.tres",
	"res://scenes/levels/materials/slab.tres",
	"res://scenes/levels/materials/dirt.tres",
]
## What a plain StandardMaterial3D surface has, by property: no textures, and none of the
## work that reads them (an empty slot is still sampled, a white texture bound in its place).
const PLAIN := {
	albedo_texture = null,
	normal_texture = null,
	normal_enabled = false,
	uv1_triplanar = false,
	uv1_world_triplanar = false,
}

## The preset in force.
var preset := ""
## Whether auto chooses the preset (the setting is "auto").
var automatic := false

## The surfaces' materials, held so every level loads these very ones (a material nothing
## holds is freed, and the next load would read it afresh, textured).
var _surfaces: Array[Material] = []
## Each surface's textured properties as loaded (those PLAIN changes), by material, to
## put back.
var _textured := {}
var _frames_to_settle := SETTLING_FRAMES
var _measured: PackedFloat64Array = []
var _last_frame_usec := 0
var _stepped_down := false
var _edge_smoothing: ColorRect


func _ready() -> void:
	_add_edge_smoothing()
	for path in SURFACES:
		var material := load(path) as Material if ResourceLoader.exists(path) else null
		if material == null:
			push_warning("Graphics: cannot load the surface %s; it is left as it is" % path)
		else:
			_surfaces.append(material)
	Settings.changed.connect(_on_setting_changed)
	Settings.reloaded.connect(_follow_setting)
	_follow_setting()


func _on_setting_changed(key: StringName) -> void:
	if key == &"graphics_quality":
		_follow_setting()


func _follow_setting() -> void:
	var chosen: String = Settings.get_value(&"graphics_quality")
	automatic = chosen == "auto"
	_stepped_down = false
	apply(AUTO_START if automatic else chosen)


## Draws with preset `name` (one of ORDER) from now on.
func apply(name: String) -> void:
	if not PRESETS.has(name):
		push_error("Graphics: no preset is called '%s'" % name)
		return
	var settings: Dictionary = PRESETS[name]
	for material in _surfaces:
		_texture_surface(material, settings.textured)
	RenderingServer.directional_shadow_atlas_set_size(settings.shadow_size, true)
	RenderingServer.directional_soft_shadow_filter_set_quality(settings.shadow_filter)
	get_tree().root.msaa_3d = settings.msaa
	_edge_smoothing.visible = settings.edge_smoothing
	preset = name
	_frames_to_settle = SETTLING_FRAMES
	_measured.clear()
	applied.emit(name)


func _texture_surface(material: Material, textured: bool) -> void:
	if material is ShaderMaterial:
		(material as ShaderMaterial).set_shader_parameter(&"textured", textured)
		return
	if not _textured.has(material):
		var loaded := {}
		for property: String in PLAIN:
			loaded[property] = material.get(property)
		_textured[material] = loaded
	var values: Dictionary = _textured[material] if textured else PLAIN
	for property: String in values:
		material.set(property, values[property])


func _process(_delta: float) -> void:
	# Real time between frames: `delta` is fixed when the game runs at a fixed rate.
	var now := Time.get_ticks_usec()
	var frame_s := (now - _last_frame_usec) / 1e6
	_last_frame_usec = now
	if _riding():
		measure_frame(frame_s)


## Counts one ridden frame that took `frame_s` seconds towards auto's choice (nothing
## when the player chose a preset).
func measure_frame(frame_s: float) -> void:
	if not automatic:
		return
	if _frames_to_settle > 0:
		_frames_to_settle -= 1
		return
	_measured.append(frame_s)
	if _measured.size() < MEASURED_FRAMES:
		return
	var mean := 0.0
	for s in _measured:
		mean += s
	mean /= _measured.size()
	_measured.clear()
	var at := ORDER.find(preset)
	if mean > SLOW_FRAME_S and at > 0:
		_stepped_down = true
		apply(ORDER[at - 1])
	elif mean < FAST_FRAME_S and at < ORDER.size() - 1 and not _stepped_down:
		apply(ORDER[at + 1])


## Whether a level is being ridden: a 3D camera draws the window and the game runs.
func _riding() -> bool:
	return get_viewport().get_camera_3d() != null and not get_tree().paused


## Whether the edge smoothing pass is drawn now.
func is_smoothing_edges() -> bool:
	return _edge_smoothing.visible


## The edge smoothing pass: a rectangle over the whole window on the lowest canvas layer,
## which lets every click and touch through.
func _add_edge_smoothing() -> void:
	var layer := CanvasLayer.new()
	layer.name = "EdgeSmoothing"
	layer.layer = EDGE_SMOOTHING_LAYER
	add_child(layer)
	_edge_smoothing = ColorRect.new()
	_edge_smoothing.name = "Pass"
	_edge_smoothing.mouse_filter = Control.MOUSE_FILTER_IGNORE
	_edge_smoothing.set_anchors_preset(Control.PRESET_FULL_RECT)
	var material := ShaderMaterial.new()
	material.shader = EDGE_SMOOTHING
	_edge_smoothing.material = material
	layer.add_child(_edge_smoothing)
