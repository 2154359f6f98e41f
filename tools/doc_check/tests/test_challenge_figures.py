"""The lessons' table and thresholds the docs quote, read from made-up Challenge files as
the game writes them: a threshold changed in a file changes the doc's figure."""

import tempfile
import unittest
from pathlib import Path

from doc_check import challenge_figures, markers, project_figures

CHALLENGE = """[gd_resource type="Resource" script_class="Challenge" load_steps=4 format=3]

[resource]
title = "{title}"
score_name = "{score}"
unit = "{unit}"
lower_is_better = {lower}
bronze = {bronze}
silver = {silver}
gold = {gold}
judge = SubResource("Judge")
"""


class ChallengeFiguresTest(unittest.TestCase):
    def setUp(self):
        self.root = Path(tempfile.mkdtemp())
        lessons = self.root / "scenes/challenges/lessons"
        lessons.mkdir(parents=True)
        (lessons / "stop.tres").write_text(CHALLENGE.format(
            title="Stop", score="distance", unit="m", lower="true", bronze=1.5, silver=0.6,
            gold=0.25), encoding="utf-8")
        (lessons / "bend.tres").write_text(CHALLENGE.format(
            title="The bend", score="lean held", unit="°", lower="false", bronze=30.0,
            silver=38.0, gold=43.0), encoding="utf-8")
        (self.root / challenge_figures.CATALOGUE).write_text(
            '[resource]\nlessons = Array[String](["res://scenes/challenges/lessons/stop.tres", '
            '"res://scenes/challenges/lessons/bend.tres"])\nchallenges = Array[String]([])\n',
            encoding="utf-8")

    def test_the_table_lists_the_lessons_in_order_with_their_thresholds(self):
        self.assertEqual(challenge_figures.table(self.root, "lessons").splitlines()[2:], [
            "| 1. Stop (`stop`) | distance | ≤ 0.25 m | ≤ 0.60 m | ≤ 1.50 m |",
            "| 2. The bend (`bend`) | lean held | ≥ 43.0° | ≥ 38.0° | ≥ 30.0° |"])

    def test_a_quoted_threshold_follows_its_file(self):
        figures = project_figures.figures(self.root)
        doc = "gold needs 0.25 m<!--= medal stop gold --> of the box's middle\n"
        self.assertEqual(markers.check(doc, figures, {}), [])
        stale = doc.replace("0.25 m", "0.30 m")
        self.assertEqual(len(markers.check(stale, figures, {})), 1)
        self.assertEqual(markers.update(stale, figures, {}), doc)

    def test_the_bot_table_has_a_column_a_bike_and_says_why_a_ride_missed(self):
        rides = self.root / challenge_figures.BOT_RIDES
        rides.parent.mkdir(parents=True)
        rides.write_text("challenge,bike,passed,score,medal,why\n"
                         "stop,street_390,true,0.1,gold,\nstop,dirt_125,false,,no medal,"
                         "you stopped 1.2 m past the box\nbend,street_390,true,39.04,silver,\n",
                         encoding="utf-8")
        self.assertEqual(challenge_figures.bot_table(self.root).splitlines(), [
            "| lesson or challenge | street 390 | dirt 125 |", "|---|---|---|",
            "| Stop | gold (0.10 m) | missed: you stopped 1.2 m past the box |",
            "| The bend | silver (39.0°) | – |"])

    def test_an_unknown_challenge_is_an_error(self):
        with self.assertRaises(markers.FigureError):
            challenge_figures.threshold(self.root, "nowhere", "gold")


if __name__ == "__main__":
    unittest.main()
