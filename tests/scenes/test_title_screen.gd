extends TestCase
## The title screen shows the game's name and the native module's version.

const TITLE_SCENE := preload("res://scenes/ui/title_screen.tscn")

var _screen: Control


func before_each() -> void:
	_screen = TITLE_SCENE.instantiate()
	add_child(_screen)
	await wait_frames(1)


func after_each() -> void:
	_screen.queue_free()


func test_shows_the_game_name() -> void:
	var title: Label = _screen.get_node("Titles/GameTitle")
	assert_eq(title.text, "COUNTER-STEER")


func test_shows_the_native_version() -> void:
	var version: Label = _screen.get_node("%VersionLabel")
	assert_has(version.text, "native %s" % NativeModule.version())
	assert_has(version.text, "Godot 4.6")


func test_enter_asks_to_ride() -> void:
	var asked: Array[bool] = [false]
	_screen.connect(&"ride_requested", func() -> void: asked[0] = true)
	var event := InputEventAction.new()
	event.action = &"ui_accept"
	event.pressed = true
	Input.parse_input_event(event)
	await wait_frames(2)
	assert_true(asked[0])
	assert_ne(get_tree().current_scene, _screen, "an embedded title screen does not navigate")
