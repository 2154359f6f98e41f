class_name PauseMenu
extends CanvasLayer
## The pause menu (Back / Esc): stops the simulation and offers resume, the trajectory
## view, physical or visual model, motor force, top speed, volume (all and the engine's),
## controller, trajectory count, auto-accelerate speed, the replay of the last run,
## restart and quit; lists the controls. Every change is saved in the settings at once.
## Works with a gamepad alone (d-pad/stick to move, A to choose, B or Back to resume).

## The player asked to start the attempt again, to watch the last run, or to leave for
## the start menu.
signal restart_requested
signal replay_requested
signal quit_requested

const CONTROLS := """Gamepad / keyboard
RT / W, ↑        throttle
LT / S, ↓        brake
Left stick / A D, ← →   turn (sets the lean)
Right stick / I J K L   rider's weight (fore, aft, sides)
  back + throttle        wheelie
  in the air             nose up (back) or down (forward)
  forward + brake        stoppie
D-pad / numpad 8 4 6 2, right mouse drag   camera
Left stick click / Tab   camera: chase, low side, helmet
Start / C        cycle controller
Back / Esc, P    pause
B / R            respawn
A / T            lift the bike upright
LB RB / Q E      previous / next spawn point
X / F            auto-accelerate
Y / V            show trajectories"""

var _syncing := false

@onready var _resume: Button = %Resume
@onready var _trajectories_shown: CheckButton = %ShowTrajectories
@onready var _physical: CheckButton = %PhysicalModel
@onready var _motor_force: HSlider = %MotorForce
@onready var _motor_force_label: Label = %MotorForceLabel
@onready var _max_speed: HSlider = %MaxSpeed
@onready var _max_speed_label: Label = %MaxSpeedLabel
@onready var _master_volume: HSlider = %MasterVolume
@onready var _master_volume_label: Label = %MasterVolumeLabel
@onready var _engine_volume: HSlider = %EngineVolume
@onready var _engine_volume_label: Label = %EngineVolumeLabel
@onready var _controller: OptionButton = %Controller
@onready var _trajectory_count: OptionButton = %TrajectoryCount
@onready var _auto_speed: OptionButton = %AutoSpeed
@onready var _controls: Label = %Controls


func _ready() -> void:
	visible = false
	_controls.text = CONTROLS
	for name in NativeModule.controller_names():
		_controller.add_item(NativeModule.controller_label(name))
	for label in Settings.trajectory_labels():
		_trajectory_count.add_item(label)
	for speed in Settings.AUTO_SPEEDS:
		_auto_speed.add_item("%d km/h" % speed)
	_resume.pressed.connect(close)
	%Restart.pressed.connect(_on_restart)
	%WatchReplay.pressed.connect(_on_replay)
	%Quit.pressed.connect(_on_quit)
	_trajectories_shown.toggled.connect(_save.bind(&"show_trajectories"))
	_physical.toggled.connect(_save.bind(&"physical_model"))
	_motor_force.value_changed.connect(_save.bind(&"motor_force"))
	_max_speed.value_changed.connect(_save.bind(&"max_speed_kmh"))
	_master_volume.value_changed.connect(_save.bind(&"master_volume"))
	_engine_volume.value_changed.connect(_save.bind(&"engine_volume"))
	_controller.item_selected.connect(
		func(i: int) -> void: _save(NativeModule.controller_names()[i], &"controller")
	)
	_trajectory_count.item_selected.connect(
		func(i: int) -> void:
			if not _syncing:
				Settings.choose_trajectories(i)
	)
	_auto_speed.item_selected.connect(
		func(i: int) -> void: _save(Settings.AUTO_SPEEDS[i], &"auto_speed_kmh")
	)


## Pauses the game and shows the menu with the current settings.
func open() -> void:
	_sync()
	visible = true
	get_tree().paused = true
	_resume.grab_focus()


## Hides the menu and resumes the game.
func close() -> void:
	visible = false
	get_tree().paused = false


func _unhandled_input(event: InputEvent) -> void:
	if visible and (event.is_action_pressed(&"pause") or event.is_action_pressed(&"ui_cancel")):
		get_viewport().set_input_as_handled()
		close()


func _sync() -> void:
	_syncing = true
	_trajectories_shown.button_pressed = Settings.get_value(&"show_trajectories")
	_physical.button_pressed = Settings.get_value(&"physical_model")
	_motor_force.value = Settings.get_value(&"motor_force")
	_max_speed.value = Settings.get_value(&"max_speed_kmh")
	_master_volume.value = Settings.get_value(&"master_volume")
	_engine_volume.value = Settings.get_value(&"engine_volume")
	_controller.selected = maxi(
		NativeModule.controller_names().find(Settings.get_value(&"controller")), 0
	)
	_trajectory_count.selected = Settings.trajectory_choice()
	_auto_speed.selected = maxi(Settings.AUTO_SPEEDS.find(Settings.get_value(&"auto_speed_kmh")), 0)
	_update_labels()
	_syncing = false


func _save(value: Variant, key: StringName) -> void:
	if _syncing:
		return
	Settings.set_value(key, value)
	_update_labels()


func _update_labels() -> void:
	_motor_force_label.text = "Motor force: %d %%" % roundi(_motor_force.value * 100.0)
	_max_speed_label.text = "Top speed: %d km/h" % roundi(_max_speed.value)
	_master_volume_label.text = "Volume: %d %%" % roundi(_master_volume.value * 100.0)
	_engine_volume_label.text = "Engine: %d %%" % roundi(_engine_volume.value * 100.0)


func _on_restart() -> void:
	close()
	restart_requested.emit()


func _on_replay() -> void:
	visible = false
	replay_requested.emit()


func _on_quit() -> void:
	close()
	quit_requested.emit()
