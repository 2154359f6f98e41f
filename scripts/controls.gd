extends Node
## The player's controls (autoload `Controls`): the keyboard and pad bindings of every
## action a player may change, read from `user://controls.cfg` over the project's own
## (project.godot's input map) and saved there at once, atomically (ConfigStore). A file
## that cannot be read is kept aside as `controls.cfg.broken`, with a message, and the
## defaults are used; a binding to a key no keyboard has, or to an action that no longer
## exists, is dropped with a warning. One place names every action for people: the
## Controls screen, the pause menu's list and the README's table read it.

## A binding changed, or every one was read again.
signal changed

const PLAYER_CONTROLS := "user://controls.cfg"
const SECTION := "bindings"
## The two kinds of binding each action has, as the Controls screen's columns.
const KEYBOARD := "keyboard"
const PAD := "pad"
## Every action a player may rebind, in the order the Controls screen lists them, with
## what it does.
const ACTIONS := {
	&"throttle": "throttle (analog)",
	&"brake": "brake (analog; both wheels)",
	&"steer_left": "turn left (sets the lean)",
	&"steer_right": "turn right (sets the lean)",
	&"rider_forward": "rider's weight forward",
	&"rider_back": "rider's weight back",
	&"rider_left": "rider's weight left",
	&"rider_right": "rider's weight right",
	&"camera_up": "orbit the camera up",
	&"camera_down": "orbit the camera down",
	&"camera_left": "orbit the camera left",
	&"camera_right": "orbit the camera right",
	&"cycle_camera": "camera: chase, low side, helmet",
	&"pause": "pause menu",
	&"reset_bike": "respawn at the spawn point (in a lesson: try again)",
	&"rewind": "rewind the ride a few seconds (again: further; not in a lesson)",
	&"lift_bike": "stand the bike up where it lies",
	&"previous_spawn": "previous spawn point",
	&"next_spawn": "next spawn point",
	&"toggle_auto_accelerate": "auto-accelerate on / off",
	&"cycle_controller": "Lab: next controller",
	&"toggle_trajectories": "Lab: show / hide the lines ahead",
}
## Moves made of two actions at once, for the lists of controls.
const MOVES := [
	["wheelie: weight back with the throttle open", &"rider_back", &"throttle"],
	["stoppie: weight forward with the brake on", &"rider_forward", &"brake"],
	["in the air: nose up", &"rider_back", &""],
	["in the air: nose down", &"rider_forward", &""],
]
const BUTTON_NAMES := {
	JOY_BUTTON_A: "A",
	JOY_BUTTON_B: "B",
	JOY_BUTTON_X: "X",
	JOY_BUTTON_Y: "Y",
	JOY_BUTTON_BACK: "Back",
	JOY_BUTTON_GUIDE: "Guide",
	JOY_BUTTON_START: "Start",
	JOY_BUTTON_LEFT_STICK: "left stick click",
	JOY_BUTTON_RIGHT_STICK: "right stick click",
	JOY_BUTTON_LEFT_SHOULDER: "LB",
	JOY_BUTTON_RIGHT_SHOULDER: "RB",
	JOY_BUTTON_DPAD_UP: "d-pad up",
	JOY_BUTTON_DPAD_DOWN: "d-pad down",
	JOY_BUTTON_DPAD_LEFT: "d-pad left",
	JOY_BUTTON_DPAD_RIGHT: "d-pad right",
}
## Each stick axis's two directions (negative first), and the triggers.
const AXIS_NAMES := {
	JOY_AXIS_LEFT_X: ["left stick left", "left stick right"],
	JOY_AXIS_LEFT_Y: ["left stick up", "left stick down"],
	JOY_AXIS_RIGHT_X: ["right stick left", "right stick right"],
	JOY_AXIS_RIGHT_Y: ["right stick up", "right stick down"],
	JOY_AXIS_TRIGGER_LEFT: ["LT", "LT"],
	JOY_AXIS_TRIGGER_RIGHT: ["RT", "RT"],
}
const KEY_NAMES := {"Up": "↑", "Down": "↓", "Left": "←", "Right": "→", "Escape": "Esc"}

var controls_path := PLAYER_CONTROLS
## What was wrong with the file when it was last read (empty: nothing), for the menus.
var problem := ""


func _ready() -> void:
	reload()


