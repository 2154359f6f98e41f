class_name SettingsSandbox
extends RefCounted
## Test helper: points the Settings autoload at scratch files, so tests never touch the
## player's own settings and records, and back again.

const SETTINGS := "user://test-settings.cfg"
const RECORDS := "user://test-records.cfg"


## Switches Settings to empty scratch files (defaults).
static func enter() -> void:
	for path: String in [SETTINGS, RECORDS, SETTINGS + ".broken"]:
		DirAccess.remove_absolute(path)
	Settings.settings_path = SETTINGS
	Settings.records_path = RECORDS
	Settings.reload()


## Switches Settings back to the player's files.
static func leave() -> void:
	Settings.settings_path = "user://settings.cfg"
	Settings.records_path = "user://records.cfg"
	Settings.reload()
