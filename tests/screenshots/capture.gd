extends Node
## Opens a scene in a real window, waits for it to render, saves a screenshot and fails
## when the picture is blank (one flat colour, or nearly so): a scene that loads but shows
## a grey screen is a bug. Run under Xvfb by tools/screenshot.sh, with scratch settings.
##
## Arguments after `--`: `--scene=res://…`, `--out=PATH.png`, `--frames=N` (default 30),
## and to stage the picture: `--set=property=value` (on the scene's root before it enters
## the tree, repeatable), `--hold=action` (held throughout, repeatable, `action:0.5` for
## part strength, `action@40-90` from frame 40 up to frame 90), `--tap=action@frame`
## (pressed once at that frame, repeatable) and
## `--call=node:method:argument@frame` (calls a method of a node under the scene's root,
## found by name, with one string argument or none, at that frame; repeatable), and
## `--copy=SOURCE>user://DEST` (a file copied into the scratch user folder before the
## scene loads: a ghost to race, say; repeatable) and `--setting=key=value` (a player
## setting, repeatable). Pictures are drawn at the PICTURE_QUALITY preset unless a
## `--setting=graphics_quality=…` says otherwise: auto would pick by the machine's speed.
##
## Only the last DRAWN_FRAMES frames are drawn: the game's logic, physics and controllers
## run every frame as usual, but drawing a 1280×720 frame in software (llvmpipe under
## Xvfb) costs about 0.2 s, far more than the frame's simulation, and only the last
## picture is kept. Every bike in the scene waits for each of its plans
## (`wait_for_every_plan`), so undrawn frames run as fast as the planners deliver and the
## ride is the one its seed gives however busy the machine: pacing them to the clock
## instead took 50 ms a frame, most of this step's time. The full ride is drawn frame by
## frame by the sound check's recording.

## The graphics quality pictures show: the textured world with its edges smoothed, without
## the MSAA that multiplies a software renderer's frame time several times over.
const PICTURE_QUALITY := "medium"
const MIN_DISTINCT_COLOURS := 12
const MIN_LUMINANCE_SPREAD := 0.04
## Enough drawn frames before the picture for the renderer to warm up (shader pipelines,
## shadow maps) as it would in play.
const DRAWN_FRAMES := 20


func _ready() -> void:
	var options := {scene = "", out = "", frames = "30"}
	var staging := {"set": [], "hold": [], "tap": [], "call": [], "copy": [], "setting": []}
	for argument: String in OS.get_cmdline_user_args():
		var parts := argument.trim_prefix("--").split("=", true, 1)
		if parts.size() == 2 and options.has(parts[0]):
			options[parts[0]] = parts[1]
		elif parts.size() == 2 and staging.has(parts[0]):
			(staging[parts[0]] as Array).append(parts[1])
	if options.scene.is_empty() or options.out.is_empty():
		_quit_with("usage: -- --scene=res://… --out=PATH.png [--frames=N]", 2)
		return
	# Pictures start from the default settings and no records, whatever this machine's
	# player last chose (a camera mode, a controller), so they are repeatable.
	SettingsSandbox.enter()
	Settings.set_value(&"graphics_quality", PICTURE_QUALITY)
	for setting: String in staging["setting"]:
		var pair := setting.split("=", true, 1)
		Settings.set_value(StringName(pair[0]), _parsed(pair[-1]))
	for copy: String in staging["copy"]:
		var ends := copy.split(">")
		DirAccess.make_dir_recursive_absolute(ends[-1].get_base_dir())
		if ends.size() != 2 or DirAccess.copy_absolute(ends[0], ends[1]) != OK:
			_quit_with("cannot copy %s" % copy, 2)
			return
	# A copied medals file (`--copy=…>user://test-medals.cfg`) is the player's from here.
	Progress.reload()
	var packed := load(options.scene) as PackedScene
	if packed == null:
		_quit_with("cannot load scene %s" % options.scene, 1)
		return
	get_tree().node_added.connect(_wait_for_every_plan)
	var root := packed.instantiate()
	for assignment: String in staging["set"]:
		var pair := assignment.split("=", true, 1)
		root.set(pair[0], _parsed(pair[1]))
	add_child(root)
	var frames := int(options.frames)
	RenderingServer.render_loop_enabled = frames <= DRAWN_FRAMES
	for frame: int in frames:
		if frame == frames - DRAWN_FRAMES:
			RenderingServer.render_loop_enabled = true
		for held: String in staging["hold"]:
			_hold(held, frame)
		for tap: String in staging["tap"]:
			var at := tap.split("@")
			if at.size() == 2 and int(at[1]) == frame:
				_tap(at[0])
		for call: String in staging["call"]:
			var at := call.split("@")
			if at.size() == 2 and int(at[1]) == frame:
				_call(root, at[0])
		await get_tree().process_frame
	await RenderingServer.frame_post_draw
	var image := get_viewport().get_texture().get_image()
	DirAccess.make_dir_recursive_absolute(String(options.out).get_base_dir())
	var saved := image.save_png(options.out)
	if saved != OK:
		_quit_with("cannot write %s: %s" % [options.out, error_string(saved)], 1)
		return
	var stats := _picture_stats(image)
	var blank: bool = stats.colours < MIN_DISTINCT_COLOURS or stats.spread < MIN_LUMINANCE_SPREAD
	print(
		(
			"screenshot %s: %dx%d, %d distinct colours, luminance spread %.3f%s"
			% [
				options.out,
				image.get_width(),
				image.get_height(),
				stats.colours,
				stats.spread,
				" — BLANK" if blank else ""
			]
		)
	)
	_quit_with("", 1 if blank else 0)


