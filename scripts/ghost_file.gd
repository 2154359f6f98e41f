class_name GhostFile
extends RefCounted
## A lap's recording (`RideRecording`) on disk, for racing it later. Binary and versioned:
## "CSGHOST" and a format number, the level it was ridden on, the recording, and a
## SHA-256 of all that, so a file cut short or damaged is known as such. Written to a
## temporary file first and renamed over the old one, so a crash or a kill never leaves
## half a ghost. A file that cannot be read is set aside as `<path>.broken`, never
## trusted and never lost.

const MAGIC := "CSGHOST"
## Bumped whenever the layout changes; an older file is set aside, not misread.
const FORMAT := 1
## A ghost longer than this many frames is not believed (a ten-minute lap at 30 Hz).
const MOST_FRAMES := 18000


## Saves `recording` of a lap on `level` to `path` atomically. Returns OK or the error.
static func save(recording: RideRecording, level: String, path: String) -> Error:
	DirAccess.make_dir_recursive_absolute(path.get_base_dir())
	var body := StreamPeerBuffer.new()
	body.put_data(MAGIC.to_ascii_buffer())
	body.put_u32(FORMAT)
	body.put_utf8_string(level)
	body.put_float(recording.rate)
	body.put_u32(recording.body_count)
	body.put_double(recording.lap_time)
	body.put_u32(recording.splits.size())
	for split in recording.splits:
		body.put_float(split)
	body.put_u32(recording.frame_count())
	body.put_data(recording.poses.to_byte_array())
	var bytes := body.data_array
	var temporary := path + ".tmp"
	var file := FileAccess.open(temporary, FileAccess.WRITE)
	if file == null:
		return _failed(path, FileAccess.get_open_error())
	file.store_buffer(bytes)
	file.store_buffer(_digest(bytes))
	var error := file.get_error()
	file.close()
	if error == OK:
		error = DirAccess.rename_absolute(temporary, path)
	if error != OK:
		DirAccess.remove_absolute(temporary)
		return _failed(path, error)
	return OK


## The lap saved at `path` for `level` and `body_count` bodies: {recording, problem}.
## No file: both empty. A file that is broken, of another format, level or bike: no
## recording, `problem` says why, and the file is kept aside as `<path>.broken`.
static func load_ghost(path: String, level: String, body_count: int) -> Dictionary:
	if not FileAccess.file_exists(path):
		return {recording = null, problem = ""}
	var problem := ""
	var recording := RideRecording.new()
	var bytes := FileAccess.get_file_as_bytes(path)
	if bytes.size() < 32 or _digest(bytes.slice(0, -32)) != bytes.slice(-32):
		problem = "it is damaged or cut short"
	else:
		problem = _read(bytes.slice(0, -32), level, body_count, recording)
	if problem.is_empty():
		return {recording = recording, problem = ""}
	DirAccess.rename_absolute(path, path + ".broken")
	push_warning("ghost %s set aside as %s.broken: %s" % [path, path, problem])
	return {recording = null, problem = problem}


static func _read(
	bytes: PackedByteArray, level: String, bodies: int, into: RideRecording
) -> String:
	var body := StreamPeerBuffer.new()
	body.data_array = bytes
	if body.get_data(MAGIC.length())[1].get_string_from_ascii() != MAGIC:
		return "it is not a ghost file"
	var format := body.get_u32()
	if format != FORMAT:
		return "it has format %d, this game reads %d" % [format, FORMAT]
	var ridden_on := body.get_utf8_string()
	if ridden_on != level:
		return "it was ridden on %s" % ridden_on
	into.rate = body.get_float()
	into.body_count = body.get_u32()
	if into.body_count != bodies or not (into.rate > 0.0 and into.rate <= 240.0):
		return "it was recorded of another bike"
	into.lap_time = body.get_double()
	var split_count := body.get_u32()
	if split_count > 64 or not (into.lap_time > 0.0 and is_finite(into.lap_time)):
		return "its lap time or checkpoints make no sense"
	for i in split_count:
		into.splits.append(body.get_float())
	var frames := body.get_u32()
	var size := frames * bodies * BikeSimulation.POSE_FLOATS * 4
	if frames == 0 or frames > MOST_FRAMES or body.get_available_bytes() != size:
		return "its frames do not add up"
	into.poses = body.get_data(size)[1].to_float32_array()
	return ""


static func _digest(bytes: PackedByteArray) -> PackedByteArray:
	var hashing := HashingContext.new()
	hashing.start(HashingContext.HASH_SHA256)
	hashing.update(bytes)
	return hashing.finish()


static func _failed(path: String, error: Error) -> Error:
	push_error("Could not save the ghost %s: %s" % [path, error_string(error)])
	return error
