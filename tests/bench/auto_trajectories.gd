extends Node
## What the learned cost-to-go buys the game's automatic trajectory count (issue 59): the
## test level ridden by combined at the auto-accelerate speed, headless and in real time,
## in blocks taken in turn with the player's cost-to-go switch on and off (on, off, off,
## on, … so a drift of the machine's load falls on both alike). Each block's second half
## is measured, after the automatic N has settled on what this machine plans in time: the
## mean N in use and the mean planning time. Prints each pair and the paired ratio of N
## (on ÷ off) with its 95 % interval, and the same for the planning time.
## Run by tools/auto-trajectories.sh, in scratch settings.
##
## Arguments after `--`: `--bike=res://…tres` (default the game's default bike),
## `--pairs=N` (default 6), `--block=S` (seconds a block, default 20).

const GAME := preload("res://scenes/game/game.tscn")
const LEVEL := "res://scenes/levels/test_level/test_level.tscn"
## Student's t at 97.5 % by degrees of freedom (1–10), for the pairs' interval.
const T_975 := [12.71, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228]

var _game: Game
var _pairs := 6
var _block_s := 20.0
var _on_first := true
## The block under way: its index, whether the switch is on, its clock and sums.
var _block := 0
var _value_on := true
var _clock := 0.0
var _sum_n := 0.0
var _sum_ms := 0.0
var _samples := 0
## Each pair's measures: {true: [n, ms], false: [n, ms]}.
var _measured: Array[Dictionary] = []


func _ready() -> void:
	var bike_path := ""
	for argument: String in OS.get_cmdline_user_args():
		var parts := argument.trim_prefix("--").split("=", true, 1)
		match parts[0]:
			"bike":
				bike_path = parts[1]
			"pairs":
				_pairs = clampi(int(parts[1]), 2, T_975.size() + 1)
			"block":
				_block_s = maxf(float(parts[1]), 4.0)
	SettingsSandbox.enter()
	Settings.set_value(&"controller", "combined")
	Settings.set_value(&"auto_trajectories", true)
	Settings.set_value(&"auto_accelerate", true)
	Settings.set_value(&"auto_speed_kmh", 20)
	_game = GAME.instantiate() as Game
	_game.level_path = LEVEL
	_game.bike_path = bike_path
	add_child(_game)
	if not _game.bike.has_learned_cost_to_go():
		_finish("the bike %s has no learned cost-to-go to measure" % _game.bike_key, 1)
		return
	_start_block()


func _start_block() -> void:
	# Pairs alternate their order: on-off, off-on, …
	_value_on = (_block % 2 == 0) == ((_block / 2) % 2 == 0)
	Settings.set_value(&"terminal_value", _value_on)
	_clock = 0.0
	_sum_n = 0.0
	_sum_ms = 0.0
	_samples = 0


func _process(delta: float) -> void:
	if _game == null:
		return
	_clock += delta
	if _clock >= _block_s / 2.0:
		_sum_n += _game.bike.get_trajectories_in_use()
		_sum_ms += _game.bike.get_planning_ms()
		_samples += 1
	if _clock < _block_s:
		return
	var pair := _block / 2
	if _measured.size() <= pair:
		_measured.append({})
	_measured[pair][_value_on] = [_sum_n / maxi(_samples, 1), _sum_ms / maxi(_samples, 1)]
	if _measured[pair].size() == 2:
		var on: Array = _measured[pair][true]
		var off: Array = _measured[pair][false]
		print(
			(
				"auto trajectories pair %d: on N %.1f (%.1f ms), off N %.1f (%.1f ms)"
				% [pair + 1, on[0], on[1], off[0], off[1]]
			)
		)
	_block += 1
	if _block < 2 * _pairs:
		_start_block()
		return
	print(
		(
			"auto trajectories %s: N on ÷ off %s; planning time on ÷ off %s; %d of %d reached the goal"
			% [_game.bike_key, _ratio_text(0), _ratio_text(1), _game.successes, _game.attempts]
		)
	)
	_finish("", 0)


## The pairs' mean ratio of measure `index` (on ÷ off) with its 95 % t interval.
func _ratio_text(index: int) -> String:
	var ratios: Array[float] = []
	for pair: Dictionary in _measured:
		ratios.append(pair[true][index] / maxf(pair[false][index], 1e-9))
	var mean := 0.0
	for r in ratios:
		mean += r / ratios.size()
	var spread := 0.0
	for r in ratios:
		spread += (r - mean) * (r - mean) / (ratios.size() - 1)
	var half: float = T_975[ratios.size() - 2] * sqrt(spread / ratios.size())
	return "%.2f (%.2f–%.2f, %d pairs)" % [mean, mean - half, mean + half, ratios.size()]


func _finish(problem: String, code: int) -> void:
	if not problem.is_empty():
		push_error("auto trajectories: " + problem)
	SettingsSandbox.leave()
	get_tree().quit(code)
	_game = null
