class_name TestRun
extends RefCounted
## One attempt at the test level, simulated as fast as the machine allows (headless tests
## and the experiment): the bike is put at the start, the bumps are laid out for the seed,
## and auto-accelerate rides it at the chosen speed with no turn command until the level
## judges the attempt (within the level's limit for that speed: `time_limit_at`). The
## game plays the same attempt in real time. The bike must be
## attached to the level (`Level.attach`) so it reads new bumps.


## Rides one attempt and returns `outcome` (Level.GOAL, FELL or TIMEOUT), `time` (s),
## `distance` (m towards the goal), `steps` (control steps simulated) and `planning_ms`
## (mean planning time per step; 0 for the arcade controller) and `late_plans` (steps the
## optimizer drove without that step's plan: 0 when the ride repeats exactly). The bike's
## `_physics_process` must be off so only this drives it.
static func ride(
	level: TestLevel, bike: BikeSimulation, seed_value: int, speed_kmh: float
) -> Dictionary:
	var spawn := level.spawn_points()[0]
	bike.reset_to(spawn.spawn_transform())
	level.begin_attempt(bike, seed_value)
	level.attempt_time_limit = level.time_limit_at(speed_kmh)
	var dt := SettingsSchema.control_period()
	var outcome := Level.RIDING
	var planning_ms := 0.0
	var plans := 0
	while outcome == Level.RIDING:
		bike.max_speed_kmh = speed_kmh
		bike.set_drive(BikeDriver.AUTO_THROTTLE, 0.0)
		bike.set_turn(0.0)
		bike.advance(1)
		var step_ms := bike.get_planning_ms()
		if step_ms > 0.0:
			planning_ms += step_ms
			plans += 1
		outcome = level.judge(bike, dt)
	return {
		outcome = outcome,
		time = level.elapsed,
		distance = level.distance(bike),
		steps = bike.get_step_count(),
		planning_ms = planning_ms / maxi(plans, 1),
		late_plans = bike.get_late_plan_count(),
	}
