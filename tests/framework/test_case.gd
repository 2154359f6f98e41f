class_name TestCase
extends Node
## Base class of GDScript test suites. Assertion names follow GUT's (assert_eq, assert_true,
## …) so the suites can move to GUT unchanged once it can be installed.
##
## A suite is a script named `test_*.gd` under `tests/` that extends TestCase; each method
## named `test_*` is one test. `before_each`/`after_each` run around every test and
## `before_all`/`after_all` around the suite. Tests may `await`.

var _failures: PackedStringArray = []
var _pending_reason := ""
var _is_pending := false
var _expected_errors: PackedStringArray = []
var _assert_count := 0


## Runs once before the first test of the suite.
func before_all() -> void:
	pass


## Runs before every test.
func before_each() -> void:
	pass


## Runs after every test.
func after_each() -> void:
	pass


## Runs once after the last test of the suite.
func after_all() -> void:
	pass


func assert_eq(got: Variant, expected: Variant, text := "") -> void:
	_check(_same(got, expected), "expected %s, got %s" % [_show(expected), _show(got)], text)


func assert_ne(got: Variant, not_expected: Variant, text := "") -> void:
	_check(not _same(got, not_expected), "expected anything but %s" % _show(not_expected), text)


func assert_true(got: Variant, text := "") -> void:
	_check(got is bool and got == true, "expected true, got %s" % _show(got), text)


func assert_false(got: Variant, text := "") -> void:
	_check(got is bool and got == false, "expected false, got %s" % _show(got), text)


## Passes when |got − expected| ≤ tolerance; works for numbers and Vector2/3/4.
func assert_almost_eq(got: Variant, expected: Variant, tolerance: Variant, text := "") -> void:
	var close := false
	if _is_number(got) and _is_number(expected) and _is_number(tolerance):
		close = absf(float(got) - float(expected)) <= float(tolerance)
	elif (
		typeof(got) == typeof(expected)
		and typeof(got) in [TYPE_VECTOR2, TYPE_VECTOR3, TYPE_VECTOR4]
	):
		close = _within((got - expected).abs(), tolerance)
	_check(
		close, "expected %s ± %s, got %s" % [_show(expected), _show(tolerance), _show(got)], text
	)


func assert_gt(got: Variant, bound: Variant, text := "") -> void:
	_check(
		_is_number(got) and _is_number(bound) and got > bound,
		"expected %s > %s" % [_show(got), _show(bound)],
		text
	)


func assert_lt(got: Variant, bound: Variant, text := "") -> void:
	_check(
		_is_number(got) and _is_number(bound) and got < bound,
		"expected %s < %s" % [_show(got), _show(bound)],
		text
	)


func assert_between(got: Variant, low: Variant, high: Variant, text := "") -> void:
	_check(
		_is_number(got) and _is_number(low) and _is_number(high) and got >= low and got <= high,
		"expected %s in [%s, %s]" % [_show(got), _show(low), _show(high)],
		text
	)


func assert_null(got: Variant, text := "") -> void:
	_check(got == null, "expected null, got %s" % _show(got), text)


func assert_not_null(got: Variant, text := "") -> void:
	_check(got != null, "expected a value, got null", text)


## Passes when `container` (Array, Dictionary key, String, Packed array) holds `value`.
func assert_has(container: Variant, value: Variant, text := "") -> void:
	var found := false
	match typeof(container):
		TYPE_DICTIONARY, TYPE_ARRAY, TYPE_STRING, TYPE_STRING_NAME:
			found = (
				container.has(value)
				if typeof(container) != TYPE_STRING
				else (container as String).contains(str(value))
			)
		_:
			if typeof(container) >= TYPE_PACKED_BYTE_ARRAY:
				found = container.has(value)
	_check(found, "expected %s to contain %s" % [_show(container), _show(value)], text)


## Fails the running test with a message.
func fail_test(text: String) -> void:
	_check(false, "failed", text)


## Marks the running test as pending (reported as skipped, never as passed).
func pending(text := "") -> void:
	_is_pending = true
	_pending_reason = text


## Declares that the running test expects an engine error containing `fragment`
## (for tests of error handling); each declaration absorbs one matching error.
func expect_error(fragment: String) -> void:
	_expected_errors.append(fragment)


## Waits for `count` rendered/processed frames.
func wait_frames(count: int) -> void:
	for _i: int in count:
		await get_tree().process_frame


## Waits for `count` physics ticks.
func wait_physics_frames(count: int) -> void:
	for _i: int in count:
		await get_tree().physics_frame


func _check(passed: bool, detail: String, text: String) -> void:
	_assert_count += 1
	if passed:
		return
	var message := detail if text.is_empty() else "%s: %s" % [text, detail]
	_failures.append("%s %s" % [_caller_location(), message])


## `file:line` of the test code that made the failing assertion.
func _caller_location() -> String:
	var own_file: String = (get_script() as Script).resource_path
	for backtrace: ScriptBacktrace in Engine.capture_script_backtraces():
		for frame: int in backtrace.get_frame_count():
			if backtrace.get_frame_file(frame) == own_file:
				return "%s:%d" % [own_file, backtrace.get_frame_line(frame)]
	return own_file


func _same(a: Variant, b: Variant) -> bool:
	if _is_number(a) and _is_number(b):
		return a == b
	return typeof(a) == typeof(b) and a == b


func _is_number(value: Variant) -> bool:
	return typeof(value) in [TYPE_INT, TYPE_FLOAT]


func _within(difference: Variant, tolerance: Variant) -> bool:
	var bound: float = float(tolerance) if _is_number(tolerance) else -1.0
	match typeof(difference):
		TYPE_VECTOR2:
			var d: Vector2 = difference
			var t: Vector2 = Vector2(bound, bound) if bound >= 0.0 else tolerance
			return d.x <= t.x and d.y <= t.y
		TYPE_VECTOR3:
			var d: Vector3 = difference
			var t: Vector3 = Vector3(bound, bound, bound) if bound >= 0.0 else tolerance
			return d.x <= t.x and d.y <= t.y and d.z <= t.z
		TYPE_VECTOR4:
			var d: Vector4 = difference
			var t: Vector4 = Vector4(bound, bound, bound, bound) if bound >= 0.0 else tolerance
			return d.x <= t.x and d.y <= t.y and d.z <= t.z and d.w <= t.w
	return false


func _show(value: Variant) -> String:
	if typeof(value) == TYPE_STRING:
		return '"%s"' % value
	return var_to_str(value) if typeof(value) != TYPE_OBJECT else str(value)
