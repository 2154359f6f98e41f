class_name Bikes
extends RefCounted
## The bikes a player chooses from: the choices of the native `bike` setting, each a
## BikeDescription file of that name in scenes/bike/bikes/ (the thesis's street_350 there
## is the research's reference bike, not a choice).

const FOLDER := "res://scenes/bike/bikes"
## The bike whose best laps and ghosts were saved before there was a choice of bikes:
## its records keep their old keys, so a player's best lap and ghost from then stay theirs.
const FIRST_BIKE := "street_390"


## The bikes' keys, in the order menus offer them.
static func keys() -> Array[String]:
	var keys: Array[String] = []
	for key: String in Settings.schema_entry(&"bike").get("choices", PackedStringArray()):
		keys.append(key)
	return keys


## Path of bike `key`'s file.
static func path_of(key: String) -> String:
	return FOLDER.path_join(key + ".tres")


## Bike `key` as described, or null with an error saying why: no such bike, a file that is
## not a bike, or a bike the core cannot build (naming the bike and the field).
static func description(key: String) -> BikeDescription:
	var path := path_of(key)
	if not keys().has(key) or not ResourceLoader.exists(path, "BikeDescription"):
		push_error("Bikes: no bike is called %s" % key)
		return null
	var bike := load(path) as BikeDescription
	if bike == null:
		push_error("Bikes: %s is not a bike description" % path)
		return null
	if not bike.problem().is_empty():
		push_error("Bikes: %s cannot be built: %s" % [key, bike.problem()])
		return null
	return bike


## The bikes that can be ridden, by key, in the menus' order (a broken one left out, with
## the error `description` gives).
static func rideable() -> Array[String]:
	var keys: Array[String] = []
	for key: String in keys():
		if description(key) != null:
			keys.append(key)
	return keys


## The chosen bike's file: the settings' choice, or, where that cannot be built (its
## error names the bike and the field), the first bike that can.
static func chosen_path() -> String:
	var chosen := str(Settings.get_value(&"bike"))
	if description(chosen) != null:
		return path_of(chosen)
	var can_ride := rideable()
	if can_ride.is_empty():
		push_error("Game: no bike can be built; riding the reference bike")
		return ""
	push_error("Game: %s cannot be ridden; riding %s" % [chosen, can_ride[0]])
	return path_of(can_ride[0])


## The bike described at `path`, or none (the reference bike) with an error saying why.
static func load_description(path: String) -> BikeDescription:
	var found := (
		load(path) as BikeDescription if ResourceLoader.exists(path, "BikeDescription") else null
	)
	if found == null:
		push_error("Game: %s is not a bike description; riding the reference bike" % path)
	return found


## The key best laps and ghosts of `level_key` ridden on bike `key` are saved under.
static func record_key(level_key: String, key: String) -> String:
	return level_key if key == FIRST_BIKE else "%s@%s" % [level_key, key]


## `bike`'s name for people (null: the reference bike the scene carries).
static func name_of(bike: BikeDescription) -> String:
	return bike.name if bike != null else "Street 350"


## `bike`'s name and its main figures, as the pause menu shows them.
static func summary_text(bike: BikeDescription) -> String:
	if bike == null:
		return name_of(bike)
	return "%s   ·   %s" % [name_of(bike), figures_text(bike)]


## A line of `bike`'s main figures for a menu: "94 kg · 26.7 kW · 38.5° lean · 315 mm
## travel" (the power where the bike has a limit).
static func figures_text(bike: BikeDescription) -> String:
	var figures: Dictionary = bike.figures()
	if figures.is_empty():
		return ""
	var parts := ["%d kg" % roundi(figures.mass_kg)]
	if figures.power_kw > 0.0:
		parts.append("%s kW" % Settings.number_text(snappedf(figures.power_kw, 0.1)))
	parts.append("%s° lean" % Settings.number_text(snappedf(figures.max_lean_deg, 0.1)))
	parts.append("%d mm travel" % roundi(maxf(figures.front_travel_mm, figures.rear_travel_mm)))
	return " · ".join(parts)
