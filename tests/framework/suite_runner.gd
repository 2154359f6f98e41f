extends Node
## Headless GDScript test runner: finds `test_*.gd` suites, runs every `test_*` method with
## its hooks (awaiting coroutines), fails tests that raise engine or script errors they did
## not expect, prints `file:line` of each failed assertion, and ends with the line
## `GDScript: N passed, N failed, N skipped`. Exits 1 on any failure or when no test ran.
##
## Arguments after `--`: `--dir=res://tests` (repeatable), `--filter=TEXT` (suite path or
## test name contains TEXT). `tests/fixtures/` is skipped unless named with --dir.

## Printed first; tools/check-godot-log trusts the runner for errors between this line and the
## closing counts (it attributes each to its test) and fails on any error outside them.
const START_MARKER := "GDScript test run started"
const DEFAULT_DIR := "res://tests"
const FIXTURES_DIR := "res://tests/fixtures"
## Tests at least this long print their wall time.
const SLOW_TEST_SECONDS := 1.0

var _passed := 0
var _failed := 0
var _skipped := 0
var _failure_report: PackedStringArray = []
var _capture := ErrorCapture.new()


func _ready() -> void:
	OS.add_logger(_capture)
	print(START_MARKER)
	var refusal := _scratch_refusal()
	if not refusal.is_empty():
		_record_failure("user://", refusal)
		_finish()
		return
	var options := _parse_arguments(OS.get_cmdline_user_args())
	var dirs: PackedStringArray = options.dirs
	var suites: PackedStringArray = []
	for dir: String in dirs:
		suites.append_array(_discover(dir, dir.begins_with(FIXTURES_DIR)))
	for path: String in suites:
		await _run_suite(path, options.filter)
	_finish()


## Tests save settings, records and ghosts, so they run only in a data home made empty for
## the run by tools/run-suites.sh, never in the player's own user:// folder.
func _scratch_refusal() -> String:
	var scratch := OS.get_environment("COUNTER_STEER_SCRATCH")
	if scratch.is_empty():
		return (
			(
				"refusing to run in the player's data (%s): start the suites with "
				+ "tools/run-suites.sh NAME, which gives them a scratch folder"
			)
			% OS.get_user_data_dir()
		)
	if not OS.get_user_data_dir().begins_with(scratch.path_join("")):
		return "user:// is %s, outside the scratch folder %s" % [OS.get_user_data_dir(), scratch]
	return ""


func _parse_arguments(arguments: PackedStringArray) -> Dictionary:
	var dirs: PackedStringArray = []
	var filter := ""
	for argument: String in arguments:
		if argument.begins_with("--dir="):
			dirs.append(argument.trim_prefix("--dir="))
		elif argument.begins_with("--filter="):
			filter = argument.trim_prefix("--filter=")
	if dirs.is_empty():
		dirs.append(DEFAULT_DIR)
	return {dirs = dirs, filter = filter}


func _discover(dir: String, include_fixtures: bool) -> PackedStringArray:
	var found: PackedStringArray = []
	if not include_fixtures and dir.begins_with(FIXTURES_DIR):
		return found
	var access := DirAccess.open(dir)
	if access == null:
		_record_failure(
			dir, "cannot open test directory (%s)" % error_string(DirAccess.get_open_error())
		)
		return found
	var files := access.get_files()
	files.sort()
	for file: String in files:
		if file.begins_with("test_") and file.ends_with(".gd"):
			found.append(dir.path_join(file))
	var subdirs := access.get_directories()
	subdirs.sort()
	for subdir: String in subdirs:
		found.append_array(_discover(dir.path_join(subdir), include_fixtures))
	return found


