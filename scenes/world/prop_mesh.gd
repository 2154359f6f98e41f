class_name PropMesh
extends RefCounted
## Set dressing's meshes are built from Godot's primitives, so no asset can go missing:
## a prop is one mesh of parts, each part a primitive placed and coloured, one surface a
## colour (`joined`). Trackside's and the skate park's props are made this way.


## One mesh of `parts`: [primitive, offset (or a whole Transform3D), colour] each. A fourth
## element true makes the part's colour glow, as a lamp's does.
static func joined(parts: Array) -> ArrayMesh:
	var mesh := ArrayMesh.new()
	for part: Array in parts:
		var tool := SurfaceTool.new()
		var placed: Transform3D = (
			part[1] if part[1] is Transform3D else Transform3D(Basis(), part[1])
		)
		tool.append_from(part[0] as Mesh, 0, placed)
		var material := StandardMaterial3D.new()
		material.albedo_color = part[2]
		material.roughness = 0.9
		if part.size() > 3 and part[3]:
			material.emission_enabled = true
			material.emission = part[2]
		tool.set_material(material)
		tool.commit(mesh)
	return mesh


static func box(size: Vector3) -> BoxMesh:
	var mesh := BoxMesh.new()
	mesh.size = size
	return mesh


## A cylinder of `sides` faces, `top` and `bottom` its radii (a cone with `top` 0).
static func cylinder(top: float, bottom: float, height: float, sides: int) -> CylinderMesh:
	var mesh := CylinderMesh.new()
	mesh.top_radius = top
	mesh.bottom_radius = bottom
	mesh.height = height
	mesh.radial_segments = sides
	mesh.rings = 1
	return mesh


## `mesh` drawn at each of `transforms` (in the parent's space) as one MultiMesh named
## `title`. Where each stands is kept as the node's `laid` metadata (`laid_at`): the
## rendering server keeps the instances' transforms, and a headless one keeps none.
static func instances(title: String, mesh: Mesh, transforms: Array) -> MultiMeshInstance3D:
	var origins := PackedVector3Array()
	var multimesh := MultiMesh.new()
	multimesh.transform_format = MultiMesh.TRANSFORM_3D
	multimesh.mesh = mesh
	multimesh.instance_count = transforms.size()
	for i in transforms.size():
		var placed: Transform3D = transforms[i]
		multimesh.set_instance_transform(i, placed)
		origins.append(placed.origin)
	var node := MultiMeshInstance3D.new()
	node.name = title
	node.multimesh = multimesh
	node.set_meta(&"laid", origins)
	return node


## Where `instances`' props stand, global (none for a node it did not make).
static func laid_at(node: MultiMeshInstance3D) -> PackedVector3Array:
	var out := PackedVector3Array()
	if not is_instance_valid(node) or not node.is_inside_tree():
		return out
	for at: Vector3 in node.get_meta(&"laid", PackedVector3Array()):
		out.append(node.global_transform * at)
	return out


## Props cast shadows, or not, as the graphics quality's `prop_shadows` says.
static func cast_shadows(nodes: Array, on: bool) -> void:
	for node: GeometryInstance3D in nodes:
		if is_instance_valid(node):
			node.cast_shadow = (
				GeometryInstance3D.SHADOW_CASTING_SETTING_ON
				if on
				else GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
			)
