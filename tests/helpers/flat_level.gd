class_name FlatLevel
extends RefCounted
## Test helper: an empty level whose ground is an infinite plane at height 0.


## A new level node with the ground in it; the caller adds it to the tree.
static func create() -> Node3D:
	var level := Node3D.new()
	level.name = "FlatLevel"
	var ground := StaticBody3D.new()
	ground.name = "Ground"
	var shape := CollisionShape3D.new()
	shape.name = "Shape"
	shape.shape = WorldBoundaryShape3D.new()
	ground.add_child(shape)
	level.add_child(ground)
	return level
