extends Node
## Rides the track by simulated input while Godot's movie writer records the sound, and
## logs what the engine should sound like frame by frame, for tools/sound_check to
## compare with the recording: idle, pull away and accelerate through the gears, coast,
## brake hard, then pause (which must be silent), with the arcade controller, on the bike
## asked for. Run by tools/sound-check.sh for each bike.
##
## Arguments after `--`: `--log=PATH.csv`, `--bike=KEY` (a `Bikes` key; the settings'
## default without it).

const GAME := preload("res://scenes/game/game.tscn")
## The ride, by frame (60 per second): [first frame, action, strength].
const SCRIPT := [
	[0, &"throttle", 0.0],
	[30, &"throttle", 0.8],
	[330, &"throttle", 0.0],
	[390, &"brake", 1.0],
	[450, &"brake", 0.0],
]
const PAUSE_AT := 480
const LAST_FRAME := 560

var _log: FileAccess
var _game: Game


func _ready() -> void:
	var path := ""
	var bike := ""
	for argument: String in OS.get_cmdline_user_args():
		if argument.begins_with("--log="):
			path = argument.trim_prefix("--log=")
		elif argument.begins_with("--bike="):
			bike = argument.trim_prefix("--bike=")
	_log = FileAccess.open(path, FileAccess.WRITE) if not path.is_empty() else null
	if _log == null:
		printerr("sound capture: give --log=PATH.csv (a writable path)")
		get_tree().quit(2)
		return
	SettingsSandbox.enter()
	# The arcade controller plans nothing, so the ride, and the sound, are the same
	# however busy the machine is.
	Settings.set_value(&"controller", "arcade")
	if not bike.is_empty():
		Settings.set_value(&"bike", bike)
	# Only the sound matters here: the movie's pictures skip the 3D scene, which would
	# cost most of the run on a software renderer.
	get_viewport().disable_3d = true
	_log.store_line("frame,mix_rate,paused,speed,rpm,gear,firing_frequency,cylinders,strokes")
	_game = GAME.instantiate() as Game
	_game.level_path = "res://scenes/levels/track/track.tscn"
	add_child(_game)
	var sound := _game.bike.get_node(^"Sound") as BikeSound
	var engine := sound.engine()
	for frame: int in LAST_FRAME:
		for change: Array in SCRIPT:
			if change[0] == frame:
				Input.action_press(change[1], change[2])
				if change[2] == 0.0:
					Input.action_release(change[1])
		if frame == PAUSE_AT:
			_game.get_node(^"PauseMenu").open()
		(
			_log
			. store_line(
				(
					"%d,%d,%d,%.4f,%.1f,%d,%.3f,%d,%d"
					% [
						frame,
						AudioServer.get_mix_rate(),
						int(get_tree().paused),
						_game.bike.get_speed(),
						sound.rpm(),
						sound.gear(),
						sound.firing_frequency(),
						engine.cylinders,
						engine.strokes,
					]
				)
			)
		)
		await get_tree().process_frame
	_log.close()
	get_tree().paused = false
	CleanExit.quit(get_tree())
