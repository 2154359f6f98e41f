class_name VisualBikeView
extends Node3D
## The bike and rider as the player sees them (thesis §4.2): a stylised naked motorcycle
## built from primitive meshes, each authored in the bike's frame at rest (BikeRestFrame)
## and carried by its simulated body, and the skinned rider posed on the rider's bodies
## by IK (RiderFigure).

const WHEELS: Array[int] = [BikeSimulation.REAR_WHEEL, BikeSimulation.FRONT_WHEEL]
const FORK := BikeSimulation.FORK
const FRAME := BikeSimulation.FRAME
const FORK_LOWER := BikeSimulation.FORK_LOWER
const SWINGARM := BikeSimulation.SWINGARM
const LOWER_ARM := BikeSimulation.LOWER_ARM
const BIKE_FORWARD := BikeRestFrame.FORWARD
const BIKE_DOWN := BikeRestFrame.DOWN

## The simulation to draw; by default the parent.
@export var simulation_path: NodePath = ^".."
## Posed by `show_pose` (a ghost, a replay) instead of following the simulation, which
## then only gives the shapes and the rest pose.
@export var posed_by_recording := false
## Drawn see-through (a ghost).
@export var ghost := false
## The rider drawn in the stance a rider takes (RiderStance: tucked, hanging off, standing);
## off, the drawn rider is the simulated one alone.
@export var stance_drawn := true

## The physical_model setting (the game sets it by name): the physical view is drawn
## instead of this one.
var physical_model := false:
	set(value):
		physical_model = value
		visible = not value

var _simulation: BikeSimulation
## The bike as it stood when its drawing was built.
var _frame: BikeRestFrame
## The drawn bike's pieces, each on its body.
var _parts: BikeParts
## Centre of the grips (bike frame), where the simulated hand holds the bar.
var _grip := Vector3.ZERO
## The rear shock's coil, stretched between its mounts every frame: its mounts on the
## frame and on the swingarm (each in its body's frame) and its length at rest.
var _shock: MeshInstance3D
var _shock_mounts: Array[Vector3] = []
var _shock_rest_length := 1.0
## One stanchion (on the fork) and the lower leg it slides in, to measure the drawn fork.
var _stanchion: Node3D
var _fork_leg: Node3D
var _rider: RiderFigure
## The bike's paint (BikeDescription.paint).
var _paint := Color.WHITE
## The bike's bodywork, whose rider's style (tuck, hang off, stand) the stance follows.
var _bodywork: BikeBodywork
var _stance := RiderStance.new()


func _ready() -> void:
	_simulation = get_node_or_null(simulation_path) as BikeSimulation
	if _simulation != null and not _simulation.is_node_ready():
		await _simulation.ready
	if _simulation == null or not _simulation.is_running():
		push_error("VisualBikeView: no running BikeSimulation at %s" % simulation_path)
		set_process(false)
		return
	_frame = BikeRestFrame.new(_simulation)
	_grip = _frame.capsule_ends(LOWER_ARM, -BIKE_FORWARD)[1]
	var bike: BikeDescription = _simulation.bike if _simulation.bike else BikeDescription.new()
	_paint = bike.paint
	var bodywork := BikeBodywork.worn_by(bike)
	_parts = BikeParts.new(_frame, self, _paint, ghost)
	BikeWheels.build(_parts, _simulation.get_wheel_radius(), bodywork)
	_bodywork = bodywork
	_build_bodywork(bodywork)
	_build_swingarm()
	_build_fork(bodywork)
	_rider = RiderFigure.new()
	_rider.name = "Rider"
	_rider.ghost = ghost
	_rider.paint = _paint
	_rider.gear = bodywork.gear
	add_child(_rider)
	_rider.build(_frame)
	follow()


func _process(_delta: float) -> void:
	if visible and not posed_by_recording:
		follow()


## Puts every piece on the bodies at `bodies` (global transforms, in body order), the
## rider's feet put down on the road at `feet_down` (see RiderFigure.pose).
func show_pose(bodies: Array[Transform3D], feet_down: Array[Dictionary] = []) -> void:
	if posed_by_recording:
		var frame := bodies[FRAME]
		_stance.advance_recorded(
			get_process_delta_time(), _bodywork, frame.origin, _frame.lean_of(frame)
		)
	_rider.pose(bodies, feet_down, _stance if stance_drawn else null)
	_parts.place(bodies)
	# The coil between its mounts: it shortens as the swingarm rises.
	var top := bodies[FRAME] * _shock_mounts[0]
	var bottom := bodies[SWINGARM] * _shock_mounts[1]
	var stretch := top.distance_to(bottom) / _shock_rest_length
	var basis := BikeParts.basis_with_y((top - bottom).normalized(), _frame.right())
	_shock.global_transform = Transform3D(
		basis.scaled_local(Vector3(1, stretch, 1)), (top + bottom) / 2.0
	)


