class_name ExperimentWorker
extends Node
## One worker of the headless experiment (tools/experiment starts it; see
## docs/experiment.md). It rides a block of test-level attempts for one configuration on
## the game's own test level and prints one `TRY {json}` line per attempt as soon as it
## ends, so the driver can save it before the next begins. With `--timing` it instead
## rides with each trajectory count in turn and prints one `TIMING {json}` line per count.
##
## Arguments (after `--`): --speed=KMH --controller=NAME (a name of the controller registry)
## --trajectories=N[,N...] --seed=BASE --first=I --count=K --threads=T [--timing --steps=S]
## [--physics=classic|exact] [--bike=res://FILE] [--model=res://FILE] [--warm-up=CONTROLLER]
## [--set=NAME=VALUE …] [--platform]
## `--set` plans with a planner's setting other than its default (the horizon, the learned
## cost-to-go), as the game's node would with that property set.
## Attempt i uses bump seed BASE + i and a planner seed drawn from it, so every controller
## meets the same bumps at attempt i and a rerun of an attempt repeats it exactly.
## Before any attempt it prints one `PLATFORM {json}` line (NativeModule.platform()), what
## the results depend on beyond the code; `--platform` prints only that and quits.
## `--warm-up` first rides one attempt with another controller, unreported, to check that
## an attempt does not depend on what the worker rode before it.

const LEVEL := preload("res://scenes/levels/test_level/test_level.tscn")
const BIKE := preload("res://scenes/bike/bike.tscn")
## Exit codes the driver tells apart: bad arguments, a level that would not load, and a
## planner whose thread died (its attempt was ridden by the arcade stand-in: no result).
const EXIT_USAGE := 2
const EXIT_SETUP := 3
const EXIT_PLANNER_FAILED := 4

var _level: TestLevel
var _bike: BikeSimulation


func _ready() -> void:
	var args := ExperimentArgs.parse(OS.get_cmdline_user_args())
	if not args.error.is_empty():
		printerr("experiment worker: ", args.error)
		get_tree().quit(EXIT_USAGE)
		return
	print("PLATFORM ", JSON.stringify(NativeModule.platform()))
	if args.platform_only:
		get_tree().quit(0)
		return
	if not _build(args):
		get_tree().quit(EXIT_SETUP)
		return
	if not args.warm_up.is_empty():
		_warm_up(args)
	if args.timing:
		_measure_planning(args)
	else:
		_ride_attempts(args)
	get_tree().quit(EXIT_PLANNER_FAILED if _planner_failed() else 0)


func _build(args: ExperimentArgs) -> bool:
	_level = LEVEL.instantiate()
	add_child(_level)
	var problems := TerrainCheck.problems(_level)
	if not problems.is_empty():
		printerr("experiment worker: the test level has unusable shapes: ", problems)
		return false
	_bike = BIKE.instantiate()
	if not args.bike.is_empty():
		var description := load(args.bike) as BikeDescription
		if description == null or not description.problem().is_empty():
			var why := "not a bike" if description == null else description.problem()
			printerr("experiment worker: --bike=%s cannot be ridden: %s" % [args.bike, why])
			_bike.free()
			return false
		_bike.bike = description
	_bike.policy_model = args.model
	_bike.terrain_root = NodePath("../%s" % _level.name)
	_bike.transform = _level.spawn_points()[0].spawn_transform()
	_bike.controller = args.controller
	_bike.physics = args.physics
	_bike.planning_threads = args.threads
	for name: String in args.settings:
		_bike.set(name, args.settings[name])
	# Wait for every plan: no step uses a late plan, and a ride repeats exactly.
	_bike.wait_for_every_plan = true
	# Nothing is heard either.
	_bike.get_node(^"Sound").free()
	add_child(_bike)
	_level.attach(_bike)
	# Only TestRun drives the bike; nothing is drawn.
	_bike.set_physics_process(false)
	_bike.set_process(false)
	_bike.visible = false
	return true


func _ride_attempts(args: ExperimentArgs) -> void:
	_bike.trajectories = args.trajectories[0]
	var plans := BikeSimulation.controller_plans(args.controller)
	for attempt in range(args.first, args.first + args.count):
		var bump_seed := args.base_seed + attempt
		_bike.planner_seed = planner_seed_of(bump_seed)
		var started := Time.get_ticks_usec()
		var result := TestRun.ride(_level, _bike, bump_seed, args.speed)
		if not _bike.get_controller_failure().is_empty():
			return
		(
			result
			. merge(
				{
					"speed_kmh": args.speed,
					"controller": args.controller,
					"physics": args.physics,
					"trajectories": args.trajectories[0] if plans else 0,
					"attempt": attempt,
					"seed": bump_seed,
					"planner_seed": _bike.planner_seed,
					"wall_ms": (Time.get_ticks_usec() - started) / 1000.0,
				}
			)
		)
		print("TRY ", JSON.stringify(result))


## True (with the reason on stderr) when the planner's thread died during the ride.
func _planner_failed() -> bool:
	var failure := _bike.get_controller_failure()
	if failure.is_empty():
		return false
	printerr("experiment worker: the planner failed (%s); the attempt is not reported" % failure)
	return true


## The planner's seed for the attempt with bump seed `bump_seed`.
static func planner_seed_of(bump_seed: int) -> int:
	return hash([bump_seed, "planner"])


## Rides one attempt (bump seed BASE − 1) with the warm-up controller, reporting nothing.
func _warm_up(args: ExperimentArgs) -> void:
	var controller := _bike.controller
	_bike.controller = args.warm_up
	_bike.planner_seed = planner_seed_of(args.base_seed - 1)
	TestRun.ride(_level, _bike, args.base_seed - 1, args.speed)
	_bike.controller = controller


## Rides the level from its start with each trajectory count for `steps` control steps
## (or until the attempt ends) and reports the planning time per step.
func _measure_planning(args: ExperimentArgs) -> void:
	for count in args.trajectories:
		_bike.trajectories = count
		_bike.planner_seed = args.base_seed
		_bike.reset_to(_level.spawn_points()[0].spawn_transform())
		_level.begin_attempt(_bike, args.base_seed)
		var samples: Array[float] = []
		for step in args.steps:
			_bike.max_speed_kmh = args.speed
			_bike.set_drive(BikeDriver.AUTO_THROTTLE, 0.0)
			_bike.set_turn(0.0)
			_bike.advance(1)
			# The first plans build the rollout worlds; they are not what a rider waits for.
			if step >= 5 and _bike.get_planning_ms() > 0.0:
				samples.append(_bike.get_planning_ms())
			if _level.judge(_bike, SettingsSchema.control_period()) != Level.RIDING:
				break
		samples.sort()
		var timing := {
			"controller": args.controller,
			"trajectories": count,
			"threads": args.threads,
			"samples": samples.size(),
			"mean_ms": _mean(samples),
			"median_ms": samples[samples.size() / 2] if not samples.is_empty() else 0.0,
			"p95_ms": samples[int(samples.size() * 0.95)] if not samples.is_empty() else 0.0,
		}
		print("TIMING ", JSON.stringify(timing))


static func _mean(values: Array[float]) -> float:
	var total := 0.0
	for value in values:
		total += value
	return total / maxi(values.size(), 1)
