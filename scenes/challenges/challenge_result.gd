class_name ChallengeResult
extends RefCounted
## How an attempt at a lesson or challenge ended, as its judge saw it from the simulation:
## passed with a score, or failed with what went wrong in words a player understands; and
## what the ride measured that is worth telling ("braked from 61 km/h in 16.0 m: 0.91 g").
## Judges make them (`ChallengeJudge.passed_with`, `ChallengeJudge.failed`): a script
## that names its own class stays loaded past an export's exit in Godot 4.6, so this one
## does not.

var passed := false
## The measure the medals are given by (NAN when failed).
var score := NAN
## Why the attempt failed ("you stopped 1.2 m past the line"); empty when passed.
var why := ""
## What the ride measured, a line each.
var facts := PackedStringArray()
