extends Node
## What the game-feel features cost per frame, riding the track by simulated input with a
## ghost beside the bike: each feature's own per-frame work timed in place (the engine
## sound's listening and mixing a frame of samples, the replay recorder's step, the ghost
## race's posing, the skinned rider's IK), and the drawing of the ghost and of the skinned
## rider as the paired difference in wall-clock frame time between alternating blocks of
## frames with it shown and hidden, the game paused so nothing else changes (95 % interval);
## then the world's drawing the same way (the land and hills round the level, the clouded
## sky against a plain one of the same colours, the track's kerbs and edge lines, medium's
## edge smoothing pass), then
## each graphics quality preset's frame time on the same still picture, in blocks taken in
## turn, with its paired difference from low. The features are measured at low.
## Run under Xvfb by tools/frame-time.sh; the ghost raced is the bot's lap from the
## GDScript suites (build/ghosts/track.ghost), in scratch settings.
##
## Arguments after `--`: `--controller=NAME` (default combined), `--blocks=N` (pairs of
## blocks, default 20).

const GAME := preload("res://scenes/game/game.tscn")
const BLOCK := 20
## Frames ridden before measuring: past the start line, so the ghost rides along.
const SETTLE := 150
## Calls timed per feature.
const REPEATS := 300

var _game: Game


func _ready() -> void:
	var controller := "combined"
	var blocks := 20
	for argument: String in OS.get_cmdline_user_args():
		if argument.begins_with("--controller="):
			controller = argument.trim_prefix("--controller=")
		elif argument.begins_with("--blocks="):
			blocks = int(argument.trim_prefix("--blocks="))
	SettingsSandbox.enter()
	DirAccess.make_dir_recursive_absolute(Settings.ghosts_dir)
	DirAccess.copy_absolute("res://build/ghosts/track.ghost", Settings.ghost_path("track"))
	Settings.set_value(&"controller", controller)
	Settings.set_value(&"graphics_quality", "low")
	_game = GAME.instantiate() as Game
	_game.level_path = "res://scenes/levels/track/track.tscn"
	add_child(_game)
	Input.action_press(&"throttle", 0.5)
	for frame in SETTLE:
		await get_tree().process_frame
	var costs := _feature_costs()
	# The drawing is measured on a still picture (the game paused), where the ghost is all
	# that changes between blocks.
	process_mode = Node.PROCESS_MODE_ALWAYS
	get_tree().paused = true
	var drawing := await _drawing_cost(_game.ghost_race.ghost_view(), blocks)
	var rider_drawing := await _drawing_cost(_live_view().rider(), blocks)
	var world := await _world_costs(blocks)
	# Half the rounds: three presets a round, each block a few seconds in software.
	var presets := await _preset_costs(maxi(blocks / 2, 3))
	get_tree().paused = false
	Input.action_release(&"throttle")
	var total: float = costs.sound + costs.ghost + costs.rider + costs.recorder / 2.0 + drawing[0]
	print(
		(
			(
				"frame time (%s, ghost %s): sound %.3f ms, ghost posing %.3f ms, rider posing"
				+ " %.3f ms, recorder %.3f ms a step (every other frame), ghost drawing"
				+ " %+.2f ± %.2f ms; together %.2f ms a frame; the skinned rider's drawing"
				+ " %+.2f ± %.2f ms (it replaced a rider of primitives: see docs/benchmarks-history.md)"
			)
			% [
				controller,
				"shown" if _game.ghost_race.ghost() != null else "MISSING",
				costs.sound,
				costs.ghost,
				costs.rider,
				costs.recorder,
				drawing[0],
				drawing[1],
				total,
				rider_drawing[0],
				rider_drawing[1],
			]
		)
	)
	var figures: Array = [controller]
	for part: String in ["horizon", "sky", "kerbs", "edges"]:
		figures.append_array(world[part])
	print(
		(
			(
				"frame time of the world (%s): the land and hills %+.2f ± %.2f ms, the clouded sky"
				+ " %+.2f ± %.2f ms against a plain one, the kerbs and edge lines %+.2f ± %.2f ms,"
				+ " the edge smoothing pass %+.2f ± %.2f ms"
			)
			% figures
		)
	)
	var by_preset := PackedStringArray()
	for preset: String in Graphics.ORDER:
		by_preset.append(
			(
				"%s %.1f ms (%+.1f ± %.1f)"
				% [preset, presets[preset].mean, presets[preset].over_low, presets[preset].half]
			)
		)
	print("frame time by preset (%s, against low): %s" % [controller, ", ".join(by_preset)])
	CleanExit.quit(get_tree())


