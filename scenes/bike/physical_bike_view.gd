class_name PhysicalBikeView
extends Node3D
## Draws the simulated bodies of a BikeSimulation as simple meshes (spheres, boxes,
## capsules), each following its body every frame. It shows exactly what collides.

const WHEEL_COLOUR := Color(0.12, 0.12, 0.13)
const BIKE_COLOUR := Color(0.85, 0.25, 0.15)
const RIDER_COLOUR := Color(0.2, 0.45, 0.8)
const RIDER_FIRST_BODY := BikeSimulation.LOWER_LEG

## The simulation to draw; by default the parent.
@export var simulation_path: NodePath = ^".."

## The physical_model setting (the game sets it by name): this view is drawn instead of
## the visual one.
var physical_model := false:
	set(value):
		physical_model = value
		visible = value

var _simulation: BikeSimulation
## Per shape: the body index it follows and its offset within that body.
var _followers: Array[Dictionary] = []


func _ready() -> void:
	_simulation = get_node_or_null(simulation_path) as BikeSimulation
	if _simulation != null and not _simulation.is_node_ready():
		# Children are ready before their parent: wait for the simulation to build.
		await _simulation.ready
	if _simulation == null or not _simulation.is_running():
		push_error("PhysicalBikeView: no running BikeSimulation at %s" % simulation_path)
		set_process(false)
		return
	for shape: BikeShape in _simulation.get_shapes():
		_add_shape(shape)
	_follow()


func _process(_delta: float) -> void:
	if visible:
		_follow()


func _add_shape(shape: BikeShape) -> void:
	var body := shape.body
	var mesh_instance := MeshInstance3D.new()
	var alignment := Transform3D.IDENTITY
	match shape.kind:
		"sphere":
			var sphere := SphereMesh.new()
			sphere.radius = shape.radius
			sphere.height = 2.0 * shape.radius
			mesh_instance.mesh = sphere
		"box":
			var box := BoxMesh.new()
			box.size = shape.size
			mesh_instance.mesh = box
		"capsule":
			var capsule := CapsuleMesh.new()
			capsule.radius = shape.radius
			capsule.height = shape.length + 2.0 * shape.radius
			mesh_instance.mesh = capsule
			# Godot's capsule stands along y; the simulation's lies along z.
			alignment = Transform3D(Basis(Vector3.RIGHT, PI / 2.0), Vector3.ZERO)
	var material := StandardMaterial3D.new()
	material.albedo_color = _colour_of(body)
	material.roughness = 0.7
	mesh_instance.material_override = material
	mesh_instance.name = "%s_%d" % [_simulation.get_body_name(body), _followers.size()]
	mesh_instance.top_level = true
	add_child(mesh_instance)
	_followers.append({node = mesh_instance, body = body, offset = shape.offset * alignment})


func _follow() -> void:
	# Each body once per frame, however many shapes it carries.
	var bodies: Array[Transform3D] = []
	for body in _simulation.get_body_count():
		bodies.append(_simulation.get_body_transform(body))
	for follower: Dictionary in _followers:
		var node: MeshInstance3D = follower.node
		node.global_transform = bodies[follower.body] * (follower.offset as Transform3D)


func _colour_of(body: int) -> Color:
	if body in [BikeSimulation.REAR_WHEEL, BikeSimulation.FRONT_WHEEL]:
		return WHEEL_COLOUR
	return BIKE_COLOUR if body < RIDER_FIRST_BODY else RIDER_COLOUR
