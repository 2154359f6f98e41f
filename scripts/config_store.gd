class_name ConfigStore
extends RefCounted
## Reads and writes ConfigFiles so that a crash or a kill never leaves a half-written file:
## each save goes to a temporary file first, which then replaces the old one in one rename.


## Saves `config` to `path` atomically. Returns OK or the error, after reporting it.
static func save(config: ConfigFile, path: String) -> Error:
	var temporary := path + ".tmp"
	var error := config.save(temporary)
	if error == OK:
		error = DirAccess.rename_absolute(temporary, path)
	if error != OK:
		push_error("Could not save %s: %s" % [path, error_string(error)])
		DirAccess.remove_absolute(temporary)
	return error


## The ConfigFile at `path`: empty when there is none yet. A file that cannot be read is
## kept beside it as `<path>.broken` (so nothing is lost) and an empty one returned.
static func load_or_empty(path: String) -> ConfigFile:
	var config := ConfigFile.new()
	if not FileAccess.file_exists(path):
		return config
	var error := config.load(path)
	if error != OK:
		push_warning(
			(
				"%s could not be read (%s); starting from defaults, the old file is kept as %s.broken"
				% [path, error_string(error), path]
			)
		)
		DirAccess.rename_absolute(path, path + ".broken")
		return ConfigFile.new()
	return config