## Poses the drawing on the simulation now (it does so every frame by itself).
func follow() -> void:
	# One native call per body, not per piece: some sixty pieces ride on eleven bodies.
	var bodies: Array[Transform3D] = []
	for body in _simulation.get_body_count():
		bodies.append(_simulation.get_body_transform(body))
	_stance.advance_riding(get_process_delta_time(), _bodywork, _simulation)
	show_pose(bodies, feet_down_of(_simulation))


## How the drawn rider holds themself now (tucked, hanging off, standing).
func stance() -> RiderStance:
	return _stance


## The feet the rider of `simulation` has put down that stand on the road (or on the side
## the bike leans to, about to): each {side, sole (world), up}, as `show_pose` takes them.
## Recordings keep them with the bodies.
static func feet_down_of(simulation: BikeSimulation) -> Array[Dictionary]:
	var down: Array[Dictionary] = []
	var feet := simulation.get_feet()
	var frame := simulation.get_body_transform(FRAME)
	var lean := simulation.get_lean()
	for i in feet.size():
		var side := -1.0 if i == 0 else 1.0
		var foot: BikeFoot = feet[i]
		if foot.down and (foot.on_ground or lean * side > 0.0):
			down.append(
				{side = side, sole = frame * foot.on_frame, up = frame.basis.y.normalized()}
			)
	return down


## How long the fork is drawn now (m, from the middle of a lower leg up its axis to the
## middle of its stanchion): it shortens by as much as the simulated fork compresses.
func drawn_fork_length() -> float:
	var up := _fork_leg.global_basis.y.normalized()
	return (_stanchion.global_position - _fork_leg.global_position).dot(up)


## Whether the rider's leg on `side` (−1 left, 1 right) is drawn down to the road.
func is_leg_down(side: float) -> bool:
	return _rider.is_leg_down(side)


## The drawn rider.
func rider() -> RiderFigure:
	return _rider


## Where the rider's eyes are now (global), inside the helmet: a camera there leaves out
## RiderFigure.HEAD_LAYER.
func eye_point() -> Vector3:
	return _rider.eye_point()


## How long the rear shock's coil is drawn now (m, between its mounts).
func drawn_shock_length() -> float:
	return _shock.global_transform.basis.y.length() * _shock_rest_length


## The bodywork on the frame (engine, tank, seat, tail, frame rails, exhaust), from the
## bike's description, fitted to this bike's size.
func _build_bodywork(bodywork: BikeBodywork) -> void:
	var points := _frame.key_points()
	for piece: BodyworkPiece in bodywork.pieces:
		var sides: Array[float] = [1.0]
		if piece.mirrored:
			sides.append(-1.0)
		for side in sides:
			var mirror := Vector3(1.0, 1.0, side)
			if piece.shape == BodyworkPiece.Shape.ROD:
				var a := bodywork.fitted(piece.from * mirror, points)
				var b := bodywork.fitted(piece.to * mirror, points)
				_parts.rod(FRAME, a, b, piece.radius, piece.look)
				continue
			var block := bodywork.fitted_block(piece.from * mirror, piece.size, piece.pitch, points)
			match piece.shape:
				BodyworkPiece.Shape.ELLIPSOID:
					_parts.unit_shape(FRAME, BikeParts.unit_sphere(), block, piece.look)
				BodyworkPiece.Shape.ROUNDED:
					_parts.unit_shape(FRAME, RoundedBox.mesh(), block, piece.look)
				_:
					_parts.box(FRAME, block.centre, block.size, block.pitch, piece.look)


## The swingarm's two arms from the pivot to the axle, and the rear shock from the frame
## to the swingarm: its coil is stretched between the mounts every frame.
func _build_swingarm() -> void:
	var pivot_axle := _frame.capsule_ends(SWINGARM, BIKE_FORWARD)
	var pivot: Vector3 = pivot_axle[0]
	var axle := _frame.bike_of(_frame.rest_of(BikeSimulation.REAR_WHEEL).origin)
	for side: float in [-1.0, 1.0]:
		_parts.rod(
			SWINGARM,
			pivot + Vector3(0, 0, side * 0.1),
			axle + Vector3(0, 0, side * 0.1),
			0.03,
			"frame"
		)
	_parts.rod(SWINGARM, pivot + Vector3(0, 0, -0.1), pivot + Vector3(0, 0, 0.1), 0.035, "frame")
	_build_chain(pivot, axle)
	# A monoshock under the seat: from the frame to a third of the way along the arm.
	var bottom := pivot.lerp(axle, 0.35) + Vector3(0, 0.04, 0)
	var top := pivot + Vector3(-0.12, 0.36, 0)
	_parts.rod(FRAME, top, top.lerp(bottom, 0.45), 0.03, "metal")
	_parts.rod(SWINGARM, bottom, bottom.lerp(top, 0.5), 0.012, "metal")
	var coil := CylinderMesh.new()
	coil.top_radius = 0.045
	coil.bottom_radius = 0.045
	_shock_rest_length = top.distance_to(bottom) * 0.6
	coil.height = _shock_rest_length
	_shock = MeshInstance3D.new()
	_shock.mesh = coil
	BikeLooks.dress(_shock, "spring", Color(0, 0, 0, 0), ghost)
	_shock.top_level = true
	_shock.name = "shock_spring"
	add_child(_shock)
	_shock_mounts = [
		_frame.rest_of(FRAME).affine_inverse() * _frame.world_of(top),
		_frame.rest_of(SWINGARM).affine_inverse() * _frame.world_of(bottom),
	]


