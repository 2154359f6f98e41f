class_name SettingsSandbox
extends RefCounted
## Test helper: points the Settings autoload at scratch files, so tests never touch the
## player's own settings, records and ghosts, and back again.

const SETTINGS := "user://test-settings.cfg"
const RECORDS := "user://test-records.cfg"
const GHOSTS := "user://test-ghosts"


## Switches Settings to empty scratch files (defaults).
static func enter() -> void:
	for path: String in [SETTINGS, RECORDS, SETTINGS + ".broken"]:
		DirAccess.remove_absolute(path)
	Settings.settings_path = SETTINGS
	Settings.records_path = RECORDS
	Settings.ghosts_dir = GHOSTS
	for ghost: String in DirAccess.get_files_at(GHOSTS):
		DirAccess.remove_absolute(GHOSTS.path_join(ghost))
	Settings.reload()


## Switches Settings back to the player's files.
static func leave() -> void:
	Settings.settings_path = Settings.PLAYER_SETTINGS
	Settings.records_path = Settings.PLAYER_RECORDS
	Settings.ghosts_dir = Settings.PLAYER_GHOSTS
	Settings.reload()
