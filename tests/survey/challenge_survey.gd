extends TestCase
## The bot's gold rides of every lesson and challenge on every bike a player chooses
## (ChallengeBot), written as rows of a CSV: what each bike scores where the street 390's
## gold pace takes it. Run by tools/challenge-survey.sh; not a test (a bike may miss where
## another earns gold: that is what it measures).
##
## Arguments after `--`: `--out=PATH.csv` (written anew), and `--bike=KEY` for one bike.

const HEADER := "challenge,bike,passed,score,medal,why"


func _ready() -> void:
	var options := {bike = "", out = ""}
	for argument: String in OS.get_cmdline_user_args():
		var parts := argument.trim_prefix("--").split("=", true, 1)
		if parts.size() == 2 and options.has(parts[0]):
			options[parts[0]] = parts[1]
	if options.out.is_empty():
		printerr("usage: -- --out=PATH.csv [--bike=KEY]")
		get_tree().quit(2)
		return
	var bikes: Array[String] = Bikes.keys()
	if not options.bike.is_empty():
		bikes = [options.bike]
	var rows := PackedStringArray([HEADER])
	var catalogue := ChallengeCatalogue.game()
	for bike in bikes:
		for path in catalogue.lessons + catalogue.challenges:
			var challenge := ChallengeCatalogue.load_challenge(path)
			SettingsSandbox.enter()
			var bot := ChallengeBot.new(self, bike)
			rows.append(_row(challenge, bike, await bot.gold_ride(challenge.key())))
			print(rows[-1])
			bot.free_all()
			await wait_frames(1)
	SettingsSandbox.leave()
	var file := FileAccess.open(options.out, FileAccess.WRITE)
	file.store_string("\n".join(rows) + "\n")
	file.close()
	get_tree().quit(0)


static func _row(challenge: Challenge, bike: String, result: ChallengeResult) -> String:
	if result == null:
		return "%s,%s,false,,none,not judged in time" % [challenge.key(), bike]
	var medal := challenge.medal_for(result.score) if result.passed else Challenge.Medal.NONE
	var score := ("%.4f" % result.score) if result.passed else ""
	var why := result.why.replace(",", ";")
	return (
		"%s,%s,%s,%s,%s,%s"
		% [challenge.key(), bike, result.passed, score, Challenge.MEDAL_NAMES[medal], why]
	)
