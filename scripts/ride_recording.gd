class_name RideRecording
extends RefCounted
## A ride recorded as the bodies' poses, one frame per control step (`rate` frames a
## second), each `body_count` × BikeSimulation.POSE_FLOATS numbers from
## `BikeSimulation.get_pose_frame`; played back by `poses_at` with the poses interpolated
## between frames. A lap's recording also keeps its time and the time at each checkpoint.

## Frames a second, and bodies a frame.
var rate := 30.0
var body_count := 0
## The lap's time (s) and the lap time at checkpoints 1, 2, … (s); empty for a ride that
## is not a lap.
var lap_time := INF
var splits := PackedFloat32Array()
## Every frame's numbers, one after the other.
var poses := PackedFloat32Array()


func _init(frames_per_second := 30.0, bodies := 0) -> void:
	rate = frames_per_second
	body_count = bodies


## Appends a frame (`get_pose_frame`); one of the wrong size is refused.
func add(frame: PackedFloat32Array) -> bool:
	if body_count == 0:
		body_count = frame.size() / BikeSimulation.POSE_FLOATS
	if body_count == 0 or frame.size() != body_count * BikeSimulation.POSE_FLOATS:
		push_error(
			"RideRecording: a frame of %d numbers for %d bodies" % [frame.size(), body_count]
		)
		return false
	poses.append_array(frame)
	return true


func frame_count() -> int:
	return 0 if body_count == 0 else poses.size() / (body_count * BikeSimulation.POSE_FLOATS)


## Seconds from the first frame to the last.
func duration() -> float:
	return maxf(frame_count() - 1, 0) / rate


## Body `body`'s transform `seconds` after the first frame (held at either end).
func pose_of(body: int, seconds: float) -> Transform3D:
	var at := clampf(seconds * rate, 0.0, maxf(frame_count() - 1, 0))
	var before := int(at)
	var after := mini(before + 1, frame_count() - 1)
	var a := _transform(before, body)
	var b := _transform(after, body)
	var weight := at - before
	return Transform3D(a.basis.slerp(b.basis, weight), a.origin.lerp(b.origin, weight))


## Every body's transform `seconds` after the first frame.
func poses_at(seconds: float) -> Array[Transform3D]:
	var bodies: Array[Transform3D] = []
	for body in body_count:
		bodies.append(pose_of(body, seconds))
	return bodies


func _transform(frame: int, body: int) -> Transform3D:
	var i := (frame * body_count + body) * BikeSimulation.POSE_FLOATS
	var rotation := Quaternion(poses[i + 3], poses[i + 4], poses[i + 5], poses[i + 6])
	return Transform3D(Basis(rotation.normalized()), Vector3(poses[i], poses[i + 1], poses[i + 2]))