## Makes a bike (any node riding with plans) wait for each plan, as the bot rides do.
func _wait_for_every_plan(node: Node) -> void:
	if "wait_for_every_plan" in node:
		node.set("wait_for_every_plan", true)


## Calls `node:method:argument` (or `node:method`, with none) on the node of that name
## under `root` that has the method (a menu's label may share a name with the node meant,
## as the pause menu's did the bike's).
func _call(root: Node, spec: String) -> void:
	var parts := spec.split(":", true, 2)
	var named := root.find_children(parts[0], "", true, false) if parts.size() >= 2 else []
	for target: Node in named:
		if target.has_method(parts[1]):
			target.callv(parts[1], parts.slice(2))
			return
	push_error("--call=%s: no such node and method under the scene" % spec)


## Presses `spec`'s action (`action[:strength][@from-to]`) at its first frame and lets go
## of it at its last.
func _hold(spec: String, frame: int) -> void:
	var timed := spec.split("@")
	var action := timed[0].split(":")
	var frames := (timed[1] if timed.size() > 1 else "0-").split("-")
	if frame == int(frames[0]):
		Input.action_press(action[0], float(action[1]) if action.size() > 1 else 1.0)
	elif frames.size() > 1 and not frames[1].is_empty() and frame == int(frames[1]):
		Input.action_release(action[0])


func _tap(action: String) -> void:
	var event := InputEventAction.new()
	event.action = action
	event.pressed = true
	Input.parse_input_event(event)
	event = event.duplicate()
	event.pressed = false
	Input.parse_input_event(event)


## Distinct colours (4 bits a channel) and luminance standard deviation over a 64×36 grid.
func _picture_stats(image: Image) -> Dictionary:
	var seen := {}
	var sum := 0.0
	var sum_squares := 0.0
	var samples := 0
	for gx: int in 64:
		for gy: int in 36:
			var colour := image.get_pixel(gx * image.get_width() / 64, gy * image.get_height() / 36)
			seen[Vector3i(colour.r8 >> 4, colour.g8 >> 4, colour.b8 >> 4)] = true
			var luminance := colour.get_luminance()
			sum += luminance
			sum_squares += luminance * luminance
			samples += 1
	var mean := sum / samples
	return {colours = seen.size(), spread = sqrt(maxf(sum_squares / samples - mean * mean, 0.0))}


func _quit_with(message: String, code: int) -> void:
	if not message.is_empty():
		printerr("capture: %s" % message)
	CleanExit.quit(get_tree(), code)


## A command-line value as Godot would write it (a number, a bool, a vector), else the text.
static func _parsed(text: String) -> Variant:
	var value: Variant = str_to_var(text)
	return value if value != null else text
