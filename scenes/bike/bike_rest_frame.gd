class_name BikeRestFrame
extends RefCounted
## The simulated bike as it stood when its drawing was built, so the drawn pieces can be
## authored in the bike's own frame (x forward, y up, z right, origin on the ground between
## the wheels) and then carried by the bodies. The bike frame's axes are the designer's;
## Godot's meshes have x right, y up and z backwards (`basis()`).

## Directions in the bike frame.
const FORWARD := Vector3(1, 0, 0)
const DOWN := Vector3(0, -1, 0)

var _simulation: BikeSimulation
## The bike node's transform when the bodies were at rest: bike frame → world.
var _rest: Transform3D
## Every body's transform at rest.
var _bodies: Array[Transform3D] = []
## The bike's up and right at rest in the frame body's own axes, to read its lean.
var _frame_up := Vector3.UP
var _frame_right := Vector3.RIGHT


func _init(simulation: BikeSimulation) -> void:
	_simulation = simulation
	_rest = simulation.global_transform
	for body in simulation.get_body_count():
		_bodies.append(simulation.get_body_transform(body))
	var frame_axes := _bodies[BikeSimulation.FRAME].basis.orthonormalized().inverse()
	_frame_up = frame_axes * basis().y
	_frame_right = frame_axes * right()


## A body's transform at rest (world).
func rest_of(body: int) -> Transform3D:
	return _bodies[body]


## World rest position of a bike-frame point.
func world_of(point: Vector3) -> Vector3:
	return _rest * Vector3(point.z, point.y, -point.x)


## Bike-frame point of a world rest position.
func bike_of(world: Vector3) -> Vector3:
	var local := _rest.affine_inverse() * world
	return Vector3(-local.z, local.y, local.x)


## World rest basis whose x is the bike's right, y up and z backwards (Godot's meshes).
func basis() -> Basis:
	return _rest.basis.orthonormalized()


## The bike's right at rest (world).
func right() -> Vector3:
	return _rest.basis.x.normalized()


## What a world rest transform is in `body`'s frame: the offset it keeps riding on it.
func on_body(body: int, world_at_rest: Transform3D) -> Transform3D:
	return _bodies[body].affine_inverse() * world_at_rest


## The bike's key points at rest (bike frame) that bodywork is fitted to (BikeBodywork):
## its axles, the swingarm's pivot, the top of the steering head and the rider's seat.
func key_points() -> Dictionary:
	return {
		rear_axle = bike_of(_bodies[BikeSimulation.REAR_WHEEL].origin),
		swingarm_pivot = capsule_ends(BikeSimulation.SWINGARM, FORWARD)[0],
		steering_head = capsule_ends(BikeSimulation.FORK, DOWN)[1],
		front_axle = bike_of(_bodies[BikeSimulation.FRONT_WHEEL].origin),
		seat = capsule_ends(BikeSimulation.TORSO, DOWN)[0],
	}


## The two ends (bike frame) of a body's capsule, the one furthest along `first_towards`
## (a bike-frame direction) first.
func capsule_ends(body: int, first_towards: Vector3) -> Array[Vector3]:
	for shape: BikeShape in _simulation.get_shapes():
		if shape.body != body or shape.kind != "capsule":
			continue
		var offset := shape.offset
		var half := offset.basis.z.normalized() * shape.length / 2.0
		var a := bike_of(_bodies[body] * (offset.origin + half))
		var b := bike_of(_bodies[body] * (offset.origin - half))
		var ends: Array[Vector3] = [a, b]
		if b.dot(first_towards) > a.dot(first_towards):
			ends.reverse()
		return ends
	push_error("BikeRestFrame: body %d has no capsule" % body)
	var fallback: Array[Vector3] = [Vector3.ZERO, Vector3.UP]
	return fallback


## The bike's lean (radians, positive to the right, as BikeSimulation.get_lean) when its
## frame body is at `frame` (world): a recording's, which keeps the bodies alone.
func lean_of(frame: Transform3D) -> float:
	var up := (frame.basis * _frame_up).normalized()
	var bike_right := frame.basis * _frame_right
	var level_right := (bike_right - Vector3.UP * bike_right.dot(Vector3.UP)).normalized()
	return atan2(up.dot(level_right), up.dot(Vector3.UP))
