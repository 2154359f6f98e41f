extends TestCase
## Settings and records survive: saved at once, atomically, read back, broken files kept.


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	SettingsSandbox.leave()


func test_a_change_is_saved_at_once_and_read_back() -> void:
	Settings.set_value(&"trajectories", 32)
	assert_false(FileAccess.file_exists(SettingsSandbox.SETTINGS + ".tmp"), "no temporary left")
	Settings.reload()
	assert_eq(Settings.get_value(&"trajectories"), 32)


func test_the_trajectory_list_is_auto_then_the_fixed_counts() -> void:
	var labels := Settings.trajectory_labels()
	assert_eq(labels.size(), Settings.offered(&"trajectories").size() + 1)
	var limits := BikeSimulation.auto_trajectory_limits()
	assert_eq(labels[0], "auto trajectories (%d–%d)" % [limits.x, limits.y])
	assert_eq(Settings.trajectory_choice(), 0, "auto is the default")
	Settings.choose_trajectories(3)
	assert_eq(Settings.get_value(&"trajectories"), Settings.offered(&"trajectories")[2])
	assert_false(Settings.get_value(&"auto_trajectories"))
	Settings.reload()
	assert_eq(Settings.trajectory_choice(), 3, "the fixed choice survives a restart")
	Settings.choose_trajectories(0)
	assert_true(Settings.get_value(&"auto_trajectories"))
	assert_eq(Settings.get_value(&"trajectories"), Settings.offered(&"trajectories")[2], "kept")
	# A count set by hand that no menu offers shows as the nearest offered.
	Settings.set_value(&"auto_trajectories", false)
	Settings.set_value(&"trajectories", 30)
	assert_eq(Settings.trajectory_choice(), Settings.offered(&"trajectories").find(32) + 1)


func test_wrong_types_and_unknown_keys_are_refused() -> void:
	expect_error("it takes")
	Settings.set_value(&"trajectories", "many")
	expect_error("no player setting is called")
	Settings.set_value(&"colour", 3)
	assert_eq(Settings.get_value(&"trajectories"), Settings.defaults[&"trajectories"])


func test_a_broken_file_is_kept_aside_and_defaults_used() -> void:
	var file := FileAccess.open(SettingsSandbox.SETTINGS, FileAccess.WRITE)
	file.store_string("[game\ntrajectories = = 7\n")
	file.close()
	expect_error("ConfigFile parse error")
	Settings.reload()
	assert_eq(Settings.get_value(&"trajectories"), Settings.defaults[&"trajectories"])
	assert_true(
		FileAccess.file_exists(SettingsSandbox.SETTINGS + ".broken"), "the old file is kept"
	)


func test_the_controller_is_saved_by_name_and_old_numbers_migrate() -> void:
	Settings.set_value(&"controller", "optimizer")
	Settings.reload()
	assert_eq(Settings.get_value(&"controller"), "optimizer")
	expect_error("no controller is called")
	Settings.set_value(&"controller", "autopilot")
	assert_eq(Settings.get_value(&"controller"), "optimizer", "an unknown name is refused")
	# Files from before controllers had names hold BikeSimulation's old numbers.
	for old: int in 4:
		var config := ConfigFile.new()
		config.set_value(Settings.SECTION, "controller", old)
		config.save(SettingsSandbox.SETTINGS)
		Settings.reload()
		# 1 was manual, which players do not pick: the default (with a warning).
		var migrated: String = ["arcade", "combined", "optimizer", "combined"][old]
		assert_eq(Settings.get_value(&"controller"), migrated, "old value %d" % old)


func test_only_a_faster_lap_is_a_new_best() -> void:
	assert_eq(Settings.best_lap("track"), INF)
	assert_true(Settings.record_lap("track", 61.5))
	assert_false(Settings.record_lap("track", 70.0))
	assert_false(Settings.record_lap("track", NAN))
	assert_true(Settings.record_lap("track", 58.25))
	Settings.reload()
	assert_eq(Settings.best_lap("track"), 58.25, "read back from the records file")


func test_a_lap_gate_counts_forward_crossings_within_its_width() -> void:
	var gate := LapGate.new()
	gate.width = 8.0
	add_child(gate)
	assert_eq(gate.crossing(Vector3(0, 0, 1), Vector3(0, 0, -1)), 1, "forwards (−z)")
	assert_eq(gate.crossing(Vector3(0, 0, -1), Vector3(0, 0, 1)), -1, "backwards")
	assert_eq(gate.crossing(Vector3(5, 0, 1), Vector3(5, 0, -1)), 0, "outside the posts")
	assert_eq(gate.crossing(Vector3(0, 0, 2), Vector3(0, 0, 1)), 0, "not reached")
	gate.free()


func test_the_follow_cameras_modes_are_the_settings_choices() -> void:
	assert_eq(Array(Settings.entries[&"camera"].choices), Array(FollowCamera.MODES))


func test_the_graphics_quality_is_one_of_its_choices() -> void:
	assert_eq(Settings.get_value(&"graphics_quality"), "auto", "by default")
	Settings.set_value(&"graphics_quality", "low")
	assert_eq(Settings.get_value(&"graphics_quality"), "low")
	expect_error("it is one of auto, low, medium, high")
	Settings.set_value(&"graphics_quality", "ultra")
	assert_eq(Settings.get_value(&"graphics_quality"), "low", "kept")


func test_the_camera_mode_is_saved_and_an_unknown_one_refused() -> void:
	Settings.set_value(&"camera", "helmet")
	Settings.reload()
	assert_eq(Settings.get_value(&"camera"), "helmet")
	expect_error("it is one of chase, low_side, helmet")
	Settings.set_value(&"camera", "drone")
	assert_eq(Settings.get_value(&"camera"), "helmet")
	var config := ConfigFile.new()
	config.set_value(Settings.SECTION, "camera", "drone")
	config.save(SettingsSandbox.SETTINGS)
	Settings.reload()
	assert_eq(Settings.get_value(&"camera"), "chase", "a hand-edited unknown mode: the default")


func test_the_volume_is_the_master_bus_and_zero_mutes_it() -> void:
	Settings.set_value(&"master_volume", 0.5)
	assert_almost_eq(AudioServer.get_bus_volume_db(0), linear_to_db(0.5), 0.01)
	assert_false(AudioServer.is_bus_mute(0))
	Settings.set_value(&"master_volume", 0.0)
	assert_true(AudioServer.is_bus_mute(0), "silent at 0")
	Settings.reload()
	assert_true(AudioServer.is_bus_mute(0), "and still after a restart")


func test_a_file_written_before_the_schema_loads_every_value() -> void:
	# The keys and types the game saved before its settings came from the native schema.
	var config := ConfigFile.new()
	var saved := {
		&"level": "track",
		&"trajectories": 32,
		&"auto_trajectories": false,
		&"controller": "guided",
		&"show_trajectories": false,
		&"physical_model": true,
		&"motor_force": 0.85,
		&"max_speed_kmh": 55.0,
		&"auto_speed_kmh": 20,
		&"auto_accelerate": true,
		&"camera": "helmet",
		&"master_volume": 0.3,
		&"engine_volume": 0.5,
	}
	for key: StringName in saved:
		config.set_value(Settings.SECTION, key, saved[key])
	config.save(SettingsSandbox.SETTINGS)
	Settings.reload()
	for key: StringName in saved:
		assert_eq(Settings.get_value(key), saved[key], key)
