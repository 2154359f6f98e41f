extends TestCase
## A bike's looks are data: its bodywork (a BikeBodywork file) is drawn as authored on the
## bike it was drawn on, fitted to a bike of another size and painted in the bike's own
## colour; a description naming something that is not usable bodywork draws the standard
## bodywork, with an error saying why. Each bike has its wheels (cast or wire-spoked),
## brake discs and mirrors. A ghost is see-through all over and casts no shadow.

const GAME := preload("res://scenes/game/game.tscn")
const LEVEL := "res://scenes/levels/test_level/test_level.tscn"
const PIT_BIKE := "res://tests/fixtures/bikes/pit_bike.tres"
const STREET_BIKE := "res://scenes/bike/bikes/street_350.tres"

var _game: Game


func before_each() -> void:
	SettingsSandbox.enter()


func after_each() -> void:
	if _game != null:
		_game.queue_free()
		_game = null
	await wait_frames(1)
	SettingsSandbox.leave()


## The view of a game riding the bike described at `bike_path`, still waiting at the start
## (so the bike stands as it did when its drawing was built).
func _drawn(bike_path: String) -> VisualBikeView:
	_game = GAME.instantiate() as Game
	_game.level_path = LEVEL
	_game.bike_path = bike_path
	add_child(_game)
	await wait_physics_frames(2)
	return _game.bike.get_node(^"VisualBikeView") as VisualBikeView


## The drawn pieces of `look` made of `mesh_class` meshes.
func _pieces(view: VisualBikeView, look: String, mesh_class: String) -> Array[MeshInstance3D]:
	var found: Array[MeshInstance3D] = []
	for child in view.get_children():
		var piece := child as MeshInstance3D
		if piece != null and piece.name.begins_with(look + "_") and piece.mesh.is_class(mesh_class):
			found.append(piece)
	return found


func test_the_standard_bodywork_fits_the_bike_it_was_drawn_on_unchanged() -> void:
	var bodywork := load(BikeBodywork.STANDARD) as BikeBodywork
	assert_eq(bodywork.problem(), "", "its key points are in order")
	var authored := bodywork.authored_points()
	for piece: BodyworkPiece in bodywork.pieces:
		for point: Vector3 in [piece.from, piece.to]:
			assert_almost_eq(bodywork.fitted(point, authored), point, Vector3.ONE * 1e-9)
	await _drawn(STREET_BIKE)
	var measured := BikeRestFrame.new(_game.bike).key_points()
	for name: String in authored:
		assert_almost_eq(measured[name], authored[name], Vector3.ONE * 1e-3, "%s as drawn" % name)


func test_a_smaller_bike_wears_the_bodywork_fitted_to_it_in_its_own_paint() -> void:
	var view := await _drawn(PIT_BIKE)
	var description := _game.bike.bike
	var frame := BikeRestFrame.new(_game.bike)
	var points := frame.key_points()
	var tanks := _pieces(view, "paint", "SphereMesh")
	assert_eq(tanks.size(), 1, "one tank")
	var tank := frame.bike_of(tanks[0].global_position)
	assert_between(tank.x, points.seat.x, points.steering_head.x, "between seat and steering head")
	var tank_length := tanks[0].global_basis.z.length()
	assert_lt(tank_length, 0.52 - 0.1, "shorter than on the longer reference bike")
	var gap: float = tank.x - tank_length / 2.0 - points.seat.x
	assert_lt(gap, 0.12, "no gap opens between the seat and the tank")
	var paint := (tanks[0].material_override as StandardMaterial3D).albedo_color
	assert_eq(paint, description.paint, "the bike's own paint")
	var engines := _pieces(view, "engine", "ArrayMesh")
	assert_eq(engines.size(), 1, "one engine, a rounded box")
	assert_eq(engines[0].mesh, RoundedBox.mesh(), "the shared rounded box")
	var engine_front := (
		frame.bike_of(engines[0].global_position).x + engines[0].global_basis.z.length() / 2.0
	)
	var front_tyre_back: float = points.front_axle.x - _game.bike.get_wheel_radius()
	assert_lt(engine_front, front_tyre_back, "the engine clears the front tyre")
	var lights := _pieces(view, "tail_light", "BoxMesh")
	var overhang: float = frame.bike_of(lights[0].global_position).x - points.rear_axle.x
	var authored := load(BikeBodywork.STANDARD) as BikeBodywork
	var is_light := func(piece: BodyworkPiece) -> bool: return piece.look == "tail_light"
	var light: BodyworkPiece = authored.pieces.filter(is_light)[0]
	assert_almost_eq(
		overhang, light.from.x - authored.rear_axle.x, 1e-4, "the tail overhangs as much"
	)


