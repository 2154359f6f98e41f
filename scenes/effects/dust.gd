class_name Dust
extends Node3D
## Dust thrown up behind a tyre rolling over dirt (a `DirtPatch`): read every physics frame
## from the simulation (each tyre's contact and slide, whether it is on the ground, the
## bike's speed), thicker and faster the faster the bike goes and the harder the tyre
## slides. None on asphalt, grass or concrete, none from a wheel in the air.

## Rolling faster than this (m/s) over dirt raises dust; at FULL_SPEED all it can.
const DUST_SPEED := 2.0
const FULL_SPEED := 15.0
## A tyre sliding this fast (m/s) throws as much as one at FULL_SPEED.
const FULL_SLIDE := 4.0

## The bike whose tyres raise the dust.
@export var bike: BikeSimulation

var _clouds: Array[CPUParticles3D] = []


func _ready() -> void:
	for wheel in 2:
		var cloud := Puffs.cloud(Puffs.DUST)
		cloud.name = "Dust%d" % wheel
		add_child(cloud)
		_clouds.append(cloud)


func _physics_process(_delta: float) -> void:
	if bike == null or not bike.is_running():
		follow([], [false, false], 0.0, [false, false])
		return
	var tyres := bike.get_tyres()
	var on_dirt: Array[bool] = []
	for tyre in tyres:
		on_dirt.append(DirtPatch.on_dirt(get_tree(), Vector3(tyre.x, tyre.y, tyre.z)))
	var grounded: Array[bool] = [bike.is_rear_wheel_grounded(), bike.is_front_wheel_grounded()]
	follow(tyres, grounded, absf(bike.get_speed()), on_dirt)


## Raises dust from each of `tyres` (contact, and slide speed as the fourth number; rear
## then front) that is `grounded` and `on_dirt` while the bike rolls at `speed` (m/s).
func follow(
	tyres: Array[Vector4], grounded: Array[bool], speed: float, on_dirt: Array[bool]
) -> void:
	for wheel in 2:
		var cloud := _clouds[wheel]
		var raising := (
			wheel < tyres.size()
			and wheel < on_dirt.size()
			and on_dirt[wheel]
			and grounded[wheel]
			and is_finite(speed)
		)
		var strength := 0.0
		if raising:
			var tyre := tyres[wheel]
			var rolling := (speed - DUST_SPEED) / (FULL_SPEED - DUST_SPEED)
			var sliding := tyre.w / FULL_SLIDE if is_finite(tyre.w) else 0.0
			strength = clampf(maxf(rolling, sliding), 0.0, 1.0)
			cloud.global_position = Vector3(tyre.x, tyre.y, tyre.z)
		cloud.emitting = strength > 0.0
		if cloud.emitting:
			cloud.initial_velocity_max = lerpf(0.6, 2.5, strength)
			cloud.scale_amount_max = lerpf(1.0, 2.2, strength)


## Whether wheel `wheel` (0 rear, 1 front) raises dust now.
func raising(wheel: int) -> bool:
	return _clouds[wheel].emitting
