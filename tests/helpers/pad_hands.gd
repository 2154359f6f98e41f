class_name PadHands
extends RefCounted
## Test helper: a gamepad's sticks and triggers. Holds an analog action at a strength by
## moving the pad axis the InputMap binds it to (so remapped controls are followed) through
## `Input.parse_input_event`, the path a real pad's events take; the action's deadzone is
## allowed for, so the strength the game reads is the one asked.


## Presses `actions[1]` for positive `value` and `actions[0]` for negative, with its size as
## the strength, letting go of the other (a stick's two directions, or two triggers).
static func press_axis(actions: Array[StringName], value: float) -> void:
	var pressed := actions[1] if value > 0.0 else actions[0]
	var released := actions[0] if value > 0.0 else actions[1]
	if _bound_axis(released).axis != _bound_axis(pressed).axis:
		hold(released, 0.0)
	hold(pressed, absf(value))


## Moves the axis `action` is bound to so that the action reads `strength` (0–1).
static func hold(action: StringName, strength: float) -> void:
	var bound := _bound_axis(action)
	var deadzone := InputMap.action_get_deadzone(action)
	var event := InputEventJoypadMotion.new()
	event.axis = bound.axis
	if strength > 0.0:
		var travel := deadzone + clampf(strength, 0.0, 1.0) * (1.0 - deadzone)
		event.axis_value = signf(bound.axis_value) * travel
	Input.parse_input_event(event)


## Lets every analog action of `actions` go.
static func release(actions: Array[StringName]) -> void:
	for action in actions:
		hold(action, 0.0)


## The pad axis event `action` is bound to (an error when it has none).
static func _bound_axis(action: StringName) -> InputEventJoypadMotion:
	for event in InputMap.action_get_events(action):
		if event is InputEventJoypadMotion:
			return event
	push_error("PadHands: %s is bound to no pad axis" % action)
	return InputEventJoypadMotion.new()
