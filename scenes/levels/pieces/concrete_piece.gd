@tool
class_name ConcretePiece
extends StaticBody3D
## A level piece that builds its own mesh and collision shape from a few numbers, in the
## pieces' shared concrete tinted its `colour` (RampPiece, BankPiece). A subclass gives
## its mesh (`_piece_mesh`) and the collision shape for it (`_piece_shape`), and calls
## `_build()` when one of its numbers changes.

## Every piece's concrete, one material shared (so the graphics quality reaches them
## all); each piece's colour is its vertices'.
const CONCRETE: StandardMaterial3D = preload("res://scenes/levels/materials/piece.tres")

## Colour of the surface, a tint of its concrete.
@export var colour := Color(0.6, 0.55, 0.48):
	set(value):
		colour = value
		_build()

var _shape: CollisionShape3D
var _mesh: MeshInstance3D


func _ready() -> void:
	_build()


## Builds the piece again from its numbers (nothing until it is in the tree).
func _build() -> void:
	if not is_inside_tree():
		return
	if _shape == null:
		_shape = CollisionShape3D.new()
		_shape.name = "Shape"
		add_child(_shape)
		_mesh = MeshInstance3D.new()
		_mesh.name = "Mesh"
		add_child(_mesh)
	var mesh := _piece_mesh()
	_mesh.mesh = mesh
	_shape.shape = _piece_shape(mesh)


## The piece's mesh, in `colour` on CONCRETE.
func _piece_mesh() -> ArrayMesh:
	return ArrayMesh.new()


## The collision shape of `mesh`.
func _piece_shape(mesh: ArrayMesh) -> Shape3D:
	return mesh.create_trimesh_shape()
