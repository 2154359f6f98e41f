extends TestCase
## The suites start from nothing: they run in a data home made empty for the run, never
## the player's, and the settings sandbox makes whatever it needs there.


func after_each() -> void:
	SettingsSandbox.leave()


func test_the_suites_run_in_a_scratch_data_home() -> void:
	var scratch := OS.get_environment("COUNTER_STEER_SCRATCH")
	assert_false(scratch.is_empty(), "tools/run-suites.sh names the scratch folder")
	assert_true(
		OS.get_user_data_dir().begins_with(scratch.path_join("")),
		"user:// (%s) lies in the scratch folder" % OS.get_user_data_dir()
	)


func test_the_sandbox_starts_with_its_folders_absent() -> void:
	SettingsSandbox.enter()
	Settings.record_lap("track", 42.0)
	for file: String in DirAccess.get_files_at(SettingsSandbox.GHOSTS):
		DirAccess.remove_absolute(SettingsSandbox.GHOSTS.path_join(file))
	DirAccess.remove_absolute(SettingsSandbox.GHOSTS)
	for path: String in [SettingsSandbox.SETTINGS, SettingsSandbox.RECORDS]:
		DirAccess.remove_absolute(path)
	assert_false(DirAccess.dir_exists_absolute(SettingsSandbox.GHOSTS), "no ghost folder yet")

	SettingsSandbox.enter()

	assert_true(DirAccess.dir_exists_absolute(SettingsSandbox.GHOSTS), "the ghost folder is made")
	assert_eq(DirAccess.get_files_at(SettingsSandbox.GHOSTS).size(), 0, "and holds nothing")
	assert_false(is_finite(Settings.best_lap("track")), "no records")
	assert_eq(Settings.get_value(&"trajectories"), Settings.defaults[&"trajectories"])
