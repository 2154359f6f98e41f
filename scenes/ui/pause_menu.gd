class_name PauseMenu
extends CanvasLayer
## The pause menu (Back / Esc): stops the simulation, says which bike is ridden (the start
## menu chooses it) and offers resume, a rewind, the replay of the last run, every player
## setting the schema puts in a player's menu group (`SettingControls`), the controls
## (listed, and rebound on the Controls screen, `ControlsMenu`), the Lab (the research
## tools, `LabPanel`), restart and quit. Every change is saved in the settings at once.
## Works with a gamepad alone (d-pad/stick to move, A to choose, B or Back to resume).

## The player asked to start the attempt again, to watch the last run, or to leave for
## the start menu.
signal restart_requested
signal rewind_requested
signal replay_requested
signal quit_requested
## The menu opened over the game, or closed (the game hides its HUD behind it meanwhile).
signal opened
signal closed

var _lab: LabPanel
var _controls_menu: ControlsMenu

@onready var _resume: Button = %Resume
@onready var _settings: SettingControls = %Settings
@onready var _controls: Label = %Controls


func _ready() -> void:
	visible = false
	_list_controls()
	Controls.changed.connect(_list_controls)
	_controls_menu = ControlsMenu.new()
	_controls_menu.name = "ControlsMenu"
	add_child(_controls_menu)
	_controls_menu.closed.connect(_on_sub_menu_closed.bind(%EditControls))
	%EditControls.pressed.connect(open_controls)
	_lab = LabPanel.new()
	_lab.name = "Lab"
	add_child(_lab)
	_lab.closed.connect(_on_sub_menu_closed.bind(%OpenLab))
	%OpenLab.pressed.connect(open_lab)
	_resume.pressed.connect(close)
	%Restart.pressed.connect(_on_restart)
	%Rewind.pressed.connect(_on_rewind)
	%WatchReplay.pressed.connect(_on_replay)
	%Quit.pressed.connect(_on_quit)


## Shows which bike is ridden: `text` names it and its main figures.
func show_bike(text: String) -> void:
	%BikeSummary.text = text


## Offers a rewind of `seconds`, or says why there is none (`refusal` not empty).
func offer_rewind(seconds: float, refusal: String) -> void:
	var rewind: Button = %Rewind
	rewind.disabled = not refusal.is_empty()
	rewind.text = "Rewind %d s" % roundi(seconds) if refusal.is_empty() else "No rewind: " + refusal
	rewind.focus_mode = Control.FOCUS_NONE if rewind.disabled else Control.FOCUS_ALL


## The menu's control of setting `key`, the Lab's for a research tool (null if neither
## has one).
func control_of(key: StringName) -> Control:
	var control := _settings.control_of(key)
	return control if control != null else _lab.control_of(key)


## Lists what each assist level does, then the controls as they are bound now.
func _list_controls() -> void:
	_controls.text = "Assist levels\n%s\n\n%s" % [Assists.summary(), Controls.summary()]


## Shows the Controls screen over the menu.
func open_controls() -> void:
	$Panel.visible = false
	_controls_menu.open()


## Shows the Lab over the menu.
func open_lab() -> void:
	$Panel.visible = false
	_lab.open()


## Pauses the game and shows the menu with the current settings.
func open() -> void:
	_sync()
	visible = true
	get_tree().paused = true
	_resume.grab_focus()
	opened.emit()


## Hides the menu and resumes the game.
func close() -> void:
	visible = false
	get_tree().paused = false
	closed.emit()


func _unhandled_input(event: InputEvent) -> void:
	if _lab.visible or _controls_menu.visible:
		return
	if visible and (event.is_action_pressed(&"pause") or event.is_action_pressed(&"ui_cancel")):
		get_viewport().set_input_as_handled()
		close()


func _sync() -> void:
	_settings.sync()


func _on_sub_menu_closed(opener: Button) -> void:
	$Panel.visible = true
	opener.grab_focus()


func _on_restart() -> void:
	close()
	restart_requested.emit()


func _on_rewind() -> void:
	close()
	rewind_requested.emit()


func _on_replay() -> void:
	visible = false
	closed.emit()
	replay_requested.emit()


func _on_quit() -> void:
	close()
	quit_requested.emit()