func _run_suite(path: String, filter: String) -> void:
	var script := load(path) as GDScript
	var load_errors := _capture.take()
	if script == null or not script.can_instantiate():
		_record_failure(path, "cannot load suite: %s" % "; ".join(load_errors))
		return
	var instance: Variant = script.new()
	if not instance is TestCase:
		_record_failure(path, "suite does not extend TestCase")
		return
	var suite: TestCase = instance
	var tests := _test_names(script, path, filter)
	if tests.is_empty():
		suite.free()
		return
	print("%s" % path)
	var started_msec := Time.get_ticks_msec()
	add_child(suite)
	await suite.before_all()
	_fail_on_errors(path, "before_all", _capture.take())
	for test: String in tests:
		await _run_test(suite, path, test)
	await suite.after_all()
	_fail_on_errors(path, "after_all", _capture.take())
	suite.queue_free()
	await get_tree().process_frame
	# Wall time per suite, to see where a slow CI run spends its minutes.
	print("  %d tests in %.1f s" % [tests.size(), (Time.get_ticks_msec() - started_msec) / 1000.0])


func _test_names(script: GDScript, path: String, filter: String) -> PackedStringArray:
	var names: PackedStringArray = []
	for method: Dictionary in script.get_script_method_list():
		var name: String = method.name
		if name.begins_with("test_") and not names.has(name):
			if filter.is_empty() or path.contains(filter) or name.contains(filter):
				names.append(name)
	return names


func _run_test(suite: TestCase, path: String, test: String) -> void:
	suite._failures = []
	suite._is_pending = false
	suite._pending_reason = ""
	suite._expected_errors = []
	_capture.take()
	var started_msec := Time.get_ticks_msec()
	await suite.before_each()
	await suite.call(test)
	await suite.after_each()
	var failures := suite._failures
	failures.append_array(_unexpected_errors(_capture.take(), suite._expected_errors))
	# A slow test's wall time on its line, to see which rides a CI cut should look at.
	var seconds := (Time.get_ticks_msec() - started_msec) / 1000.0
	var took := " (%.1f s)" % seconds if seconds >= SLOW_TEST_SECONDS else ""
	if not failures.is_empty():
		_failed += 1
		print("  FAIL %s%s" % [test, took])
		for failure: String in failures:
			print("       %s" % failure)
			_failure_report.append("%s %s: %s" % [path, test, failure])
	elif suite._is_pending:
		_skipped += 1
		print("  skip %s %s" % [test, suite._pending_reason])
	else:
		_passed += 1
		print("  ok   %s%s" % [test, took])


## Errors the test did not declare with expect_error, plus declared ones that never came.
func _unexpected_errors(
	errors: PackedStringArray, expected: PackedStringArray
) -> PackedStringArray:
	var remaining_expected := expected.duplicate()
	var unexpected: PackedStringArray = []
	for error: String in errors:
		var matched := -1
		for i: int in remaining_expected.size():
			if error.contains(remaining_expected[i]):
				matched = i
				break
		if matched >= 0:
			remaining_expected.remove_at(matched)
		else:
			unexpected.append("unexpected error: %s" % error)
	for fragment: String in remaining_expected:
		unexpected.append('expected an error containing "%s", none was reported' % fragment)
	return unexpected


func _fail_on_errors(path: String, phase: String, errors: PackedStringArray) -> void:
	for error: String in errors:
		_record_failure(path, "%s raised: %s" % [phase, error])


func _record_failure(where: String, message: String) -> void:
	_failed += 1
	print("  FAIL %s: %s" % [where, message])
	_failure_report.append("%s: %s" % [where, message])


func _finish() -> void:
	OS.remove_logger(_capture)
	if not _failure_report.is_empty():
		print("\nFailures:")
		for line: String in _failure_report:
			print("  %s" % line)
	if _passed + _failed == 0:
		print("\nNo test ran.")
	print("\nGDScript: %d passed, %d failed, %d skipped" % [_passed, _failed, _skipped])
	# A game a test freed may still have its engine's sound in the audio server, which lets
	# go of it only at its next mix: quitting before that leaks it (see CleanExit).
	CleanExit.quit(get_tree(), 1 if _failed > 0 or _passed + _failed == 0 else 0)
