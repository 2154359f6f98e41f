extends Node
## The player's medals (autoload `Progress`): the best score and medal of every lesson and
## challenge on every bike, and what was played last. Every change is saved at once,
## atomically, to `user://medals.cfg` (ConfigStore), so a crash or a kill loses nothing
## earned. A file that cannot be read, or that holds anything but medals and scores (a
## hand edit gone wrong), is kept aside as `medals.cfg.broken` with a message, and play
## goes on with no medals.

## A medal was earned or a best improved, or the file was read again.
signal changed

const PLAYER_MEDALS := "user://medals.cfg"
const PROGRESS := "progress"
const MEDAL := "medal"
const BEST := "best"

var medals_path := PLAYER_MEDALS
## What was wrong with the file when it was last read (empty: nothing), for the menu.
var problem := ""

var _file := ConfigFile.new()


func _ready() -> void:
	reload()


## Reads the medals file again (at start, and by tests that point `medals_path` elsewhere).
func reload() -> void:
	problem = ""
	var existed := FileAccess.file_exists(medals_path)
	_file = ConfigStore.load_or_empty(medals_path)
	if existed and not FileAccess.file_exists(medals_path):
		problem = "your medals file could not be read; it was kept as medals.cfg.broken"
	var wrong := _first_wrong_value(_file)
	if not wrong.is_empty():
		push_warning(
			(
				"%s holds %s; starting with no medals, the old file is kept as %s.broken"
				% [medals_path, wrong, medals_path]
			)
		)
		DirAccess.rename_absolute(medals_path, medals_path + ".broken")
		problem = "your medals file held %s; it was kept as medals.cfg.broken" % wrong
		_file = ConfigFile.new()
	changed.emit()


## The medal earned on `challenge` (its key) riding `bike`.
func medal(challenge: String, bike: String) -> Challenge.Medal:
	return int(_entry(challenge, bike).get(MEDAL, Challenge.Medal.NONE)) as Challenge.Medal


## The best score on `challenge` riding `bike` (NAN: none yet).
func best(challenge: String, bike: String) -> float:
	return float(_entry(challenge, bike).get(BEST, NAN))


## The best medal on `challenge` on any bike.
func best_medal(challenge: String) -> Challenge.Medal:
	var best_one := Challenge.Medal.NONE
	var section := _section(challenge)
	if _file.has_section(section):
		for bike: String in _file.get_section_keys(section):
			best_one = maxi(best_one, medal(challenge, bike)) as Challenge.Medal
	return best_one


## Records a passed attempt at `challenge` on `bike` with `score`: saved when it is the
## best so far. Returns whether it was.
func record(challenge: Challenge, bike: String, score: float) -> bool:
	var earlier := best(challenge.key(), bike)
	if not is_finite(score) or (is_finite(earlier) and not _better(challenge, score, earlier)):
		return false
	var entry := {MEDAL: challenge.medal_for(score), BEST: score}
	_file.set_value(_section(challenge.key()), bike, entry)
	ConfigStore.save(_file, medals_path)
	changed.emit()
	return true


## The lesson, challenge or level played last (a challenge's key or a level's; empty: none).
func last_played() -> String:
	return str(_file.get_value(PROGRESS, "last_played", ""))


## Remembers `key` (a challenge's or a level's) as played last.
func set_last_played(key: String) -> void:
	if key == last_played():
		return
	_file.set_value(PROGRESS, "last_played", key)
	ConfigStore.save(_file, medals_path)


static func _better(challenge: Challenge, score: float, than: float) -> bool:
	return score < than if challenge.lower_is_better else score > than


static func _section(challenge: String) -> String:
	return "medals/" + challenge


func _entry(challenge: String, bike: String) -> Dictionary:
	var value: Variant = _file.get_value(_section(challenge), bike, {})
	return value if value is Dictionary else {}


## The first value of `file` that is not a medal with a score or the last played key
## ("medals/x street_390 = 7"); empty when all are.
static func _first_wrong_value(file: ConfigFile) -> String:
	for section in file.get_sections():
		for key in file.get_section_keys(section):
			var value: Variant = file.get_value(section, key)
			var fine := (
				section == PROGRESS and key == "last_played" and value is String
				or section.begins_with("medals/") and _is_medal_entry(value)
			)
			if not fine:
				return "[%s] %s = %s" % [section, key, var_to_str(value)]
	return ""


static func _is_medal_entry(value: Variant) -> bool:
	if not value is Dictionary or value.size() != 2:
		return false
	var medal_value: Variant = value.get(MEDAL)
	var best_value: Variant = value.get(BEST)
	return (
		medal_value is int
		and medal_value >= Challenge.Medal.NONE
		and medal_value <= Challenge.Medal.GOLD
		and (best_value is float or best_value is int)
		and is_finite(float(best_value))
	)