## Milliseconds per call of each feature's per-frame work, done as the game does it.
func _feature_costs() -> Dictionary:
	var synth := BikeSynth.at_rate(AudioServer.get_mix_rate())
	var samples := int(AudioServer.get_mix_rate() / 60.0)
	var started := Time.get_ticks_usec()
	for i in REPEATS:
		synth.listen(_game.bike, 1.0 / 60.0)
		synth.mix(samples)
	var sound := (Time.get_ticks_usec() - started) / 1000.0 / REPEATS
	var ghost_skeleton := _game.ghost_race.ghost_view().rider().skeleton()
	started = Time.get_ticks_usec()
	for i in REPEATS:
		_game.ghost_race.show_ghost()
		# Its rider's IK solves when its skeleton updates, at the end of the frame: here.
		ghost_skeleton.notification(Skeleton3D.NOTIFICATION_UPDATE_SKELETON)
	var ghost := (Time.get_ticks_usec() - started) / 1000.0 / REPEATS
	# The live rider's posing and IK, as the drawn bike poses it every frame.
	var bodies: Array[Transform3D] = []
	for body in _game.bike.get_body_count():
		bodies.append(_game.bike.get_body_transform(body))
	var no_feet_down: Array[Dictionary] = []
	started = Time.get_ticks_usec()
	var skeleton := _live_view().rider().skeleton()
	for i in REPEATS:
		_live_view().rider().pose(bodies, no_feet_down)
		# The IK solves when the skeleton updates, at the end of the frame: now, here.
		skeleton.notification(Skeleton3D.NOTIFICATION_UPDATE_SKELETON)
	var rider := (Time.get_ticks_usec() - started) / 1000.0 / REPEATS
	_game.recorder.capacity_seconds = 1.0
	started = Time.get_ticks_usec()
	for i in REPEATS:
		_game.recorder.record_step()
	var recorder := (Time.get_ticks_usec() - started) / 1000.0 / REPEATS
	_game.recorder.capacity_seconds = ReplayRecorder.MOST_SECONDS
	return {sound = sound, ghost = ghost, rider = rider, recorder = recorder}


func _live_view() -> VisualBikeView:
	return _game.bike.get_node(^"VisualBikeView") as VisualBikeView


## Each graphics preset's frame time (ms) on the still picture, over `pairs` rounds of a
## block at each in turn (the order rotating, so a drift favours none), and its paired
## difference from low with the 95 % half-width.
func _preset_costs(pairs: int) -> Dictionary:
	var times := {}
	for preset: String in Graphics.ORDER:
		times[preset] = PackedFloat64Array()
	# A round first, unmeasured, so every preset's shaders are compiled before timing.
	for turn in pairs + 1:
		for i in Graphics.ORDER.size():
			var preset: String = Graphics.ORDER[(i + turn) % Graphics.ORDER.size()]
			Graphics.apply(preset)
			await get_tree().process_frame
			var started := Time.get_ticks_usec()
			for frame in BLOCK:
				await get_tree().process_frame
			if turn > 0:
				times[preset].append((Time.get_ticks_usec() - started) / 1000.0 / BLOCK)
	Graphics.apply("low")
	var costs := {}
	for preset: String in Graphics.ORDER:
		var differences := PackedFloat64Array()
		for i in pairs:
			differences.append(times[preset][i] - times["low"][i])
		var over_low := _mean_and_half_width(differences)
		costs[preset] = {
			mean = _mean_and_half_width(times[preset])[0],
			over_low = over_low[0],
			half = over_low[1],
		}
	return costs