func test_each_bike_a_player_chooses_wears_its_own_bodywork_and_fork_front() -> void:
	var fronts := {}
	var bodyworks := {}
	for key: String in Bikes.keys():
		var view := await _drawn(Bikes.path_of(key))
		var bodywork := BikeBodywork.worn_by(_game.bike.bike)
		assert_eq(bodywork.problem(), "", "%s's bodywork fits" % key)
		bodyworks[bodywork.resource_path] = key
		var lamps := _pieces(view, "lamp", "SphereMesh").size()
		var wheel := _game.bike.get_body_transform(BikeSimulation.FRONT_WHEEL).origin
		var boards := 0
		for plate in _pieces(view, "plate", "BoxMesh"):
			boards += int(plate.global_position.distance_to(wheel) < 0.8)
		fronts[key] = [lamps, boards]
		_game.queue_free()
		_game = null
		await wait_frames(1)
	assert_eq(bodyworks.size(), 3, "three bodyworks: %s" % bodyworks)
	assert_eq(fronts.street_390, [1, 0], "a round headlamp")
	assert_eq(fronts.dirt_125, [0, 1], "a number board")
	assert_eq(fronts.sport_600, [0, 0], "the fairing's lamps")


func test_each_bike_has_its_wheels_brakes_and_mirrors() -> void:
	var seen := {}
	for key: String in Bikes.keys():
		var view := await _drawn(Bikes.path_of(key))
		var axle := _game.bike.get_body_transform(BikeSimulation.FRONT_WHEEL).origin
		var front_calipers := 0
		for caliper in _pieces(view, "caliper", "BoxMesh"):
			var off := caliper.global_position.distance_to(axle)
			front_calipers += int(off < BikeWheels.DISC * _game.bike.get_wheel_radius() + 0.05)
		var spokes := 0
		for wheel in _pieces(view, "rim", "ArrayMesh"):
			spokes = maxi(spokes, wheel.mesh.surface_get_array_len(0))
		seen[key] = {
			calipers = _pieces(view, "caliper", "BoxMesh").size(),
			front_calipers = front_calipers,
			mirrors = _pieces(view, "frame", "SphereMesh").size(),
			spoke_vertices = spokes,
		}
		_game.queue_free()
		_game = null
		await wait_frames(1)
	assert_eq(seen.street_390.front_calipers, 2, "two discs up front on the street 390")
	assert_eq(seen.sport_600.front_calipers, 2, "and on the sport 600")
	assert_eq(seen.dirt_125.front_calipers, 1, "one on the light dirt 125")
	for key: String in seen:
		assert_eq(seen[key].calipers - seen[key].front_calipers, 1, "%s: one at the back" % key)
	assert_eq([seen.street_390.mirrors, seen.sport_600.mirrors], [2, 2], "road bikes' mirrors")
	assert_eq(seen.dirt_125.mirrors, 0, "no mirrors on the dirt bike")
	assert_gt(
		seen.dirt_125.spoke_vertices,
		2 * seen.street_390.spoke_vertices,
		"laced wire spokes on the dirt bike, a few cast ones on the road bikes"
	)


func test_bodywork_that_cannot_be_worn_draws_the_standard_bodywork_with_an_error() -> void:
	var bike := BikeDescription.new()
	bike.bodywork = Resource.new()
	expect_error("not a BikeBodywork")
	assert_eq(BikeBodywork.worn_by(bike).resource_path, BikeBodywork.STANDARD)
	var folded := (load(BikeBodywork.STANDARD) as BikeBodywork).duplicate() as BikeBodywork
	folded.seat = Vector3(0.0, 2.0, 0.0)
	bike.bodywork = folded
	expect_error("key points out of order")
	assert_eq(BikeBodywork.worn_by(bike).resource_path, BikeBodywork.STANDARD)
	bike.bodywork = null
	assert_eq(BikeBodywork.worn_by(bike).resource_path, BikeBodywork.STANDARD, "none named")


