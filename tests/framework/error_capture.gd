class_name ErrorCapture
extends Logger
## Collects every error and script error the engine reports while a test runs, so the
## runner can fail the test that caused it (Godot itself would only print it and go on).
## The engine may log from any thread, hence the mutex.

var _mutex := Mutex.new()
var _errors: PackedStringArray = []


func _log_error(
	function: String,
	file: String,
	line: int,
	code: String,
	rationale: String,
	_editor_notify: bool,
	error_type: int,
	_script_backtraces: Array[ScriptBacktrace]
) -> void:
	if error_type == ERROR_TYPE_WARNING:
		return
	var text := rationale if not rationale.is_empty() else code
	_mutex.lock()
	_errors.append("%s (%s:%d in %s)" % [text, file, line, function])
	_mutex.unlock()


func _log_message(_message: String, _error: bool) -> void:
	pass


## Returns the errors collected since the last call and forgets them.
func take() -> PackedStringArray:
	_mutex.lock()
	var taken := _errors
	_errors = []
	_mutex.unlock()
	return taken