## The final drive on the left: a sprocket on the gearbox's shaft at the swingarm's pivot,
## one on the rear wheel (turning with it), and the chain's two runs between them, which
## swing with the arm.
func _build_chain(pivot: Vector3, axle: Vector3) -> void:
	var left := Vector3(0, 0, -0.13)
	var sprockets := {
		FRAME: [pivot + Vector3(0.06, 0.0, 0.0), 0.045], BikeSimulation.REAR_WHEEL: [axle, 0.09]
	}
	for body: int in sprockets:
		_parts.disc(body, sprockets[body][0] + left, sprockets[body][1], 0.012, "chain")
	var front: Vector3 = sprockets[FRAME][0] + left
	for run: float in [-1.0, 1.0]:
		_parts.rod(
			SWINGARM,
			front + Vector3(0, run * 0.045, 0),
			axle + left + Vector3(0, run * 0.09, 0),
			0.008,
			"chain"
		)


## The fork: stanchions on the steered part slide into the lower legs, which carry the
## axle and the mudguard, so the fork visibly compresses; up front what the bodywork puts
## there (`BikeBodywork.fork_front`, `high_mudguard`).
func _build_fork(bodywork: BikeBodywork) -> void:
	var axle := _frame.bike_of(_frame.rest_of(BikeSimulation.FRONT_WHEEL).origin)
	var lower_top: Vector3 = _frame.capsule_ends(FORK_LOWER, BIKE_DOWN)[1]
	var stanchions := _frame.capsule_ends(FORK, BIKE_DOWN)
	var top: Vector3 = stanchions[1]
	for side: float in [-1.0, 1.0]:
		var out := Vector3(0, 0, side * 0.09)
		_stanchion = _parts.rod(FORK, stanchions[0] + out, top + out, 0.022, "metal")
		_fork_leg = _parts.rod(FORK_LOWER, axle + out, lower_top + out, 0.032, "frame")
		_parts.rod(
			FORK,
			top + Vector3(-0.04, 0.04, side * 0.06),
			Vector3(_grip.x, _grip.y, side * 0.33),
			0.016,
			"frame"
		)
	_parts.rod(
		FORK, Vector3(_grip.x, _grip.y, -0.38), Vector3(_grip.x, _grip.y, 0.38), 0.015, "frame"
	)
	for side: float in [-1.0, 1.0]:
		_parts.rod(
			FORK,
			Vector3(_grip.x, _grip.y, side * 0.3),
			Vector3(_grip.x, _grip.y, side * 0.4),
			0.022,
			"rubber"
		)
	_parts.box(FORK, top + Vector3(0.0, -0.02, 0.0), Vector3(0.08, 0.05, 0.24), 0.0, "frame")
	if bodywork.mirrors:
		for side: float in [-1.0, 1.0]:
			# A stalk up and out from inside the grip, a mirror's head on it facing back.
			var foot := Vector3(_grip.x - 0.02, _grip.y + 0.02, side * 0.25)
			var head := foot + Vector3(-0.02, 0.2, side * 0.08)
			_parts.rod(FORK, foot, head, 0.007, "frame")
			var block := {
				centre = head + Vector3(0, 0.03, side * 0.02),
				size = Vector3(0.03, 0.07, 0.12),
				pitch = 0.0
			}
			_parts.unit_shape(FORK, BikeParts.unit_sphere(), block, "frame")
	match bodywork.fork_front:
		"lamp":
			var lamp := SphereMesh.new()
			lamp.radius = 0.085
			lamp.height = 0.15
			var at := _frame.world_of(top + Vector3(0.14, -0.12, 0.0))
			_parts.add(FORK, lamp, "lamp", Transform3D(_frame.basis(), at))
		"number_board":
			# Leaning back with the fork, ahead of the clamps and the bar.
			_parts.box(
				FORK, top + Vector3(0.17, -0.16, 0.0), Vector3(0.02, 0.24, 0.26), 0.4, "plate"
			)
	var radius := _simulation.get_wheel_radius()
	if bodywork.high_mudguard:
		# On the bottom clamp, clear of the tyre by the travel: a blade reaching forward.
		var clamp := axle + Vector3(0.03, radius + 0.13, 0.0)
		_parts.box(FORK, clamp, Vector3(0.5, 0.03, 0.13), -0.1, "paint")
	else:
		# The mudguard a few centimetres above the tyre, whatever its size.
		var mudguard := axle + Vector3(0.0, radius + 0.05, 0.0)
		_parts.box(FORK_LOWER, mudguard, Vector3(0.3, 0.03, 0.14), 0.0, "paint")