func test_a_bike_of_odd_proportions_bends_its_bodywork_without_folding_it() -> void:
	var bodywork := load(BikeBodywork.STANDARD) as BikeBodywork
	var points := bodywork.authored_points()
	# A steering head behind the seat: the tank may not turn inside out.
	points.steering_head = Vector3(-0.4, 1.0, 0.0)
	var back := bodywork.fitted(Vector3(-0.12, 0.94, 0.0), points)
	var front := bodywork.fitted(Vector3(0.4, 0.94, 0.0), points)
	assert_gt(front.x - back.x, 0.0, "the tank's front stays ahead of its back")


func test_a_bike_file_that_is_not_a_bike_rides_the_reference_bike_with_an_error() -> void:
	expect_error("is not a bike description")
	await _drawn("res://tests/fixtures/bikes/missing.tres")
	assert_null(_game.bike.bike, "the reference bike")
	assert_true(_game.bike.is_running())


func test_a_controller_the_bike_does_not_offer_rides_as_arcade_and_says_why() -> void:
	# The pit bike has no learned model of its own: learned is not offered on it.
	Settings.set_value(&"controller", "learned")
	var announced: Array[String] = []
	_game = GAME.instantiate() as Game
	_game.level_path = LEVEL
	_game.bike_path = PIT_BIKE
	(_game.get_node(^"Driver") as BikeDriver).announced.connect(announced.append)
	add_child(_game)
	await wait_physics_frames(2)
	assert_eq(_game.bike.controller, "arcade", "rides with arcade")
	assert_eq(Settings.get_value(&"controller"), "learned", "the player's choice stays saved")
	assert_eq(announced, ["Learned is not offered on this bike: it has no learned model"])


func test_a_rounded_box_has_flat_faces_and_rounded_corners() -> void:
	var vertices: PackedVector3Array = RoundedBox.mesh().surface_get_arrays(0)[Mesh.ARRAY_VERTEX]
	var widest := Vector3.ZERO
	var farthest := 0.0
	for at in vertices:
		widest = widest.max(at.abs())
		farthest = maxf(farthest, at.length())
	assert_almost_eq(widest, Vector3.ONE * 0.5, Vector3.ONE * 1e-3, "a metre each way")
	assert_lt(farthest, sqrt(3.0) / 2.0 - 0.05, "its corners rounded off")
	assert_gt(farthest, 0.6, "squarer than a sphere")


func test_a_ghost_is_see_through_all_over_and_casts_no_shadow() -> void:
	for key: String in Bikes.keys():
		var level := FlatLevel.create()
		var bike := BikeSimulation.new()
		bike.bike = Bikes.description(key)
		level.add_child(bike)
		var view := VisualBikeView.new()
		view.ghost = true
		view.posed_by_recording = true
		view.simulation_path = ^".."
		bike.add_child(view)
		add_child(level)
		await wait_frames(2)
		var pieces := view.find_children("*", "GeometryInstance3D", true, false)
		assert_gt(pieces.size(), 20, "%s: the bike and its rider are drawn" % key)
		for piece: GeometryInstance3D in pieces:
			if not piece.is_visible_in_tree():
				continue
			var where := "%s: %s" % [key, piece.name]
			assert_eq(piece.cast_shadow, GeometryInstance3D.SHADOW_CASTING_SETTING_OFF, where)
			var material := piece.material_override as BaseMaterial3D
			if material == null and piece is MeshInstance3D:
				material = (piece as MeshInstance3D).mesh.surface_get_material(0) as BaseMaterial3D
			assert_not_null(material, where)
			if material != null:
				assert_ne(material.transparency, BaseMaterial3D.TRANSPARENCY_DISABLED, where)
		level.free()
