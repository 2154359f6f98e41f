class_name BikeSound
extends AudioStreamPlayer
## The bike's sound: the engine its file names (`engine/layout`), tyres, thumps and wind,
## synthesised at run time by `BikeSynth` from what the simulation measures each physics
## tick, streamed through an `AudioStreamGenerator`. Pausing the game fades it to
## silence; the engine's loudness is the player's setting.

## Seconds of sound kept ready ahead of the mixer: enough to ride out a slow frame,
## short enough that the engine answers the throttle at once.
const BUFFER_SECONDS := 0.08

## The simulation to listen to; by default the parent.
@export var simulation_path: NodePath = ^".."

var _simulation: BikeSimulation
var _synth: BikeSynth
var _playback: AudioStreamGeneratorPlayback


func _ready() -> void:
	# Runs while paused too, to fade out rather than stop mid-wave.
	process_mode = Node.PROCESS_MODE_ALWAYS
	_simulation = get_node_or_null(simulation_path) as BikeSimulation
	if _simulation == null:
		push_error("BikeSound: no BikeSimulation at %s" % simulation_path)
		set_process(false)
		set_physics_process(false)
		return
	var generator := AudioStreamGenerator.new()
	generator.mix_rate = AudioServer.get_mix_rate()
	generator.buffer_length = BUFFER_SECONDS
	stream = generator
	_synth = BikeSynth.at_rate(generator.mix_rate)
	_synth.hear_engine_of(_simulation)
	_synth.set_engine_volume(Settings.get_value(&"engine_volume"))
	Settings.changed.connect(_on_setting_changed)
	play()
	_playback = get_stream_playback() as AudioStreamGeneratorPlayback
	# The playback points at its generator by a bare pointer, and the audio server mixes
	# a stopped playback once more (its fade-out) in its own thread, when this player and
	# its stream may already be freed (godotengine/godot issue 92349). Read after free,
	# the garbage sample rate once kept the audio thread looping, hanging the exit. So the
	# playback holds its generator itself: freed only when the server lets go of both.
	_playback.set_meta(&"generator", generator)


func _physics_process(delta: float) -> void:
	if not get_tree().paused and _simulation.is_running():
		_synth.listen(_simulation, delta)


func _process(_delta: float) -> void:
	_synth.set_muted(get_tree().paused or not _simulation.is_running())
	var room := _playback.get_frames_available()
	if room > 0:
		_playback.push_buffer(_synth.mix(room))


## Crank speed (rpm) and gear now, and the pitch one hears (Hz).
func rpm() -> float:
	return _synth.get_rpm()


## Crank speed as a share of the rev limiter's (0–1): how hard the engine is revving.
func revs() -> float:
	return _synth.get_rpm() / float(_synth.get_engine().limiter_rpm)


## The engine's layout (`BikeSynth.get_engine`: name, label, cylinders, strokes, idle and
## limiter rpm).
func engine() -> Dictionary:
	return _synth.get_engine()


func gear() -> int:
	return _synth.get_gear()


func firing_frequency() -> float:
	return _synth.get_firing_frequency()


func _on_setting_changed(key: StringName) -> void:
	if key == &"engine_volume":
		_synth.set_engine_volume(Settings.get_value(&"engine_volume"))


func _exit_tree() -> void:
	# The audio server holds the playing stream's playback; stop it before the node goes,
	# or the playback outlives everything at exit.
	stop()
	_playback = null
