class_name ExperimentArgs
extends RefCounted
## The experiment worker's command line, checked: every value in range, or `error` says
## which one is wrong.

var speed := 15.0
var controller := "combined"
var physics := "classic"
## The bike file ridden (a res:// path); empty: the reference bike.
var bike := ""
## The learned controllers' network (a res:// model file); empty: the bike's own.
var model := ""
var trajectories: Array[int] = [5]
var base_seed := 1000
var first := 0
var count := 1
var threads := 0
var timing := false
var platform_only := false
var warm_up := ""
var steps := 150
## Planner settings other than their defaults (`--set=NAME=VALUE`, repeatable), by name.
var settings := {}
var error := ""


static func parse(arguments: PackedStringArray) -> ExperimentArgs:
	var args := ExperimentArgs.new()
	for argument in arguments:
		var parts := argument.trim_prefix("--").split("=", true, 1)
		var value := parts[1] if parts.size() == 2 else ""
		match parts[0]:
			"speed":
				args.speed = _number(args, "speed", value, 1.0, 90.0)
			"controller":
				if not BikeSimulation.controller_names().has(value):
					args._fail("--controller must be one of %s, not '%s'" % [_choices(), value])
				args.controller = value
			"physics":
				if not BikeSimulation.physics_names().has(value):
					args._fail(
						(
							"--physics must be one of %s, not '%s'"
							% [", ".join(BikeSimulation.physics_names()), value]
						)
					)
				args.physics = value
			"bike":
				if not ResourceLoader.exists(value, "BikeDescription"):
					args._fail("--bike must name a bike file, not '%s'" % value)
				args.bike = value
			"model":
				if not FileAccess.file_exists(value) or not value.ends_with(".safetensors"):
					args._fail("--model must name a .safetensors model file, not '%s'" % value)
				args.model = value
			"trajectories":
				args.trajectories.clear()
				var limits := BikeSimulation.trajectory_limits()
				for item in value.split(","):
					args.trajectories.append(
						int(_number(args, "trajectories", item, limits.x, limits.y))
					)
			"seed":
				args.base_seed = int(_number(args, "seed", value, 0, 2_000_000_000))
			"first":
				args.first = int(_number(args, "first", value, 0, 10_000_000))
			"count":
				args.count = int(_number(args, "count", value, 1, 10_000_000))
			"threads":
				args.threads = int(_number(args, "threads", value, 0, 64))
			"steps":
				args.steps = int(_number(args, "steps", value, 1, 100_000))
			"timing":
				args.timing = true
			"platform":
				args.platform_only = true
			"set":
				var assignment := SettingsSchema.planner_assignment(value)
				if assignment.has("error"):
					args._fail("--set=%s: %s" % [value, assignment.error])
				else:
					args.settings[assignment.name] = assignment.value
			"warm-up":
				if not BikeSimulation.controller_names().has(value):
					args._fail("--warm-up must be one of %s, not '%s'" % [_choices(), value])
				args.warm_up = value
			_:
				args._fail("unknown argument '%s'" % argument)
	return args


static func _number(
	args: ExperimentArgs, name: String, text: String, low: float, high: float
) -> float:
	if not text.is_valid_float():
		args._fail("--%s needs a number, not '%s'" % [name, text])
		return low
	var value := text.to_float()
	if not (value >= low and value <= high):
		args._fail("--%s must be within %s–%s, not %s" % [name, low, high, text])
		return low
	return value


static func _choices() -> String:
	return ", ".join(BikeSimulation.controller_names())


func _fail(message: String) -> void:
	# The first problem is the one to fix first.
	if error.is_empty():
		error = message
