class_name Assists
extends RefCounted
## The assist levels a player chooses (the `assist` setting): each a named set of the
## game's settings and the bike's aids, from the most help to the least. Choosing one sets
## them (`apply`); the Lab may still change each alone. The pause menu's table and the
## README's (tests/game/test_assists.gd holds it equal) are made from LEVELS. Whatever the
## level, the rider puts a foot down at a stop.

## Each level: its name for people, who balances (a controller of the registry), ABS, the
## share of the bike's lean the stick may ask for, and a line on what it means.
const LEVELS := {
	"learner":
	{
		name = "Learner",
		controller = "combined",
		abs = true,
		lean_share = 0.75,
		about =
		"the most help: the game balances the bike and leans it three quarters of its limit",
	},
	"full":
	{
		name = "Full",
		controller = "combined",
		abs = true,
		lean_share = 1.0,
		about = "the game balances the bike for you, to its limit; ABS stops it standing",
	},
	"standard":
	{
		name = "Standard",
		controller = "arcade",
		abs = true,
		lean_share = 1.0,
		about = "a simpler balance: it can let the bike fall in long hard bends",
	},
	"pro":
	{
		name = "Pro",
		controller = "arcade",
		abs = false,
		lean_share = 1.0,
		about = "no ABS: a full brake at speed can throw you over the bar",
	},
}


## Sets the settings assist `level` stands for (an unknown level: nothing, with an error).
static func apply(level: String) -> void:
	if not LEVELS.has(level):
		push_error("Assists: no assist level is called %s" % level)
		return
	var aids: Dictionary = LEVELS[level]
	Settings.set_value(&"controller", aids.controller)
	Settings.set_value(&"abs", aids.abs)
	Settings.set_value(&"lean_share", aids.lean_share)


## One line a level, as the pause menu shows them: "Full: the planners balance …".
static func summary() -> String:
	var lines := PackedStringArray()
	for level: String in LEVELS:
		lines.append("%s: %s." % [LEVELS[level].name, LEVELS[level].about])
	return "\n".join(lines)


## The README's table of the levels: who balances, ABS, the lean the stick asks for.
static func markdown_table() -> String:
	var lines := PackedStringArray(
		[
			"| assist | who balances | ABS | the lean the stick asks for | what it means |",
			"|---|---|---|---|---|",
		]
	)
	for level: String in LEVELS:
		var aids: Dictionary = LEVELS[level]
		(
			lines
			. append(
				(
					"| %s | %s | %s | %d %% of the bike's | %s |"
					% [
						aids.name,
						NativeModule.controller_label(aids.controller),
						"on" if aids.abs else "off",
						roundi(aids.lean_share * 100.0),
						aids.about,
					]
				)
			)
		)
	return "\n".join(lines)