## What the world's drawing costs, each part as `_paired_cost` measures it: the Horizon,
## the clouded sky against the procedural sky of the same colours it replaced, and the
## track's kerbs and edge lines, and the edge smoothing pass (Graphics). [mean, half-width]
## each.
func _world_costs(pairs: int) -> Dictionary:
	var horizon := _game.get_node(^"Horizon") as Node3D
	var sky := (_game.get_node(^"Environment") as WorldEnvironment).environment.sky
	var clouded := sky.sky_material
	var plain := ProceduralSkyMaterial.new()
	var sky_shader := (clouded as ShaderMaterial).shader.get_rid()
	plain.sky_top_color = RenderingServer.shader_get_parameter_default(sky_shader, &"top_colour")
	plain.sky_horizon_color = RenderingServer.shader_get_parameter_default(
		sky_shader, &"horizon_colour"
	)
	plain.ground_horizon_color = plain.sky_horizon_color
	var painted: Array[Node3D] = []
	for name: String in ["EdgeLineLeft", "EdgeLineRight", "KerbLeft", "KerbRight"]:
		painted.append(_game.level.get_node(name) as Node3D)
	var result := {}
	result.horizon = await _paired_cost(func(on: bool) -> void: horizon.visible = on, pairs)
	result.sky = await _paired_cost(
		func(on: bool) -> void: sky.sky_material = clouded if on else plain, pairs
	)
	result.kerbs = await _paired_cost(
		func(on: bool) -> void:
			for node in painted:
				node.visible = on,
		pairs
	)
	sky.sky_material = clouded
	var edge_pass := Graphics.get_node(^"EdgeSmoothing/Pass") as CanvasItem
	var smoothing := edge_pass.visible
	result.edges = await _paired_cost(func(on: bool) -> void: edge_pass.visible = on, pairs)
	edge_pass.visible = smoothing
	return result


## What drawing `node` costs (`_paired_cost` of showing it).
func _drawing_cost(node: Node3D, pairs: int) -> Array[float]:
	return await _paired_cost(func(shown: bool) -> void: node.visible = shown, pairs)


## What `show(true)` costs against `show(false)`: frame time (ms) with it on minus off,
## over `pairs` pairs of blocks in alternating order, and the 95 % half-width.
func _paired_cost(show: Callable, pairs: int) -> Array[float]:
	var differences := PackedFloat64Array()
	for pair in pairs:
		var times := [0.0, 0.0]
		# Alternate which comes first, so a drift does not favour either.
		for shown: bool in [true, false] if pair % 2 == 0 else [false, true]:
			show.call(shown)
			# One frame to settle on the new picture, then the block.
			await get_tree().process_frame
			var started := Time.get_ticks_usec()
			for frame in BLOCK:
				await get_tree().process_frame
			times[int(shown)] = (Time.get_ticks_usec() - started) / 1000.0 / BLOCK
		differences.append(times[1] - times[0])
	show.call(true)
	return _mean_and_half_width(differences)


## The mean of `values` and its 95 % half-width.
func _mean_and_half_width(values: PackedFloat64Array) -> Array[float]:
	var n := values.size()
	var mean := 0.0
	for d in values:
		mean += d / n
	var variance := 0.0
	for d in values:
		variance += (d - mean) * (d - mean) / (n - 1)
	# Student's t (97.5 %) for 5–30 degrees of freedom, near enough for a report.
	var t := 2.0 + 2.6 / n
	var result: Array[float] = [mean, t * sqrt(variance / n)]
	return result
