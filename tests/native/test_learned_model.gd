extends TestCase
## The learned and guided controllers in the node: the project's model drives, and a
## missing or corrupt model file is reported (once, with the reason) while the arcade
## controller steers and nothing crashes.

const CORRUPT := "user://corrupt_policy.safetensors"
## A bike with no learned networks of its own, nor ever will have.
const PIT_BIKE := preload("res://tests/fixtures/bikes/pit_bike.tres")

var _level: Node3D
var _bike: BikeSimulation


func before_each() -> void:
	_level = FlatLevel.create()
	add_child(_level)
	_bike = BikeSimulation.new()
	_bike.transform = Transform3D(Basis(), Vector3(0, 0.02, 0))
	_level.add_child(_bike)
	await wait_physics_frames(1)
	_bike.set_physics_process(false)


func after_each() -> void:
	_level.queue_free()


func _ride_reporting(model: String, controller: String, steps: int) -> Array[String]:
	var reasons: Array[String] = []
	_bike.controller_failed.connect(func(reason: String) -> void: reasons.append(reason))
	_bike.policy_model = model
	_bike.controller = controller
	_bike.trajectories = 4
	_bike.wait_for_every_plan = true
	_bike.set_drive(1.0, 0.0)
	_bike.advance(steps)
	return reasons


## The pit bike beside the reference one, stepped by the test alone.
func _pit_bike() -> BikeSimulation:
	var pit := BikeSimulation.new()
	pit.bike = PIT_BIKE
	pit.transform = Transform3D(Basis(), Vector3(3, 0.02, 0))
	_level.add_child(pit)
	await wait_physics_frames(1)
	pit.set_physics_process(false)
	return pit


func test_the_project_ships_a_model_and_the_learned_controller_rides_with_it() -> void:
	var own := _bike.get_policy_model_path()
	assert_eq(own, "res://models/policy-street_350.safetensors", "the reference bike's own")
	assert_true(FileAccess.file_exists(own), "the model `make train` wrote")
	assert_has(_bike.get_offered_controller_names(), "learned")
	var reasons := _ride_reporting("", "learned", 90)
	assert_eq(reasons, [] as Array[String])
	assert_eq(_bike.get_controller_failure(), "", "the network drives")
	assert_false(_bike.is_crashed())
	assert_gt(_bike.get_speed(), 2.0, "and rides off")


func test_without_a_model_learned_says_why_and_arcade_steers() -> void:
	var reasons := _ride_reporting("res://no/such/policy.safetensors", "learned", 90)
	assert_eq(reasons.size(), 1, "reported once: %s" % [reasons])
	assert_has(_bike.get_controller_failure(), "is missing")
	assert_has(_bike.get_controller_failure(), "arcade steers")
	assert_false(_bike.is_crashed(), "the arcade controller kept it up")
	assert_gt(_bike.get_speed(), 2.0)


func test_a_corrupt_model_is_refused_and_guided_plans_with_arcade() -> void:
	var file := FileAccess.open(CORRUPT, FileAccess.WRITE)
	file.store_string("not a model at all")
	file.close()
	var reasons := _ride_reporting(CORRUPT, "guided", 30)
	DirAccess.remove_absolute(CORRUPT)
	assert_eq(reasons.size(), 1, "reported once: %s" % [reasons])
	assert_has(_bike.get_controller_failure(), "unusable")
	assert_has(_bike.get_controller_failure(), "the arcade controller guides")
	assert_gt(_bike.get_trajectory_paths().size(), 0, "the planner still plans")
	assert_false(_bike.is_crashed())


func test_a_bike_without_a_model_of_its_own_offers_no_learned_and_guided_plans_without() -> void:
	var pit := await _pit_bike()
	assert_eq(pit.get_policy_model_path(), "", "no model of its own")
	var offered := pit.get_offered_controller_names()
	assert_false(offered.has("learned"), "learned is not offered: %s" % [offered])
	assert_has(offered, "guided")
	assert_has(offered, "arcade")
	var reasons: Array[String] = []
	pit.controller_failed.connect(func(reason: String) -> void: reasons.append(reason))
	pit.controller = "guided"
	pit.trajectories = 4
	pit.wait_for_every_plan = true
	pit.set_drive(1.0, 0.0)
	pit.advance(30)
	assert_eq(reasons.size(), 1, "reported once: %s" % [reasons])
	assert_has(pit.get_controller_failure(), "pit_bike has no learned model of its own")
	assert_gt(pit.get_trajectory_paths().size(), 0, "the planner still plans")


func test_without_its_cost_to_go_a_planner_plans_its_whole_horizon_and_says_so() -> void:
	var pit := await _pit_bike()
	var reasons: Array[String] = []
	pit.controller_failed.connect(func(reason: String) -> void: reasons.append(reason))
	pit.controller = "combined"
	pit.trajectories = 4
	pit.wait_for_every_plan = true
	pit.terminal_value = true
	pit.value_horizon = 0.6
	pit.set_drive(1.0, 0.0)
	pit.advance(30)
	assert_eq(reasons.size(), 1, "reported once: %s" % [reasons])
	assert_has(pit.get_controller_failure(), "value-pit_bike.safetensors is missing")
	assert_has(pit.get_controller_failure(), "it plans its whole horizon")
	assert_almost_eq(pit.get_planned_horizon(), 1.2, 1e-9)
	assert_false(pit.is_horizon_ended_by_value())
	assert_eq(pit.get_trajectory_paths()[0].size(), 36, "the whole 1.2 s is planned")
	assert_false(pit.is_crashed())
	pit.terminal_value = false
	pit.advance(2)
	assert_eq(pit.get_controller_failure(), "", "asked for none: nothing to say")
