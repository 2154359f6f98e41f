extends Control
## Title screen: the game's name and what native module is running underneath; Enter
## rides the sandbox, Esc quits.

## The player asked to ride (Enter).
signal ride_requested

const SANDBOX := "res://scenes/sandbox.tscn"

@onready var _version_label: Label = %VersionLabel
@onready var _status_label: Label = %StatusLabel


func _ready() -> void:
	if OS.get_cmdline_user_args().has("--native-info"):
		_print_native_info_and_quit()
		return
	_version_label.text = NativeModule.describe()
	# Only the title screen that is the running scene navigates; embedded ones just report.
	if get_tree().current_scene == self:
		ride_requested.connect(_go_to_sandbox)
	if not NativeModule.is_loaded():
		_status_label.text = "The native simulation is missing; the game cannot start."
		_status_label.add_theme_color_override(&"font_color", Color(1.0, 0.45, 0.4))


func _unhandled_input(event: InputEvent) -> void:
	if event.is_action_pressed(&"ui_accept") and NativeModule.is_loaded():
		ride_requested.emit()
	elif event.is_action_pressed(&"ui_cancel"):
		get_tree().quit()


## `--native-info`: print what native module is loaded and exit; non-zero when it is missing
## or unsuitable. Used to check an exported build and for bug reports.
func _print_native_info_and_quit() -> void:
	print(NativeModule.describe())
	# Quitting before the first frame has run makes the release template's containers
	# report spurious signal errors while they are torn down.
	await get_tree().process_frame
	get_tree().quit(0 if NativeModule.ode_is_suitable() else 1)


func _go_to_sandbox() -> void:
	get_tree().change_scene_to_file(SANDBOX)
