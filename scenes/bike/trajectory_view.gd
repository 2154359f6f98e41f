class_name TrajectoryView
extends MeshInstance3D
## Draws the optimizer's last plan as in the thesis's Figure 4.10: each trajectory's
## centre-of-mass path, the best in green, the refined (optimizer) or arcade (combined)
## one in yellow, the others in black. Draws nothing while another controller drives.
## A replay's view draws recorded plans instead (`draw_paths`).

const BEST_COLOUR := Color(0.1, 0.9, 0.2)
const WARM_COLOUR := Color(1.0, 0.85, 0.1)
const OTHER_COLOUR := Color(0.02, 0.02, 0.02)

## The simulation whose plans to draw; by default the parent.
@export var simulation_path: NodePath = ^".."
## Draws the live plans of the simulation; off, only what `draw_paths` is given.
@export var follows_simulation := true

## The show_trajectories setting (the game sets it by name): whether it is drawn.
var show_trajectories := true:
	set(value):
		show_trajectories = value
		visible = value

var _simulation: Node
var _lines := ImmediateMesh.new()


func _ready() -> void:
	_simulation = get_node_or_null(simulation_path)
	mesh = _lines
	# Paths are in world coordinates, whatever the parent's transform.
	top_level = true
	global_transform = Transform3D.IDENTITY
	var material := StandardMaterial3D.new()
	material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	material.vertex_color_use_as_albedo = true
	material_override = material
	cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	if not follows_simulation:
		set_process(false)
	elif _simulation == null:
		push_error("TrajectoryView: no BikeSimulation at %s" % simulation_path)
		set_process(false)


func _process(_delta: float) -> void:
	if not visible or not _simulation.call(&"is_running"):
		_lines.clear_surfaces()
		return
	draw_paths(
		_simulation.call(&"get_trajectory_paths"),
		_simulation.call(&"get_best_trajectory"),
		_simulation.call(&"get_warm_trajectory")
	)


## Draws `paths` (world coordinates), `best` in green and `warm` in yellow (−1: none).
func draw_paths(paths: Array[PackedVector3Array], best: int, warm: int) -> void:
	_lines.clear_surfaces()
	# Others first, then the highlighted two on top of them.
	var order: Array[int] = []
	for i: int in paths.size():
		if i != best and i != warm:
			order.append(i)
	# The best may be the warm-started one itself: draw it once, in green.
	for i: int in [warm, best]:
		if i >= 0 and i < paths.size() and i not in order:
			order.append(i)
	for i: int in order:
		var path := paths[i]
		if path.size() < 2:
			continue
		var colour := OTHER_COLOUR
		if i == best:
			colour = BEST_COLOUR
		elif i == warm:
			colour = WARM_COLOUR
		_lines.surface_begin(Mesh.PRIMITIVE_LINE_STRIP)
		_lines.surface_set_color(colour)
		for point: Vector3 in path:
			_lines.surface_add_vertex(point)
		_lines.surface_end()


## The number of trajectories drawn last frame (for tests and the HUD).
func drawn_count() -> int:
	return _lines.get_surface_count()
