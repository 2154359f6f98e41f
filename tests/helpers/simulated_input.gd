class_name SimulatedInput
extends RefCounted
## Test helper: input as a player makes it, through the same event path as real devices.


## Presses and releases input action `action`, then waits two physics ticks.
static func tap_action(action: StringName) -> void:
	for pressed: bool in [true, false]:
		var event := InputEventAction.new()
		event.action = action
		event.pressed = pressed
		Input.parse_input_event(event)
	for _i in 2:
		await _tree().physics_frame


## Presses and releases gamepad button `button` (menus navigate with it even while the
## tree is paused), waiting two frames after each.
static func press_joypad_button(button: JoyButton) -> void:
	for pressed: bool in [true, false]:
		var event := InputEventJoypadButton.new()
		event.button_index = button
		event.pressed = pressed
		Input.parse_input_event(event)
		for _i in 2:
			await _tree().process_frame


## Moves gamepad axis `axis` to `value` (−1 to 1) through the device event path; the
## stick stays there until moved again.
static func move_joypad_axis(axis: JoyAxis, value: float) -> void:
	var event := InputEventJoypadMotion.new()
	event.axis = axis
	event.axis_value = value
	Input.parse_input_event(event)


static func _tree() -> SceneTree:
	return Engine.get_main_loop() as SceneTree
