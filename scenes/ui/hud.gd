class_name Hud
extends CanvasLayer
## The riding HUD: lean dial (wanted vs actual lean), the rider's weight (asked vs
## actual), speed, the level's timer line and attempt tally, banners for what just
## happened, the split against a ghost at each checkpoint (a sign and an arrow as well as
## a colour), and in a lesson the player's hands on the pad. With `telemetry` on, the
## overlay a researcher reads: controller with its trajectory count (and whether the game
## picks it), planning time, late plans a second, the planner's own numbers about its plan
## (C-PBP's resamplings, MPPI's effective samples, …) and the frame rate. Containers lay it
## out, so a longer text pushes its neighbour rather than running into it
## (tests/scenes/test_hud_layout.gd).

## Seconds a banner stays before fading.
const BANNER_SECONDS := 3.0
const AHEAD_COLOUR := Color(0.4, 1.0, 0.45)
const BEHIND_COLOUR := Color(1.0, 0.35, 0.3)

## The planner telemetry overlay (a setting, the Lab's).
var telemetry := false:
	set(value):
		telemetry = value
		if is_node_ready():
			_telemetry.visible = value

var _game: Game
var _banner_left := 0.0
var _split_left := 0.0
## Late plans counted at the last whole second, and how many came in that second.
var _late_counted := 0
var _late_last_second := 0
var _late_clock := 0.0

@onready var _dial: LeanDial = %LeanDial
@onready var _rider: RiderPad = %RiderPad
@onready var _speed: Label = %Speed
@onready var _lean: Label = %Lean
@onready var _controller: Label = %Controller
@onready var _performance: Label = %Performance
@onready var _status: Label = %Status
@onready var _banner: Label = %Banner
@onready var _split: Label = %Split
@onready var _hint: Label = %Hint
@onready var _telemetry: Control = %Telemetry
@onready var _inputs: InputDisplay = %Inputs


func _ready() -> void:
	_telemetry.visible = telemetry


## Starts showing `game`'s bike and level.
func bind(game: Game) -> void:
	_game = game


## Shows `text` as a banner for a few seconds.
func announce(text: String) -> void:
	_banner.text = text
	_banner.modulate.a = 1.0
	_banner_left = BANNER_SECONDS


## Shows the player's hands on the pad (a lesson's inputs) under the hint, or not.
func show_inputs(shown: bool) -> void:
	_inputs.visible = shown


## Shows for a few seconds how far behind the ghost (seconds; negative: ahead) the rider
## crossed `checkpoint`: a sign and an arrow say it as well as the colour (green ahead, red
## behind, as in Trials).
func show_split(checkpoint: int, behind: float) -> void:
	_split.text = split_line(checkpoint, behind)
	_split.add_theme_color_override(&"font_color", BEHIND_COLOUR if behind > 0.0 else AHEAD_COLOUR)
	_split.modulate.a = 1.0
	_split_left = BANNER_SECONDS


## The split shown now (empty once it faded).
func split_text() -> String:
	return _split.text if _split_left > 0.0 else ""


## "checkpoint 2   ↑ −0.42 s ahead" or "checkpoint 2   ↓ +0.42 s behind".
static func split_line(checkpoint: int, behind: float) -> String:
	var ahead := behind <= 0.0
	return (
		"checkpoint %d   %s %s%.2f s %s"
		% [
			checkpoint,
			"↑" if ahead else "↓",
			"−" if ahead else "+",
			absf(behind),
			"ahead" if ahead else "behind"
		]
	)