## Every binding from the project's input map, then the player's file over it.
func reload() -> void:
	problem = ""
	InputMap.load_from_project_settings()
	var existed := FileAccess.file_exists(controls_path)
	var file := ConfigStore.load_or_empty(controls_path)
	if existed and not FileAccess.file_exists(controls_path):
		problem = "your controls file could not be read; it was kept as controls.cfg.broken"
	var saved := (
		file.get_section_keys(SECTION) if file.has_section(SECTION) else PackedStringArray()
	)
	for action: String in saved:
		_apply_saved(StringName(action), file.get_value(SECTION, action))
	changed.emit()


## The events of `action` of `kind` (KEYBOARD or PAD).
static func events_of(action: StringName, kind: String) -> Array[InputEvent]:
	var found: Array[InputEvent] = []
	for event in InputMap.action_get_events(action):
		if _kind_of(event) == kind:
			found.append(event)
	return found


## Binds `event` to `action` in place of its first binding of that kind, saves, and says
## what else changed: the action that had `event` takes `action`'s old binding (they swap),
## or loses it when there was none to give. Empty: nothing else changed.
func bind(action: StringName, event: InputEvent) -> String:
	if _has_event(action, event):
		return ""
	var kind := _kind_of(event)
	var old: Array[InputEvent] = events_of(action, kind)
	var previous: InputEvent = old[0] if not old.is_empty() else null
	var note := ""
	for other: StringName in ACTIONS:
		if other == action or not _has_event(other, event):
			continue
		_replace(other, event, previous)
		if previous != null:
			note = "%s was %s: %s now" % [event_text(event), ACTIONS[other], event_text(previous)]
		else:
			note = "%s was %s: it has none of its own now" % [event_text(event), ACTIONS[other]]
	if previous != null:
		_replace(action, previous, event)
	else:
		InputMap.action_add_event(action, event)
	save()
	changed.emit()
	return note


## Every binding back to the project's, the file rewritten so.
func reset_to_defaults() -> void:
	InputMap.load_from_project_settings()
	save()
	changed.emit()


## Writes every rebindable action's bindings to the player's file.
func save() -> void:
	var file := ConfigFile.new()
	for action: StringName in ACTIONS:
		var saved := PackedStringArray()
		for event in InputMap.action_get_events(action):
			if not _kind_of(event).is_empty():
				saved.append(event_key(event))
		file.set_value(SECTION, action, saved)
	ConfigStore.save(file, controls_path)


## How `action`'s bindings of `kind` read ("W, ↑"; "–" for none).
static func binding_text(action: StringName, kind: String) -> String:
	var names := PackedStringArray()
	for event in events_of(action, kind):
		names.append(event_text(event))
	return ", ".join(names) if not names.is_empty() else "–"


## How a prompt names `action` as it is bound now, the pad's first binding then the
## keyboard's: "B / R" (one of them alone when the other has none).
static func prompt(action: StringName) -> String:
	var names := PackedStringArray()
	for kind: String in [PAD, KEYBOARD]:
		var events := events_of(action, kind)
		if not events.is_empty():
			names.append(event_text(events[0]))
	return " / ".join(names) if not names.is_empty() else "(unbound)"


## The controls as the pause menu lists them, a line each: "RT / W, ↑   throttle
## (analog)", then the moves made of two.
static func summary() -> String:
	var lines := PackedStringArray(["Gamepad / keyboard"])
	for action: StringName in ACTIONS:
		lines.append(
			(
				"%s / %s   %s"
				% [binding_text(action, PAD), binding_text(action, KEYBOARD), ACTIONS[action]]
			)
		)
	for move: Array in MOVES:
		lines.append("%s   %s" % [move_text(move, PAD), move[0]])
	return "\n".join(lines)


## A move's controls of `kind` ("K + W"): its actions' first bindings, joined.
static func move_text(move: Array, kind: String) -> String:
	var parts := PackedStringArray()
	for action: StringName in move.slice(1):
		if not action.is_empty():
			var bound := events_of(action, kind)
			parts.append(event_text(bound[0]) if not bound.is_empty() else "–")
	return " + ".join(parts)


## The README's table of controls (action, keyboard, gamepad), from the bindings in use:
## tests/game/test_controls.gd holds the README's equal to the project's defaults.
static func markdown_table() -> String:
	var lines := PackedStringArray(["| action | keyboard | gamepad |", "|---|---|---|"])
	for action: StringName in ACTIONS:
		lines.append(
			(
				"| %s | %s | %s |"
				% [ACTIONS[action], binding_text(action, KEYBOARD), binding_text(action, PAD)]
			)
		)
	for move: Array in MOVES:
		lines.append(
			"| %s | %s | %s |" % [move[0], move_text(move, KEYBOARD), move_text(move, PAD)]
		)
	return "\n".join(lines)


