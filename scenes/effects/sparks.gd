class_name Sparks
extends Node3D
## Sparks where the bike itself, down on its side, slides along the road: read every
## physics frame from the simulation (`BikeSimulation.get_scrapes()`: each scraping body's
## deepest contact and how fast it slides there), so they answer the crash the physics is
## having, not a guess from the speed. More and faster sparks the faster it slides; none
## once it has slowed to SLIDE_SPARKS.

## A scrape throws sparks above this sliding speed (m/s), all it can at FULL_SLIDE.
const SLIDE_SPARKS := 1.0
const FULL_SLIDE := 8.0
## Bodies that may scrape at once (the frame, the fork and its legs, the swingarm).
const EMITTERS := 4
const AMOUNT := 60
const LIFETIME := 0.45
const HOT := Color(1.0, 0.82, 0.35)
const COOLING := Color(1.0, 0.35, 0.05)

## The bike that scrapes.
@export var bike: BikeSimulation

var _emitters: Array[CPUParticles3D] = []


func _ready() -> void:
	for i in EMITTERS:
		var emitter := _make_emitter()
		emitter.name = "Sparks%d" % i
		add_child(emitter)
		_emitters.append(emitter)


func _physics_process(_delta: float) -> void:
	var scrapes: Array[Vector4] = []
	if bike != null and bike.is_running():
		scrapes = bike.get_scrapes()
	follow(scrapes)


## Throws sparks from each of `scrapes` (a point, and its sliding speed as the fourth
## number) that slides fast enough; every other emitter stops.
func follow(scrapes: Array[Vector4]) -> void:
	var used := 0
	for scrape in scrapes:
		if used == EMITTERS or scrape.w <= SLIDE_SPARKS or not is_finite(scrape.w):
			continue
		var emitter := _emitters[used]
		var heat := clampf((scrape.w - SLIDE_SPARKS) / (FULL_SLIDE - SLIDE_SPARKS), 0.0, 1.0)
		emitter.global_position = Vector3(scrape.x, scrape.y, scrape.z)
		emitter.initial_velocity_min = lerpf(1.0, 3.0, heat)
		emitter.initial_velocity_max = lerpf(2.5, 7.0, heat)
		emitter.speed_scale = lerpf(0.6, 1.0, heat)
		emitter.emitting = true
		used += 1
	for i in range(used, EMITTERS):
		_emitters[i].emitting = false


## How many emitters throw sparks now.
func throwing() -> int:
	return _emitters.filter(func(e: CPUParticles3D) -> bool: return e.emitting).size()


## Short bright streaks that fall, cooling from white-yellow to orange (CPU particles, so
## the compatibility renderer draws them on any machine; they light nothing).
func _make_emitter() -> CPUParticles3D:
	var emitter := CPUParticles3D.new()
	emitter.emitting = false
	emitter.amount = AMOUNT
	emitter.lifetime = LIFETIME
	emitter.local_coords = false
	# A puff's or a spark's quad would cast a square shadow.
	emitter.cast_shadow = GeometryInstance3D.SHADOW_CASTING_SETTING_OFF
	var streak := QuadMesh.new()
	streak.size = Vector2(0.03, 0.14)
	var material := StandardMaterial3D.new()
	material.shading_mode = BaseMaterial3D.SHADING_MODE_UNSHADED
	material.billboard_mode = BaseMaterial3D.BILLBOARD_PARTICLES
	material.vertex_color_use_as_albedo = true
	material.transparency = BaseMaterial3D.TRANSPARENCY_ALPHA
	streak.material = material
	emitter.mesh = streak
	emitter.direction = Vector3.UP
	emitter.spread = 75.0
	emitter.gravity = Vector3(0, -9.8, 0)
	emitter.scale_amount_min = 0.6
	emitter.scale_amount_max = 1.4
	var cooling := Gradient.new()
	cooling.set_color(0, HOT)
	cooling.set_color(1, Color(COOLING, 0.0))
	emitter.color_ramp = cooling
	return emitter
