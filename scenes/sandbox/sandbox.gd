extends Node3D
## The sandbox: flat ground, a ramp and bumps to try the bike on. Shows the controls and
## what the bike is doing; Esc goes back to the title screen.

const TITLE := "res://scenes/ui/title_screen.tscn"

@onready var _bike: Node = $Bike
@onready var _status: Label = %Status


func _ready() -> void:
	_bike.connect(&"crashed", _on_crashed)


func _process(_delta: float) -> void:
	if not _bike.call(&"is_running"):
		_status.text = "The simulation is not running (see the errors above)."
		return
	var speed: float = _bike.call(&"get_speed")
	var lean: float = _bike.call(&"get_lean")
	var wanted: float = _bike.call(&"get_desired_lean")
	var steer: float = _bike.call(&"get_steering_angle")
	var state := ""
	if _bike.call(&"is_crashed"):
		state = "CRASHED: R to restart, T to lift"
	elif _bike.call(&"is_waiting_for_throttle"):
		state = "press W / RT to ride"
	var numbers := [speed * 3.6, rad_to_deg(lean), rad_to_deg(wanted), rad_to_deg(steer), state]
	var controller := str(_bike.call(&"get_controller_name"))
	if controller in ["optimizer", "combined"]:
		var handover: Dictionary = _bike.call(&"get_handover_stats")
		controller += (
			" (%d trajectories, planned in %.1f ms, %d resamples, hand-over wait %.1f ms)"
			% [
				_bike.get(&"trajectories"),
				_bike.call(&"get_planning_ms"),
				_bike.call(&"get_resample_count"),
				handover.last_wait_ms,
			]
		)
	_status.text = (
		"%s\nspeed %5.1f km/h   lean %+5.1f° (wanted %+5.1f°)   steering %+5.1f°   %s"
		% ([controller] + numbers)
	)


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"ui_cancel"):
		get_tree().change_scene_to_file(TITLE)


func _on_crashed(cause: String) -> void:
	print("sandbox: crashed: %s" % cause)
