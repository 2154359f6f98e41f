class_name ChallengeRun
extends Node
## A lesson or challenge being ridden: it starts every attempt at its area's spawn point
## with a fresh copy of its judge, asks the judge for a verdict every physics tick, fails
## a fall or a ride past the time limit in words a player understands, and saves a medal
## won (per bike, `Progress`). Only the challenge's own area of the level shows its markers.

## The attempt ended: `result` as judged, the `medal` it earned and whether it is the best
## so far on this bike.
signal finished(result: ChallengeResult, medal: Challenge.Medal, new_best: bool)

## Outcome `judge` returns for an attempt that missed its goal (the level's own outcomes
## are RIDING, GOAL, FELL and TIMEOUT).
const MISSED := "missed"

var challenge: Challenge
## Its file, and the card that briefs the player and shows the result.
var challenge_path := ""
var card: ChallengeCard
## The attempt's judge (a copy of the challenge's), and how the last attempt ended.
var judge: ChallengeJudge
var result: ChallengeResult
## The area ridden in (null: the level has none of that name; then the ride is free).
var area: ChallengeArea

var _bike: BikeSimulation
var _driver: BikeDriver
var _bike_key := ""
var _crash_cause := ""


## Rides `ridden` (the file at `path`) in `game`'s level on its bike (`bike_key` names it
## for the medals), the player's hands being `driver`; builds its card, whose "next lesson"
## it answers (retrying and leaving are the game's). Hides every other area's markers.
func setup(path: String, ridden: Challenge, game: Game, driver: BikeDriver) -> void:
	challenge_path = path
	challenge = ridden
	_bike = game.bike
	_driver = driver
	_bike_key = game.bike_key
	area = game.level.get_node_or_null(challenge.area) as ChallengeArea
	if area == null:
		push_error("ChallengeRun: %s has no ChallengeArea %s" % [game.level.name, challenge.area])
	for other in game.level.challenge_areas():
		other.visible = other == area
	_bike.crashed.connect(func(cause: String) -> void: _crash_cause = cause)
	Progress.set_last_played(challenge.key())
	var catalogue := ChallengeCatalogue.game()
	var lesson := catalogue.lessons.find(path)
	var next := catalogue.next_lesson(path)
	card = ChallengeCard.new()
	card.name = "ChallengeCard"
	add_child(card)
	card.setup(
		self, _bike, "Lesson %d" % (lesson + 1) if lesson >= 0 else "Challenge", not next.is_empty()
	)
	# Only a game that is the running scene leaves for the next (a test's stays).
	card.next_requested.connect(
		func() -> void:
			if game == get_tree().current_scene:
				ride(get_tree(), next)
	)


## Leaves for a new game riding the lesson or challenge at `path`.
static func ride(tree: SceneTree, path: String) -> void:
	var game := (load("res://scenes/game/game.tscn") as PackedScene).instantiate() as Game
	game.challenge_path = path
	tree.paused = false
	tree.change_scene_to_node(game)


## The spawn point the challenge starts from (null: the level's first).
func spawn_point() -> SpawnPoint:
	return area.spawn_point() if area != null else null


## Starts an attempt (the bike was just placed at the spawn point).
func begin() -> void:
	result = null
	_crash_cause = ""
	if challenge.top_speed_kmh > 0.0:
		_driver.max_speed_kmh = challenge.top_speed_kmh
	if judge != null:
		judge.end()
	judge = challenge.judge.duplicate(true) as ChallengeJudge if challenge.judge != null else null
	if judge != null and area != null:
		judge.begin(area, _bike)


func _exit_tree() -> void:
	if judge != null:
		judge.end()


## How the attempt stands after `delta` more seconds, given the level's own `outcome` for
## them: Level.RIDING while it goes on (or once judged, until the next attempt),
## Level.GOAL when passed, MISSED or Level.FELL when not (then `result` says why).
func judge_attempt(outcome: String, delta: float) -> String:
	if result != null:
		return Level.RIDING
	if outcome == Level.FELL:
		var cause := _crash_cause if not _crash_cause.is_empty() else "the bike went down"
		result = ChallengeJudge.failed("you fell: %s" % cause)
		return Level.FELL
	if judge == null or area == null:
		return Level.RIDING
	var verdict := judge.judge(delta)
	if verdict == null and judge.elapsed > challenge.time_limit:
		verdict = ChallengeJudge.failed(
			"out of time: this one takes at most %s" % Level.format_time(challenge.time_limit)
		)
	if verdict == null:
		return Level.RIDING
	result = verdict
	return Level.GOAL if verdict.passed else MISSED


## Ends the attempt judged: saves a passed one's medal if it is the best on this bike,
## and says how it went (`finished`).
func finish() -> void:
	if result == null:
		return
	var medal := challenge.medal_for(result.score) if result.passed else Challenge.Medal.NONE
	var new_best := result.passed and Progress.record(challenge, _bike_key, result.score)
	finished.emit(result, medal, new_best)


## The line the HUD shows while riding ("gate 2 of 6").
func progress_text() -> String:
	return judge.progress_text() if judge != null else ""


## The medal and best score on this bike so far.
func medal_so_far() -> Challenge.Medal:
	return Progress.medal(challenge.key(), _bike_key)


func best_so_far() -> float:
	return Progress.best(challenge.key(), _bike_key)
