@tool
class_name ChallengeJudge
extends Resource
## How a lesson or challenge is judged, from what the simulation knows (speed, lean, where
## the bike is, which wheel touches the ground), never from a timer alone. Every physics
## tick of the ride it is asked for a verdict: null while the ride goes on, then a
## ChallengeResult. Its markers (gates, lines, boxes) are nodes of the challenge's area,
## named by the judge's NodePaths. Falls and the time limit are the game's to judge
## (ChallengeRun), so a judge only says how the goal went.
##
## A judge keeps the state of one attempt: the game judges every attempt with a fresh
## copy of the challenge's (`Resource.duplicate`), so the file's stays untouched.

## Below this speed (m/s), held for STILL_SECONDS, the bike has stopped.
const STILL_SPEED := 0.15
const STILL_SECONDS := 0.5

var area: ChallengeArea
var bike: BikeSimulation
## Seconds since the ride began (the first throttle).
var elapsed := 0.0
## Seconds the bike has been still.
var still_for := 0.0
## What is wrong with the judge's markers in this area (empty: nothing): a designer's
## mistake, told to the player instead of a crash.
var problem := ""


## An attempt that reached its goal with `score`.
static func passed_with(score: float, measured := PackedStringArray()) -> ChallengeResult:
	var result := ChallengeResult.new()
	result.passed = true
	result.score = score
	result.facts = measured
	return result


## An attempt that missed its goal, and why.
static func failed(reason: String, measured := PackedStringArray()) -> ChallengeResult:
	var result := ChallengeResult.new()
	result.why = reason
	result.facts = measured
	return result


## Starts judging an attempt on `bike` in `challenge_area`.
func begin(challenge_area: ChallengeArea, ridden: BikeSimulation) -> void:
	area = challenge_area
	bike = ridden
	elapsed = 0.0
	still_for = 0.0
	problem = ""
	_begin()


## Lets go of whatever the attempt held on to (the level's signals); the game calls it
## before the next attempt's copy begins.
func end() -> void:
	pass


## The verdict after `delta` more seconds of riding: null while the ride goes on.
func judge(delta: float) -> ChallengeResult:
	elapsed += delta
	still_for = still_for + delta if absf(bike.get_speed()) < STILL_SPEED else 0.0
	return _judge(delta)


## A line for the HUD about how the attempt stands ("gate 2 of 6").
func progress_text() -> String:
	return ""


## Whether the bike has stood still long enough to count as stopped.
func stopped() -> bool:
	return still_for >= STILL_SECONDS


## The bike's speed in km/h.
func speed_kmh() -> float:
	return absf(bike.get_speed()) * 3.6


## Where the front tyre meets the way ahead: the front wheel's centre moved its radius
## forwards (what a line to stop at is measured to).
func front_tyre() -> Vector3:
	var frame := bike.get_body_transform(BikeSimulation.FRAME).basis.x
	var front := bike.get_body_transform(BikeSimulation.FRONT_WHEEL).origin
	return front + frame.normalized() * bike.get_wheel_radius()


## The marker at `path` in the area if it is a `type` (a class such as MarkLine), else
## null with `problem` saying what is missing.
func marker(path: NodePath, type: Variant) -> Node3D:
	var found := area.marker(path)
	if found == null or not is_instance_of(found, type):
		problem = "the area %s has no %s %s" % [area.name, type.get_global_name(), path]
		push_error("Challenge: " + problem)
		return null
	return found


## The level the area is part of.
func level() -> Level:
	var node := area.get_parent()
	while node != null and not node is Level:
		node = node.get_parent()
	return node as Level


## What a subclass resets at the start of an attempt (its markers found again).
func _begin() -> void:
	pass


## A subclass's verdict (see `judge`).
func _judge(_delta: float) -> ChallengeResult:
	return null
