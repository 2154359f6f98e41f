extends TestCase
## The experiment worker's command line: good arguments read, bad ones explained.


func test_a_block_of_attempts_is_read() -> void:
	var args := (
		ExperimentArgs
		. parse(
			PackedStringArray(
				[
					"--speed=20",
					"--controller=optimizer",
					"--trajectories=10",
					"--seed=7",
					"--first=40",
					"--count=10",
					"--threads=1",
				]
			)
		)
	)
	assert_eq(args.error, "")
	assert_eq(args.speed, 20.0)
	assert_eq(args.controller, "optimizer")
	assert_eq(args.trajectories, [10] as Array[int])
	assert_eq([args.base_seed, args.first, args.count, args.threads], [7, 40, 10, 1])
	assert_false(args.timing)
	assert_eq(args.physics, "classic", "the default physics")
	assert_eq(ExperimentArgs.parse(PackedStringArray(["--physics=exact"])).physics, "exact")


func test_the_timing_study_takes_a_list_of_counts() -> void:
	var args := ExperimentArgs.parse(
		PackedStringArray(["--timing", "--trajectories=5,6,128", "--steps=30"])
	)
	assert_eq(args.error, "")
	assert_true(args.timing)
	assert_eq(args.trajectories, [5, 6, 128] as Array[int])
	assert_eq(args.steps, 30)


func test_the_platform_and_a_warm_up_ride_can_be_asked_for() -> void:
	var args := ExperimentArgs.parse(PackedStringArray(["--platform", "--warm-up=arcade"]))
	assert_eq(args.error, "")
	assert_true(args.platform_only)
	assert_eq(args.warm_up, "arcade")


func test_a_bike_file_is_ridden_and_anything_else_refused() -> void:
	var dirt := "res://scenes/bike/bikes/dirt_125.tres"
	var args := ExperimentArgs.parse(PackedStringArray(["--bike=" + dirt]))
	assert_eq(args.error, "")
	assert_eq(args.bike, dirt)
	assert_eq(ExperimentArgs.parse(PackedStringArray()).bike, "", "the reference bike")
	for wrong: String in ["res://scenes/bike/bikes/moped_50.tres", "res://project.godot"]:
		assert_has(
			ExperimentArgs.parse(PackedStringArray(["--bike=" + wrong])).error,
			"--bike must name a bike file"
		)


func test_another_bikes_network_can_be_ridden() -> void:
	var street := "res://models/policy-street_390.safetensors"
	var args := ExperimentArgs.parse(PackedStringArray(["--model=" + street]))
	assert_eq(args.error, "")
	assert_eq(args.model, street)
	assert_eq(ExperimentArgs.parse(PackedStringArray()).model, "", "the bike's own")
	for wrong: String in ["res://models/policy-moped_50.safetensors", "res://project.godot"]:
		assert_has(
			ExperimentArgs.parse(PackedStringArray(["--model=" + wrong])).error,
			"--model must name a .safetensors model file"
		)


func test_a_planners_settings_are_checked_and_ridden_as_asked() -> void:
	var args := ExperimentArgs.parse(
		PackedStringArray(["--set=horizon=0.6", "--set=terminal_value=true"])
	)
	assert_eq(args.error, "")
	assert_eq(args.settings, {"horizon": 0.6, "terminal_value": true})
	assert_eq(ExperimentArgs.parse(PackedStringArray()).settings, {}, "the defaults")
	var cases := {
		"--set=horizon=9": "horizon must be within",
		"--set=horizon": "a planner's setting is NAME=VALUE",
		"--set=max_speed_kmh=20": "max_speed_kmh is not a planner's setting",
		"--set=trajectories=8": "trajectories is set by the tool's own options",
	}
	for argument: String in cases:
		var error := ExperimentArgs.parse(PackedStringArray([argument])).error
		assert_has(error, cases[argument], "%s gave '%s'" % [argument, error])


func test_bad_values_are_explained() -> void:
	var cases := {
		"--speed=fast": "--speed needs a number",
		"--speed=nan": "--speed needs a number",
		"--speed=0": "--speed must be within",
		"--controller=autopilot": "--controller must be",
		"--trajectories=5,0": "--trajectories must be within",
		"--count=-3": "--count must be within",
		"--threads=65": "--threads must be within",
		"--warm-up=autopilot": "--warm-up must be",
		"--physics=quickstep": "--physics must be one of classic, exact",
		"--colour=red": "unknown argument",
	}
	for argument: String in cases:
		var args := ExperimentArgs.parse(PackedStringArray([argument]))
		assert_true(
			args.error.begins_with(cases[argument]), "%s gave '%s'" % [argument, args.error]
		)
