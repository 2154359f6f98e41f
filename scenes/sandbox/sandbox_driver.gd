class_name SandboxDriver
extends Node
## Drives a BikeSimulation from the input actions: the triggers (W/S) drive and brake,
## the stick (A/D) asks for a turn, which the bike's controller turns into a lean (with
## the bike's own counter-steering); R puts the bike back at the start, T stands it up
## where it lies; C / Start cycles the controller (optimizer → combined → arcade); V / Y
## shows or hides the optimizer's trajectories.

## BikeSimulation.controller values, in the order the thesis cycles them.
const CONTROLLER_CYCLE: Array[int] = [2, 3, 0]

## The BikeSimulation to drive.
@export var bike_path: NodePath

## Steering rate (rad/s) at full stick when the bike has no controller (manual mode).
@export var steer_speed := 0.6

var _bike: Node
var _spawn: Transform3D


func _ready() -> void:
	_bike = get_node_or_null(bike_path)
	if _bike == null:
		push_error("SandboxDriver: no bike at %s" % bike_path)
		set_physics_process(false)
		return
	_spawn = (_bike as Node3D).global_transform


func _physics_process(_delta: float) -> void:
	_bike.call(
		&"set_drive", Input.get_action_strength(&"throttle"), Input.get_action_strength(&"brake")
	)
	var stick := Input.get_axis(&"steer_left", &"steer_right")
	_bike.call(&"set_turn", stick)
	_bike.call(&"set_steer_rate", -stick * steer_speed)


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"reset_bike"):
		_bike.call(&"reset_to", _spawn)
	elif event.is_action_pressed(&"lift_bike"):
		_bike.call(&"lift_upright")
	elif event.is_action_pressed(&"toggle_trajectories"):
		var view := _bike.get_node_or_null(^"TrajectoryView") as Node3D
		if view != null:
			view.visible = not view.visible
	elif event.is_action_pressed(&"cycle_controller"):
		var current := CONTROLLER_CYCLE.find(int(_bike.get(&"controller")))
		_bike.set(&"controller", CONTROLLER_CYCLE[(current + 1) % CONTROLLER_CYCLE.size()])
