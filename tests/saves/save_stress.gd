extends Node
## Saves the player's settings, records, medals and a ghost over and over (`--write`, after
## clearing the folder with `--fresh`), to be killed with SIGKILL at a random moment by
## tools/kill-test.sh; then (`--check`) reads them back with the game's own loaders: each
## file must be whole, either the last save or the one before, never half of one or set
## aside as broken.
##
## Works in `user://kill-test/` of the scratch data home tools/kill-test.sh gives it, never
## on the player's own files.

const FOLDER := "user://kill-test"
const LEVEL := "track"
## A lesson whose best score improves every round, as a lap does.
const LESSON := "res://scenes/challenges/lessons/counter_steer.tres"
const BIKE := "street_390"
const BODIES := 11
## A ghost as long as a five-minute lap (9000 frames), so a save takes a while to write.
const FRAMES := 9000


func _ready() -> void:
	if "--fresh" in OS.get_cmdline_user_args():
		for folder: String in [FOLDER.path_join("ghosts"), FOLDER]:
			SettingsSandbox.empty_folder(folder)
	Settings.settings_path = FOLDER.path_join("settings.cfg")
	Settings.records_path = FOLDER.path_join("records.cfg")
	Settings.ghosts_dir = FOLDER.path_join("ghosts")
	Settings.reload()
	Progress.medals_path = FOLDER.path_join("medals.cfg")
	Progress.reload()
	Controls.controls_path = FOLDER.path_join("controls.cfg")
	Controls.reload()
	if "--check" in OS.get_cmdline_user_args():
		get_tree().quit(_check())
	else:
		_write_forever()


func _write_forever() -> void:
	# Carry on from the rounds of the writer killed before, so every lap is a new best.
	var best := Settings.best_lap(LEVEL)
	var round := roundi((100.0 - best) / 0.001) if is_finite(best) else 0
	while true:
		round += 1
		Settings.set_value(&"trajectories", Settings.offered(&"trajectories")[round % 6])
		Settings.record_lap(LEVEL, _lap_time(round))
		Progress.record(ChallengeCatalogue.load_challenge(LESSON), BIKE, _lap_time(round))
		Controls.bind(&"throttle", _throttle_key(round))
		GhostFile.save(_ghost(round), LEVEL, Settings.ghost_path(LEVEL))
		print("saved round %d" % round)
		await get_tree().process_frame


## 0 when everything read back whole and consistent, 1 otherwise.
func _check() -> int:
	var problems: Array[String] = []
	for folder: String in [FOLDER, Settings.ghosts_dir]:
		for file: String in DirAccess.get_files_at(folder):
			if file.ends_with(".broken"):
				problems.append("%s was set aside as broken" % file)
	if not Settings.offered(&"trajectories").has(Settings.get_value(&"trajectories")):
		problems.append("settings hold %s" % Settings.get_value(&"trajectories"))
	var loaded := GhostFile.load_ghost(Settings.ghost_path(LEVEL), LEVEL, BODIES)
	var ghost := loaded.recording as RideRecording
	var round := -1
	if ghost == null:
		problems.append("no ghost: %s" % loaded.problem)
	else:
		round = roundi(ghost.splits[0])
		if ghost.poses != _ghost(round).poses or ghost.lap_time != _lap_time(round):
			problems.append("the ghost of round %d is not what was saved" % round)
		# The record is saved just before the ghost: the same round or the next.
		var best := Settings.best_lap(LEVEL)
		if best != _lap_time(round) and best != _lap_time(round + 1):
			problems.append("best lap %s against the ghost's round %d" % [best, round])
		# The medal is saved between the record and the ghost: the same round or the next.
		var medal_best := Progress.best("counter_steer", BIKE)
		if medal_best != _lap_time(round) and medal_best != _lap_time(round + 1):
			problems.append(
				"best medal score %s against the ghost's round %d" % [medal_best, round]
			)
	if not Progress.problem.is_empty():
		problems.append(Progress.problem)
	if not Controls.problem.is_empty():
		problems.append(Controls.problem)
	var throttle := Controls.events_of(&"throttle", Controls.KEYBOARD)
	if throttle.size() != 2:
		problems.append("the throttle has %d keys, not two" % throttle.size())
	for problem in problems:
		printerr("kill test: ", problem)
	if problems.is_empty():
		print(
			(
				"kill test: settings, record, medal, controls and ghost of round %d read back whole"
				% round
			)
		)
	return 0 if problems.is_empty() else 1


## A letter key for the throttle each round (G to Z, round and round: never W's place
## twice in a row).
static func _throttle_key(round: int) -> InputEventKey:
	var key := InputEventKey.new()
	key.physical_keycode = (KEY_G + round % 20) as Key
	return key


## Laps get faster every round, so every one is a new best.
static func _lap_time(round: int) -> float:
	return 100.0 - round * 0.001


## A ghost whose every number says which round saved it.
static func _ghost(round: int) -> RideRecording:
	var recording := RideRecording.new(30.0, BODIES)
	recording.lap_time = _lap_time(round)
	recording.splits.append(round)
	recording.poses.resize(FRAMES * BODIES * BikeSimulation.POSE_FLOATS)
	recording.poses.fill(round)
	return recording
