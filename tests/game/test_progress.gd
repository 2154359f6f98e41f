extends TestCase
## The player's medals (Progress): the best score and medal per lesson and bike, saved at
## once; a file that cannot be read or was hand-edited into nonsense is set aside with a
## message and play goes on with none; medals follow each challenge's thresholds.

const RIDE_OFF := "res://scenes/challenges/lessons/ride_off.tres"
const COUNTER_STEER := "res://scenes/challenges/lessons/counter_steer.tres"


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	SettingsSandbox.leave()


func test_the_best_score_and_its_medal_are_kept_per_bike_and_saved() -> void:
	var lesson := ChallengeCatalogue.load_challenge(RIDE_OFF)
	assert_true(Progress.record(lesson, "street_390", 1.2), "a first score is the best")
	assert_false(Progress.record(lesson, "street_390", 1.4), "a worse one is not kept")
	assert_true(Progress.record(lesson, "street_390", 0.1), "a better one is")
	assert_true(Progress.record(lesson, "dirt_125", 0.9))
	Progress.reload()
	assert_eq(Progress.best("ride_off", "street_390"), 0.1)
	assert_eq(Progress.medal("ride_off", "street_390"), Challenge.Medal.GOLD)
	assert_eq(Progress.medal("ride_off", "dirt_125"), Challenge.Medal.BRONZE)
	assert_eq(Progress.medal("ride_off", "sport_600"), Challenge.Medal.NONE)
	assert_true(is_nan(Progress.best("ride_off", "sport_600")), "none yet")
	assert_eq(Progress.best_medal("ride_off"), Challenge.Medal.GOLD)
	assert_eq(Progress.problem, "")


func test_the_last_played_is_remembered() -> void:
	assert_eq(Progress.last_played(), "")
	Progress.set_last_played("track")
	Progress.reload()
	assert_eq(Progress.last_played(), "track")


func test_a_file_that_cannot_be_read_is_kept_aside_and_play_goes_on() -> void:
	var file := FileAccess.open(Progress.medals_path, FileAccess.WRITE)
	file.store_string('[medals/ride_off\nstreet_390 = {"medal": 3')
	file.close()
	expect_error("ConfigFile parse error")
	Progress.reload()
	assert_eq(Progress.medal("ride_off", "street_390"), Challenge.Medal.NONE)
	assert_has(Progress.problem, "could not be read")
	assert_true(FileAccess.file_exists(Progress.medals_path + ".broken"), "kept aside")
	Progress.reload()
	assert_eq(Progress.problem, "", "said once: the next start finds no file")


func test_a_hand_edited_medal_is_kept_aside_with_what_it_held() -> void:
	for wrong: String in ['{"medal": 7, "best": 0.1}', '{"medal": 3, "best": "fast"}', "3"]:
		var file := FileAccess.open(Progress.medals_path, FileAccess.WRITE)
		file.store_string("[medals/ride_off]\nstreet_390=%s\n" % wrong)
		file.close()
		DirAccess.remove_absolute(Progress.medals_path + ".broken")
		Progress.reload()
		assert_eq(Progress.medal("ride_off", "street_390"), Challenge.Medal.NONE, wrong)
		assert_has(Progress.problem, "[medals/ride_off] street_390")
		assert_true(FileAccess.file_exists(Progress.medals_path + ".broken"), wrong)
		assert_false(FileAccess.file_exists(Progress.medals_path), "no file left to misread")


func test_medals_follow_the_thresholds_whichever_way_is_better() -> void:
	var lower := ChallengeCatalogue.load_challenge(COUNTER_STEER)
	assert_eq(lower.medal_for(lower.gold), Challenge.Medal.GOLD, "the threshold itself")
	assert_eq(lower.medal_for(lower.gold + 0.01), Challenge.Medal.SILVER)
	assert_eq(lower.medal_for(lower.bronze + 0.01), Challenge.Medal.NONE)
	assert_eq(lower.medal_for(NAN), Challenge.Medal.NONE)
	var higher := Challenge.new()
	higher.lower_is_better = false
	higher.bronze = 30.0
	higher.silver = 38.0
	higher.gold = 43.0
	higher.unit = "°"
	assert_eq(higher.medal_for(44.0), Challenge.Medal.GOLD)
	assert_eq(higher.medal_for(35.0), Challenge.Medal.BRONZE)
	assert_eq(higher.medal_for(20.0), Challenge.Medal.NONE)
	assert_eq(higher.thresholds_text(), "gold ≥ 43.0° · silver ≥ 38.0° · bronze ≥ 30.0°")


func test_every_lesson_in_the_catalogue_can_be_ridden() -> void:
	var catalogue := ChallengeCatalogue.game()
	assert_gt(catalogue.lessons.size(), 3)
	for path in catalogue.lessons + catalogue.challenges:
		var challenge := ChallengeCatalogue.load_challenge(path)
		assert_not_null(challenge, path)
		if challenge == null:
			continue
		assert_eq(challenge.problem(), "", path)
		assert_true(
			challenge.reaches(challenge.gold, challenge.silver), "gold beats silver: " + path
		)
		assert_true(
			challenge.reaches(challenge.silver, challenge.bronze), "silver beats bronze: " + path
		)
		var level := (load(challenge.level) as PackedScene).instantiate()
		var area := level.get_node_or_null(challenge.area) as ChallengeArea
		assert_not_null(area, "%s: its area %s" % [path, challenge.area])
		if area != null:
			assert_not_null(area.spawn_point(), "%s: a spawn point" % path)
		level.free()
