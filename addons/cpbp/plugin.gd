@tool
extends EditorPlugin
## Editor plugin of the native simulation: tells level designers at once when the native
## module is missing or was built without what the simulation needs, draws spawn points
## as the bike they place, and when a level is saved lists every collision shape the bike
## simulation cannot use (the Level node also shows them as configuration warnings).

const SpawnPointGizmo := preload("res://addons/cpbp/spawn_point_gizmo.gd")

var _gizmo: EditorNode3DGizmoPlugin


func _enter_tree() -> void:
	if not NativeModule.is_loaded():
		push_error(
			"Counter-Steer: the native module is not loaded. Run 'make build' and reopen the project."
		)
	elif not NativeModule.ode_is_suitable():
		push_warning(
			(
				"Counter-Steer: ODE lacks double precision or thread-local collision: %s"
				% NativeModule.ode_configuration()
			)
		)
	_gizmo = SpawnPointGizmo.new()
	add_node_3d_gizmo_plugin(_gizmo)
	scene_saved.connect(_check_saved_level)


func _exit_tree() -> void:
	remove_node_3d_gizmo_plugin(_gizmo)
	scene_saved.disconnect(_check_saved_level)


func _check_saved_level(path: String) -> void:
	var level := EditorInterface.get_edited_scene_root() as Level
	if level == null or not ClassDB.class_exists(&"TerrainCheck"):
		return
	for problem in TerrainCheck.problems(level):
		push_warning("Counter-Steer: %s: the bike simulation cannot use %s" % [path, problem])
	if level.spawn_points().is_empty():
		push_warning("Counter-Steer: %s has no SpawnPoint; the bike has nowhere to start" % path)
