@tool
class_name ChallengeCatalogue
extends Resource
## The lessons of the School, in the order they are taught, and the challenges of the
## levels: paths to Challenge files, so one that is missing or broken is named in the menu
## instead of stopping the game.

const PATH := "res://scenes/challenges/catalogue.tres"

## The School's lessons, each opened by a medal in the one before (ChallengeMenu).
@export_file("*.tres") var lessons: Array[String] = []
## The levels' challenges, open from the start.
@export_file("*.tres") var challenges: Array[String] = []


## The game's catalogue (an empty one, with an error, when its file cannot be read).
static func game() -> ChallengeCatalogue:
	var found := load(PATH) as ChallengeCatalogue if ResourceLoader.exists(PATH) else null
	if found == null:
		push_error("ChallengeCatalogue: %s cannot be read; no lessons or challenges" % PATH)
		return ChallengeCatalogue.new()
	return found


## The challenge at `path`, or null (with an error) when it is missing or is not one.
static func load_challenge(path: String) -> Challenge:
	var challenge := load(path) as Challenge if ResourceLoader.exists(path) else null
	if challenge == null:
		push_error("ChallengeCatalogue: %s is not a challenge" % path)
	return challenge


## The challenge at `path` if it can be ridden; null for an empty path, or (with an error
## saying why) for one that cannot: then the ride is free.
static func load_rideable(path: String) -> Challenge:
	if path.is_empty():
		return null
	var challenge := load_challenge(path)
	if challenge != null and not challenge.problem().is_empty():
		push_error("ChallengeCatalogue: %s cannot be ridden: %s" % [path, challenge.problem()])
		return null
	return challenge


## The challenges ridden on the level scene at `level_path`, in the catalogue's order.
func challenges_on(level_path: String) -> Array[String]:
	var found: Array[String] = []
	for path in challenges:
		var challenge := load_challenge(path)
		if challenge != null and challenge.level == level_path:
			found.append(path)
	return found


## The lesson after the one at `path` (empty: it is the last, or not a lesson).
func next_lesson(path: String) -> String:
	var index := lessons.find(path)
	return lessons[index + 1] if index >= 0 and index + 1 < lessons.size() else ""