func _process(delta: float) -> void:
	_banner_left -= delta
	_banner.modulate.a = clampf(_banner_left, 0.0, 1.0)
	_split_left -= delta
	_split.modulate.a = clampf(_split_left, 0.0, 1.0)
	if _game == null or _game.bike == null or not _game.bike.is_running():
		return
	var bike := _game.bike
	_dial.desired = bike.get_desired_lean()
	_dial.current = bike.get_lean()
	_rider.asked = bike.get_rider_position_asked()
	_rider.actual = bike.get_rider_position()
	_speed.text = "%d km/h" % roundi(absf(bike.get_speed()) * 3.6)
	_lean.text = (
		"lean %+.0f°   wanted %+.0f°"
		% [rad_to_deg(bike.get_lean()), rad_to_deg(bike.get_desired_lean())]
	)
	if _telemetry.visible:
		_show_telemetry(bike, delta)
	if _inputs.visible:
		var hands := _game.driver()
		_inputs.throttle = hands.throttle
		_inputs.brake = hands.brake
		_inputs.turn = hands.turn
		_inputs.rider = hands.rider
	var status := "%s   ·   %s" % [_game.level.title, _game.level.status_line()]
	var run := _game.challenge_run
	if run != null and run.judge != null:
		var progress := run.progress_text()
		status = (
			"%s   ·   %s%s"
			% [
				run.challenge.title,
				progress + "   ·   " if not progress.is_empty() else "",
				Level.format_time(run.judge.elapsed)
			]
		)
	elif _game.is_automatic():
		status += "   ·   %d/%d reached the goal" % [_game.successes, _game.attempts]
	else:
		status += "   ·   falls %d" % _game.falls
	# The bike on a line of its own below: the line above is full on a track.
	_status.text = "%s\n%s" % [status, _game.bike_name()]
	_hint.text = _hint_text(bike)


## The overlay's lines: the controller and its planning, then the frame rate and the
## planner's own numbers.
func _show_telemetry(bike: BikeSimulation, delta: float) -> void:
	var controller := _game.controller_name()
	var failure := bike.get_controller_failure()
	if not failure.is_empty():
		# Its whole story is the banner's (the game announces a failure to every player).
		controller += "  ·  failed: arcade steers"
	elif BikeSimulation.controller_plans(bike.controller):
		controller += (
			"  ·  %s%d trajectories  ·  planning %.1f ms  ·  %d late/s"
			% [
				"auto: " if bike.auto_trajectories else "",
				bike.get_trajectories_in_use(),
				bike.get_planning_ms(),
				_late_per_second(bike, delta),
			]
		)
	_controller.text = controller
	_performance.text = "%d fps" % Engine.get_frames_per_second()
	if failure.is_empty() and BikeSimulation.controller_plans(bike.controller):
		_performance.text += "  ·  " + _horizon_text(bike)
		_performance.text += _diagnostics_text(bike.get_plan_diagnostics())


## How far the plans look: "1.2 s ahead", or "0.6 s ahead + learned cost-to-go" when the
## network costs the rest of the horizon (the automatic N then fits more trajectories in a
## frame), or "1.2 s ahead (no cost-to-go for this bike)" when the player asked for one
## the bike does not have.
static func _horizon_text(bike: BikeSimulation) -> String:
	var text := "%.1f s ahead" % bike.get_planned_horizon()
	if bike.is_horizon_ended_by_value():
		text += " + learned cost-to-go"
	elif Settings.get_value(&"terminal_value") and not bike.terminal_value:
		# The game asks the bike only when it has a cost-to-go file (`Game`), so the
		# switch on and the bike not asked means it has none: no file check each frame.
		text += " (no cost-to-go for this bike)"
	return text


## A planner's diagnostics as the HUD shows them after the frame rate: "  ·  resamples 3"
## and the like, by the names the planner gives them.
static func _diagnostics_text(diagnostics: Dictionary) -> String:
	var text := ""
	for name: String in diagnostics:
		var value: float = diagnostics[name]
		var shown := "%d" % value if value == roundf(value) else "%.2f" % value
		text += "  ·  %s %s" % [name, shown]
	return text


## Plans that came too late in the last whole second (the count restarts with the ride).
func _late_per_second(bike: BikeSimulation, delta: float) -> int:
	_late_clock += delta
	if _late_clock >= 1.0:
		var count := bike.get_late_plan_count()
		_late_last_second = maxi(count - _late_counted, 0)
		_late_counted = count
		_late_clock = 0.0
	return _late_last_second


## What a fallen rider's player can do, as the buttons are bound now.
static func fallen_hint() -> String:
	return (
		"%s respawn   ·   %s lift the bike   ·   %s rewind"
		% [
			Controls.prompt(&"reset_bike"),
			Controls.prompt(&"lift_bike"),
			Controls.prompt(&"rewind")
		]
	)


func _hint_text(bike: BikeSimulation) -> String:
	if bike.is_waiting_for_throttle():
		return "%s to ride" % Controls.prompt(&"throttle")
	if bike.is_crashed():
		return fallen_hint()
	return "%s: pause and controls" % Controls.prompt(&"pause")
