extends TestCase
## Ghosts on disk: read back exactly, interpolated between frames, and a file that is
## damaged, cut short, of an older format, another level or another bike is set aside with
## a reason, never trusted, never a crash.

const PATH := "user://test-ghosts/unit.ghost"


func before_each() -> void:
	SettingsSandbox.enter()
	for file: String in [PATH, PATH + ".broken", PATH + ".tmp"]:
		DirAccess.remove_absolute(file)


func after_each() -> void:
	SettingsSandbox.leave()


## A lap of `frames` frames of `bodies` bodies moving 1 m along x per frame.
func _lap(frames := 4, bodies := 11) -> RideRecording:
	var recording := RideRecording.new(30.0, bodies)
	recording.lap_time = 12.5
	recording.splits = PackedFloat32Array([4.0, 8.25])
	for frame in frames:
		var numbers := PackedFloat32Array()
		for body in bodies:
			numbers.append_array([frame, body, 0.0, 0.0, 0.0, 0.0, 1.0])
		recording.add(numbers)
	return recording


func test_a_lap_reads_back_exactly() -> void:
	var lap := _lap()
	assert_eq(GhostFile.save(lap, "track", PATH), OK)
	assert_false(FileAccess.file_exists(PATH + ".tmp"), "no temporary left")
	var loaded := GhostFile.load_ghost(PATH, "track", 11)
	assert_eq(loaded.problem, "")
	var back := loaded.recording as RideRecording
	assert_eq(back.poses, lap.poses)
	assert_eq(back.splits, lap.splits)
	assert_eq(back.lap_time, 12.5)
	assert_eq(back.rate, 30.0)


func test_poses_are_interpolated_between_frames_and_held_at_the_ends() -> void:
	var lap := _lap()
	assert_almost_eq(lap.duration(), 3.0 / 30.0, 1e-6)
	assert_almost_eq(lap.pose_of(2, 1.5 / 30.0).origin, Vector3(1.5, 2, 0), Vector3.ONE * 1e-5)
	assert_eq(lap.pose_of(0, -1.0).origin, Vector3(0, 0, 0))
	assert_eq(lap.pose_of(0, 99.0).origin, Vector3(3, 0, 0))
	assert_eq(lap.poses_at(0.0).size(), 11)
	expect_error("a frame of 3 numbers")
	assert_false(lap.add(PackedFloat32Array([1, 2, 3])), "a frame of the wrong size")


func test_no_file_is_no_ghost_and_no_problem() -> void:
	var loaded := GhostFile.load_ghost(PATH, "track", 11)
	assert_null(loaded.recording)
	assert_eq(loaded.problem, "")


func test_a_file_cut_short_or_damaged_is_set_aside() -> void:
	for damage: String in ["cut", "flipped"]:
		GhostFile.save(_lap(), "track", PATH)
		var bytes := FileAccess.get_file_as_bytes(PATH)
		if damage == "cut":
			bytes = bytes.slice(0, bytes.size() / 2)
		else:
			bytes[100] = bytes[100] ^ 0x10
		FileAccess.open(PATH, FileAccess.WRITE).store_buffer(bytes)
		var loaded := GhostFile.load_ghost(PATH, "track", 11)
		assert_null(loaded.recording, damage)
		assert_eq(loaded.problem, "it is damaged or cut short", damage)
		assert_true(FileAccess.file_exists(PATH + ".broken"), "%s: kept aside" % damage)
		assert_false(FileAccess.file_exists(PATH), "%s: no longer raced" % damage)
		DirAccess.remove_absolute(PATH + ".broken")


func test_another_level_or_bike_is_set_aside_with_the_reason() -> void:
	GhostFile.save(_lap(), "skate_park", PATH)
	assert_eq(GhostFile.load_ghost(PATH, "track", 11).problem, "it was ridden on skate_park")
	DirAccess.remove_absolute(PATH + ".broken")
	GhostFile.save(_lap(4, 9), "track", PATH)
	assert_eq(GhostFile.load_ghost(PATH, "track", 11).problem, "it was recorded of another bike")


func test_an_older_format_is_set_aside_not_misread() -> void:
	GhostFile.save(_lap(), "track", PATH)
	var bytes := FileAccess.get_file_as_bytes(PATH).slice(0, -32)
	bytes.encode_u32(GhostFile.MAGIC.length(), GhostFile.FORMAT - 1)
	var hashing := HashingContext.new()
	hashing.start(HashingContext.HASH_SHA256)
	hashing.update(bytes)
	bytes.append_array(hashing.finish())
	FileAccess.open(PATH, FileAccess.WRITE).store_buffer(bytes)
	var loaded := GhostFile.load_ghost(PATH, "track", 11)
	assert_eq(loaded.problem, "it has format 0, this game reads 1")


func test_a_save_interrupted_before_its_rename_leaves_the_old_ghost_whole() -> void:
	GhostFile.save(_lap(), "track", PATH)
	# What a kill in the middle of the next save leaves: half a temporary file.
	var half := FileAccess.get_file_as_bytes(PATH).slice(0, 500)
	FileAccess.open(PATH + ".tmp", FileAccess.WRITE).store_buffer(half)
	assert_eq(GhostFile.load_ghost(PATH, "track", 11).problem, "")
	assert_eq(GhostFile.save(_lap(6), "track", PATH), OK, "the next save goes through")
	assert_eq((GhostFile.load_ghost(PATH, "track", 11).recording as RideRecording).frame_count(), 6)


func test_the_game_sets_a_broken_ghost_aside_and_says_so() -> void:
	var path := Settings.ghost_path("track")
	DirAccess.make_dir_recursive_absolute(path.get_base_dir())
	FileAccess.open(path, FileAccess.WRITE).store_string("not a ghost at all")
	var game := (load("res://scenes/game/game.tscn") as PackedScene).instantiate() as Game
	game.level_path = "res://scenes/levels/track/track.tscn"
	add_child(game)
	await wait_frames(2)
	assert_null(game.ghost_race.ghost(), "nothing to race")
	assert_true(FileAccess.file_exists(path + ".broken"), "the file is kept aside")
	var banner := (game.get_node(^"Hud/%Banner") as Label).text
	assert_true(banner.begins_with("Your ghost could not be read"), banner)
	game.queue_free()
	await wait_frames(1)
