@tool
class_name NativeModule
extends RefCounted
## Describes the native module (the Rust GDExtension) without failing when it is missing,
## so menus can show a clear message instead of a script error.

const INFO_CLASS := &"NativeInfo"
## The extension's description: which library each platform loads.
const EXTENSION := "res://addons/cpbp/cpbp.gdextension"


## The native library file this platform loads, as the extension lists it.
static func library_file() -> String:
	var extension := ConfigFile.new()
	var key := "%s.release.x86_64" % OS.get_name().to_lower()
	if extension.load(EXTENSION) != OK or not extension.has_section_key("libraries", key):
		return "the native library"
	return str(extension.get_value("libraries", key)).get_file()


## True when the extension is loaded and its classes are registered.
static func is_loaded() -> bool:
	return ClassDB.class_exists(INFO_CLASS)


## Version of the native module, or an empty string when it is not loaded.
static func version() -> String:
	if not is_loaded():
		return ""
	return str(ClassDB.class_call_static(INFO_CLASS, &"version"))


## `dGetConfiguration()` of the linked ODE, or an empty string when not loaded.
static func ode_configuration() -> String:
	if not is_loaded():
		return ""
	return str(ClassDB.class_call_static(INFO_CLASS, &"ode_configuration"))


## The controllers players pick, by name, in menu order (empty when not loaded): the one
## list, `ControllerKind::all()` in the native core.
static func controller_names() -> PackedStringArray:
	if not is_loaded():
		return PackedStringArray()
	return ClassDB.class_call_static(&"BikeSimulation", &"controller_names")


## What menus show for controller `name`.
static func controller_label(name: String) -> String:
	if not is_loaded():
		return name
	return str(ClassDB.class_call_static(&"BikeSimulation", &"controller_label", name))


## True when ODE is double precision with thread-local collision data.
static func ode_is_suitable() -> bool:
	return is_loaded() and bool(ClassDB.class_call_static(INFO_CLASS, &"ode_is_suitable"))


## What this build is and runs on: the native module's platform (compiler, ODE, the C
## library, CPU model and its math path) and the engine's version and build. The experiment
## records it with every result, and `--native-info` prints it. Empty when not loaded.
static func platform() -> Dictionary:
	if not is_loaded():
		return {}
	var native: Dictionary = ClassDB.class_call_static(INFO_CLASS, &"platform")
	var engine := Engine.get_version_info()
	var description := native.duplicate()
	description["godot"] = engine.string
	description["godot_hash"] = engine.hash
	description["godot_build"] = engine.build
	return description


## True when the game was started with `--native-info` (smoke tests, bug reports): the start
## menu prints `describe()` and `platform()` and quits, and nothing else is built (a level
## built only to be torn down makes the release template report spurious signal errors).
static func info_requested() -> bool:
	return OS.get_cmdline_user_args().has("--native-info")


## One line for title screens and bug reports.
static func describe() -> String:
	if not is_loaded():
		if OS.has_feature("template"):
			# A player's build: the library ships beside the game and Godot has printed why
			# it would not open.
			var problem := "%s beside the game is missing or could not be opened" % library_file()
			return (
				"Native module not loaded: %s (the first ERROR lines say why)." % problem
				+ " Unpack the whole download again."
			)
		return "Native module not loaded: run 'make build'"
	var precision := "double" if ode_configuration().contains("ODE_double_precision") else "single"
	var threads := "thread-safe collision" if ode_is_suitable() else "NOT thread-safe collision"
	return (
		"native %s · ODE 0.16 (%s, %s) · Godot %s"
		% [version(), precision, threads, Engine.get_version_info().string]
	)
