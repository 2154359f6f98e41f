class_name StepRate
extends RefCounted
## How fast a quantity of the ride falls (per second), measured between control steps:
## the simulation moves once a control step, not every frame, so a difference per frame
## alternates between nothing and twice the rate. Used for the deceleration tyre marks
## answer and the fall speed a landing rumbles by.

## Seconds between the last two steps measured.
var elapsed := 0.0

var _last_value := NAN
var _last_step := -1


## The rate `value` (read now from `bike`'s ride) fell at since the last control step
## measured, or NAN on the first step and while no step has passed.
func falling(bike: BikeSimulation, value: float) -> float:
	var step := bike.get_step_count()
	if step == _last_step:
		return NAN
	var rate := NAN
	if not is_nan(_last_value) and step > _last_step:
		elapsed = (step - _last_step) * bike.get_control_dt()
		rate = (_last_value - value) / elapsed
	_last_value = value
	_last_step = step
	return rate


## Forgets the last value: the next step measured starts afresh.
func reset() -> void:
	_last_value = NAN
