class_name SettingsSandbox
extends RefCounted
## Test helper: points the Settings, Progress and Controls autoloads at scratch files
## (defaults, no records, no ghosts, no medals, the project's bindings) and back again.
## The suites already run in a data home of their own (tools/run-suites.sh); this gives
## each test a clean start within it.

const SETTINGS := "user://test-settings.cfg"
const RECORDS := "user://test-records.cfg"
const GHOSTS := "user://test-ghosts"
const MEDALS := "user://test-medals.cfg"
const CONTROLS := "user://test-controls.cfg"


## Switches Settings to empty scratch files (defaults). Whatever is missing is made: the
## first test of a fresh data home finds no folders at all.
static func enter() -> void:
	for path: String in [SETTINGS, RECORDS, MEDALS, CONTROLS]:
		DirAccess.remove_absolute(path)
		DirAccess.remove_absolute(path + ".broken")
	empty_folder(GHOSTS)
	Settings.settings_path = SETTINGS
	Settings.records_path = RECORDS
	Settings.ghosts_dir = GHOSTS
	Settings.reload()
	Progress.medals_path = MEDALS
	Progress.reload()
	Controls.controls_path = CONTROLS
	Controls.reload()


## Switches Settings back to the player's files.
static func leave() -> void:
	Settings.settings_path = Settings.PLAYER_SETTINGS
	Settings.records_path = Settings.PLAYER_RECORDS
	Settings.ghosts_dir = Settings.PLAYER_GHOSTS
	Settings.reload()
	Progress.medals_path = Progress.PLAYER_MEDALS
	Progress.reload()
	Controls.controls_path = Controls.PLAYER_CONTROLS
	Controls.reload()


## Makes `folder` exist and hold no files, whether or not it was there before.
static func empty_folder(folder: String) -> void:
	DirAccess.make_dir_recursive_absolute(folder)
	for file: String in DirAccess.get_files_at(folder):
		DirAccess.remove_absolute(folder.path_join(file))
