extends TestCase
## The bike's sound never leaves the audio thread reading a freed stream: the generator
## lives as long as the audio server's hold on its playback, and both go once the server
## has mixed the fade-out (nothing leaks); each bike sounds the engine its file names.

## Frames to wait, at most, for the audio server to let go (a frame here is a few ms;
## the server lets go in its next mix, about 12 ms after the stop).
const MAX_FRAMES_TO_RELEASE := 300


func test_the_generator_outlives_its_player_until_the_audio_server_lets_go() -> void:
	var level := FlatLevel.create()
	var bike := BikeSimulation.new()
	level.add_child(bike)
	var sound := BikeSound.new()
	bike.add_child(sound)
	add_child(level)
	await wait_frames(3)
	assert_true(sound.playing, "the engine is sounding")
	var generator: WeakRef = weakref(sound.stream)
	var playback: WeakRef = weakref(sound.get_stream_playback())
	sound = null
	level.free()
	assert_not_null(playback.get_ref(), "the audio server still holds the stopped playback")
	assert_not_null(generator.get_ref(), "so its generator is kept, not left dangling")
	var frames := 0
	while playback.get_ref() != null and frames < MAX_FRAMES_TO_RELEASE:
		await wait_frames(1)
		OS.delay_msec(CleanExit.MIX_PERIOD_MS / 4)
		frames += 1
	assert_null(playback.get_ref(), "the server let go of the playback (%d frames)" % frames)
	assert_null(generator.get_ref(), "and the generator went with it")


func test_each_bike_sounds_the_engine_its_file_names() -> void:
	var heard := {}
	for key: String in Bikes.keys():
		var level := FlatLevel.create()
		var bike := BikeSimulation.new()
		bike.bike = Bikes.description(key)
		level.add_child(bike)
		var sound := BikeSound.new()
		bike.add_child(sound)
		add_child(level)
		await wait_frames(2)
		heard[key] = sound.engine().label
		level.free()
	assert_eq(
		heard,
		{
			"street_390": "four-stroke single",
			"dirt_125": "two-stroke single",
			"sport_600": "inline four",
		}
	)


func test_a_bike_file_naming_no_layout_is_refused_naming_the_layouts() -> void:
	var bike := (load(Bikes.path_of("dirt_125")) as BikeDescription).duplicate() as BikeDescription
	assert_eq(bike.get(&"engine/layout"), "two_stroke_single")
	bike.set(&"engine/layout", "v_twin")
	assert_eq(
		bike.problem(),
		(
			"Dirt 125: engine 'v_twin' is not one of four_stroke_single, two_stroke_single, "
			+ "inline_four"
		)
	)
	assert_eq(BikeDescription.new().get(&"engine/layout"), "four_stroke_single", "the default")
