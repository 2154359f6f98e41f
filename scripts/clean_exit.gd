class_name CleanExit
extends RefCounted
## Quits without leaving sound behind. Godot's audio server lets go of a stopped stream
## only in its next mix, and at exit the drivers stop before that mix (godotengine/godot
## issue 76745), so quitting while a bike's engine plays leaks its playback and prints
## a warning. This stops every player under the tree and waits a few mixes first.

## Mixes to wait for: one fades the stopped stream out, the next removes it.
const MIXES := 3
## Longest the audio server takes between mixes (ms; its buffer is about 12 ms).
const MIX_PERIOD_MS := 20


## Stops all sound under `tree`, lets the audio server release it, then quits with `code`.
static func quit(tree: SceneTree, code := 0) -> void:
	for player: AudioStreamPlayer in tree.root.find_children("*", "AudioStreamPlayer", true, false):
		player.stop()
	for i in MIXES:
		await tree.process_frame
		OS.delay_msec(MIX_PERIOD_MS)
	tree.quit(code)