## `event` as a player reads it: "W", "↑", "numpad 8", "RT", "left stick left", "A".
static func event_text(event: InputEvent) -> String:
	if event is InputEventKey:
		var name := OS.get_keycode_string(_keycode(event as InputEventKey))
		if name.begins_with("Kp "):
			return "numpad " + name.trim_prefix("Kp ")
		return KEY_NAMES.get(name, name)
	if event is InputEventJoypadButton:
		return BUTTON_NAMES.get(
			(event as InputEventJoypadButton).button_index,
			"button %d" % (event as InputEventJoypadButton).button_index
		)
	if event is InputEventJoypadMotion:
		var motion := event as InputEventJoypadMotion
		var names: Array = AXIS_NAMES.get(
			motion.axis, ["axis %d −" % motion.axis, "axis %d +" % motion.axis]
		)
		return names[1 if motion.axis_value > 0.0 else 0]
	return event.as_text()


## `event` as the file keeps it: "key:W", "button:0", "axis:5:+".
static func event_key(event: InputEvent) -> String:
	if event is InputEventKey:
		return "key:" + OS.get_keycode_string(_keycode(event as InputEventKey))
	if event is InputEventJoypadButton:
		return "button:%d" % (event as InputEventJoypadButton).button_index
	var motion := event as InputEventJoypadMotion
	return "axis:%d:%s" % [motion.axis, "+" if motion.axis_value > 0.0 else "-"]


## The event a file's `text` names, or null when it names none ("key:NoSuchKey").
static func parse_event(text: String) -> InputEvent:
	var parts := text.split(":")
	if parts.size() == 2 and parts[0] == "key":
		var code := OS.find_keycode_from_string(parts[1])
		if code == KEY_NONE:
			return null
		var key := InputEventKey.new()
		key.physical_keycode = code
		return key
	if parts.size() == 2 and parts[0] == "button" and parts[1].is_valid_int():
		var button := InputEventJoypadButton.new()
		button.button_index = int(parts[1]) as JoyButton
		button.pressed = true
		return button
	if (
		parts.size() == 3
		and parts[0] == "axis"
		and parts[1].is_valid_int()
		and parts[2] in ["+", "-"]
	):
		var motion := InputEventJoypadMotion.new()
		motion.axis = int(parts[1]) as JoyAxis
		motion.axis_value = 1.0 if parts[2] == "+" else -1.0
		return motion
	return null


## KEYBOARD or PAD for the events the Controls screen rebinds; empty for others.
static func _kind_of(event: InputEvent) -> String:
	if event is InputEventKey:
		return KEYBOARD
	if event is InputEventJoypadButton or event is InputEventJoypadMotion:
		return PAD
	return ""


static func _keycode(key: InputEventKey) -> Key:
	return key.physical_keycode if key.physical_keycode != KEY_NONE else key.keycode


func _apply_saved(action: StringName, saved: Variant) -> void:
	if not ACTIONS.has(action):
		push_warning("controls: no action %s to bind; its bindings are dropped" % action)
		return
	if not saved is PackedStringArray and not saved is Array:
		push_warning("controls: %s holds %s, not bindings; the defaults are kept" % [action, saved])
		return
	InputMap.action_erase_events(action)
	for text: Variant in saved:
		var event := parse_event(str(text))
		if event == null:
			push_warning("controls: %s cannot be bound to %s: dropped" % [action, text])
			continue
		InputMap.action_add_event(action, event)


func _has_event(action: StringName, event: InputEvent) -> bool:
	for bound in InputMap.action_get_events(action):
		if _kind_of(bound) == _kind_of(event) and event_key(bound) == event_key(event):
			return true
	return false


## `action`'s bindings with the one like `old` replaced by `new` in its place (left out
## when `new` is null), the order kept: the first binding stays the first.
func _replace(action: StringName, old: InputEvent, new: InputEvent) -> void:
	var events := InputMap.action_get_events(action)
	InputMap.action_erase_events(action)
	for bound in events:
		if _kind_of(bound) == _kind_of(old) and event_key(bound) == event_key(old):
			if new != null:
				InputMap.action_add_event(action, new)
		else:
			InputMap.action_add_event(action, bound)
