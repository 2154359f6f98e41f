@tool
extends EditorPlugin
## Editor plugin of the native simulation: tells level designers at once when the native
## module is missing or was built without what the simulation needs.


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
