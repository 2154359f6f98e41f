extends TestCase
## The thesis's automatic test on the game's own test level: riding straight across seeded
## bumps at 15 km/h, the combined controller with 5 trajectories reaches the goal.

const LEVEL := preload("res://scenes/levels/test_level/test_level.tscn")
const BIKE := preload("res://scenes/bike/bike.tscn")

var _level: TestLevel
var _bike: BikeSimulation


func before_each() -> void:
	_level = LEVEL.instantiate()
	add_child(_level)
	_bike = BIKE.instantiate()
	# By the name the level got: the last test's level may still be in the tree, freed only
	# at the end of the frame, and hold the name "TestLevel".
	_bike.terrain_root = NodePath("../%s" % _level.name)
	_bike.transform = _level.spawn_points()[0].spawn_transform()
	add_child(_bike)
	_level.attach(_bike)
	_bike.set_physics_process(false)
	# Wait for every plan, so the run repeats exactly for its seeds.
	_bike.wait_for_every_plan = true


func after_each() -> void:
	_bike.queue_free()
	_level.queue_free()


func test_the_same_seed_lays_the_same_bumps() -> void:
	var bumps: BumpField = _level.get_node("Bumps")
	bumps.regenerate(7)
	var first := _bump_positions(bumps)
	bumps.regenerate(8)
	assert_ne(_bump_positions(bumps), first, "another seed, other bumps")
	bumps.regenerate(7)
	assert_eq(_bump_positions(bumps), first, "seed 7 again")
	assert_eq(first.size(), bumps.field.count)


func test_the_limit_leaves_time_to_reach_the_goal_at_walking_pace() -> void:
	for speed: float in [10.0, 15.0, 25.0, 30.0]:
		assert_eq(_level.time_limit_at(speed), _level.time_limit, "%d km/h: the thesis's" % speed)
	assert_gt(_level.time_limit_at(5.0), 36.0, "5 km/h: half as long again as the course")
	_bike.controller = "arcade"
	var result := TestRun.ride(_level, _bike, 1000, 5.0)
	assert_eq(result.outcome, Level.GOAL, "arcade at 5 km/h: %s" % [result])
	assert_gt(result.time, _level.time_limit, "longer than the thesis's limit")


func test_combined_with_5_trajectories_reaches_the_goal_in_9_of_10_attempts() -> void:
	_bike.controller = "combined"
	_bike.trajectories = 5
	var reached := 0
	var outcomes: Array[String] = []
	for attempt in 10:
		var result := TestRun.ride(_level, _bike, 1000 + attempt, 15.0)
		outcomes.append("%s %.1f s %.1f m" % [result.outcome, result.time, result.distance])
		if result.outcome == Level.GOAL:
			reached += 1
	print("    test level, combined N=5, 15 km/h: ", ", ".join(outcomes))
	assert_gt(reached, 8, "attempts that reached the goal: %s" % ", ".join(outcomes))


func test_an_attempt_repeats_exactly_whatever_was_ridden_before() -> void:
	# The experiment rides many attempts in one process; a rerun of one on its own (after
	# a resume) must give the same result.
	for controller: String in ["arcade", "combined"]:
		_bike.controller = controller
		_bike.trajectories = 5
		_bike.planner_seed = 11
		var first := TestRun.ride(_level, _bike, 5, 25.0)
		var other := TestRun.ride(_level, _bike, 6, 25.0)
		assert_ne(
			[other.steps, other.distance],
			[first.steps, first.distance],
			"%s: other bumps, another ride (the bike read the new terrain)" % controller
		)
		_bike.planner_seed = 11
		var again := TestRun.ride(_level, _bike, 5, 25.0)
		# All but the planning time, which is the machine's.
		for key: String in ["outcome", "time", "distance", "steps"]:
			assert_eq(again[key], first[key], "%s: %s" % [controller, key])
		assert_eq(first.late_plans, 0, "%s: every step had its plan" % controller)


func test_a_new_attempt_tells_the_attached_bike_once() -> void:
	var changes := [0]
	_level.terrain_changed.connect(func() -> void: changes[0] += 1)
	_level.attach(_bike)
	_level.attach(_bike)
	_level.begin_attempt(_bike, 3)
	assert_eq(changes[0], 1, "one attempt, one change")
	assert_eq(_level.terrain_changed.get_connections().size(), 2, "the bike once, and the counter")


func test_an_attempt_without_a_rider_ends_in_a_fall_or_timeout() -> void:
	# Manual mode with the bar left alone: nobody balances, the bike falls.
	_bike.controller = "manual"
	var result := TestRun.ride(_level, _bike, 1, 15.0)
	assert_eq(result.outcome, Level.FELL)
	assert_lt(result.time, 25.0)


func _bump_positions(bumps: BumpField) -> Array[Vector3]:
	var positions: Array[Vector3] = []
	for bump: Node3D in bumps.get_children():
		positions.append(bump.position)
	return positions
