class_name ChallengeResult
extends RefCounted
## How an attempt at a lesson or challenge ended, as its judge saw it from the simulation:
## passed with a score, or failed with what went wrong in words a player understands; and
## what the ride measured that is worth telling ("braked from 61 km/h in 16.0 m: 0.91 g").

var passed := false
## The measure the medals are given by (NAN when failed).
var score := NAN
## Why the attempt failed ("you stopped 1.2 m past the line"); empty when passed.
var why := ""
## What the ride measured, a line each.
var facts := PackedStringArray()


## An attempt that reached its goal with `score`.
static func passed_with(score_value: float, measured := PackedStringArray()) -> ChallengeResult:
	var result := ChallengeResult.new()
	result.passed = true
	result.score = score_value
	result.facts = measured
	return result


## An attempt that missed its goal, and why.
static func failed(reason: String, measured := PackedStringArray()) -> ChallengeResult:
	var result := ChallengeResult.new()
	result.why = reason
	result.facts = measured
	return result
