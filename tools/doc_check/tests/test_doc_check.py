"""The doc check on made-up rows and docs: a figure or table that agrees with the rows
passes, one changed by hand fails with both texts, and `update` writes the rows' figure
back; references to missing files, headings and sections fail."""

import csv
import subprocess
import tempfile
import unittest
from pathlib import Path

from cpbp_experiment.configs import Config, Controller
from cpbp_experiment.results import FIELDS, Attempt
from doc_check import experiment_figures, markers, references, scenario_figures, tables
from doc_check.formats import count, format_p, percent_range

ARCADE = Controller("arcade", 0, "exact")
MPPI = Controller("mppi", 10, "exact")


def rows(config: Config, outcomes: str) -> list[Attempt]:
    """One attempt per letter: g reached the goal, f fell."""
    return [Attempt(config, i, 1000 + i, "goal" if o == "g" else "fell", 9.0, 36.0, 270,
                    14.0, 2000.0 + i, platform="p1")
            for i, o in enumerate(outcomes)]


class DocCheckTest(unittest.TestCase):
    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        # At 10 km/h arcade reaches the goal 20 times; MPPI-10 misses the first 12 of them.
        attempts = rows(Config(10, ARCADE), "g" * 20) + rows(Config(10, MPPI), "f" * 12 + "g" * 8)
        with (self.folder / "results.csv").open("w", newline="") as f:
            writer = csv.writer(f, lineterminator="\n")
            writer.writerow(FIELDS)
            writer.writerows(a.row() for a in attempts)
        (self.folder / "scenarios.csv").write_text(
            "scenario,controller,trajectories,seed,physics,fell,metric,planning_ms\n"
            "push,arcade,0,0,exact,true,60.0,0\npush,arcade,0,1,exact,false,20.0,0\n"
            "push,arcade,0,2,exact,false,30.0,0\npush,learned,0,0,exact,false,21.0,0\n"
            "push,learned,0,1,exact,false,19.0,0\npush,learned,0,2,exact,false,31.0,0\n")
        experiment = experiment_figures.ExperimentRows(self.folder)
        self.figures = experiment_figures.figures(experiment)
        self.figures.update(scenario_figures.figures(
            scenario_figures.ScenarioRows(self.folder / "scenarios.csv")))
        self.tables = tables.tables(experiment, self.folder / "scenarios.csv")

    def check(self, text: str) -> list[str]:
        return [p.message for p in markers.check(text, self.figures, self.tables)]

    def test_figures_that_agree_with_the_rows_pass(self):
        doc = ("MPPI-10 reached the goal **8 of 20**<!--= goals mppi-10 10 --> times, "
               "arcade 20/20<!--= cell arcade 10 -->; split 0 to 12<!--= split mppi-10 arcade 10 -->,"
               " 12 to 0<!--= split arcade mppi-10 10 --> (p = 4.9·10⁻⁴<!--= p arcade mppi-10 10 -->), "
               "40 %<!--= rate mppi-10 10 -->, tries: 40<!--= tries arcade,mppi-* -->; shoves "
               "1 in 3<!--= scenario-falls push arcade --> against 0 in 3<!--= scenario-falls push learned -->,"
               " difference 0.00 (−12.71 to 12.71)<!--= scenario-difference push learned arcade -->.")
        self.assertEqual(self.check(doc), [])

    def test_a_figure_changed_by_hand_fails_and_update_restores_it(self):
        right = "MPPI-10 reached the goal **8 of 20**<!--= goals mppi-10 10 --> times."
        wrong = right.replace("8 of 20", "9 of 20")
        problems = self.check(wrong)
        self.assertEqual(len(problems), 1)
        self.assertIn("the rows give '8 of 20', the doc says '9 of 20'", problems[0])
        self.assertEqual(markers.update(wrong, self.figures, self.tables), right)

    def test_a_figure_is_not_the_tail_of_a_longer_number(self):
        right = "shoves 1 in 3<!--= scenario-falls push arcade -->."
        for wrong in ("shoves 11 in 3", "shoves 2.1 in 3"):
            problems = self.check(right.replace("shoves 1 in 3", wrong))
            self.assertEqual(len(problems), 1, wrong)
            self.assertIn("the rows give '1 in 3'", problems[0])
        eleven = right.replace("1 in 3", "11 in 3")
        self.assertEqual(markers.update(eleven, self.figures, self.tables), right)
        # No longer of the figure's form: update will not guess which part to replace.
        with self.assertRaises(markers.FigureError):
            markers.update(right.replace("1 in 3", "2.1 in 3"), self.figures, self.tables)

    def test_a_table_changed_by_hand_fails_and_update_restores_it(self):
        right = ("<!-- figures: success-table -->\n" + tables.success_table(
            experiment_figures.ExperimentRows(self.folder)) + "\n<!-- /figures -->\n")
        self.assertIn("| arcade | 20/20 |", right)
        self.assertIn("| mppi-10 | 8/20 |", right)
        wrong = right.replace("8/20", "18/20")
        self.assertEqual(len(self.check(wrong)), 1)
        self.assertEqual(markers.update(wrong, self.figures, self.tables), right)

    def test_another_bikes_rows_and_their_superseded_rows_are_read_beside_the_table(self):
        header = "scenario,controller,trajectories,seed,physics,fell,metric,planning_ms\n"
        street = self.folder / "street_390"
        (street / "superseded" / "before").mkdir(parents=True)
        (street / "scenarios.csv").write_text(
            header + "push,arcade,0,0,exact,false,1.0,0\npush,arcade,0,1,exact,false,2.0,0\n")
        (street / "superseded" / "before" / "scenarios.csv").write_text(
            header + "push,arcade,0,0,exact,true,9.0,0\n")
        doc = ("0 in 2<!--= scenario-falls push street_390/arcade -->, mean "
               "1.50<!--= scenario-mean push street_390/arcade -->, before 1 in 1<!--= "
               "scenario-falls push street_390/arcade@before -->; the reference 1 in 3<!--= "
               "scenario-falls push arcade -->.")
        self.assertEqual(self.check(doc), [])
        self.assertEqual(len(self.check(doc.replace("0 in 2", "1 in 2"))), 1)

    def test_bikes_pair_up_attempt_by_attempt_with_their_superseded_rows_too(self):
        # A bike whose MPPI-10 missed the first 12 tries before a change and none after.
        before = self.folder / "bike" / "superseded" / "before"
        before.mkdir(parents=True)
        for folder, outcomes in ((before, "f" * 12 + "g" * 8), (self.folder / "bike", "g" * 20)):
            with (folder / "results.csv").open("w", newline="") as f:
                writer = csv.writer(f, lineterminator="\n")
                writer.writerow(FIELDS)
                writer.writerows(a.row() for a in rows(Config(10, MPPI), outcomes))
        doc = ("0 to 12<!--= bike-split bike/superseded/before/mppi-10 bike/mppi-10 10 --> "
               "(p = 4.9·10⁻⁴<!--= bike-p bike/superseded/before/mppi-10 bike/mppi-10 10 -->), "
               "0 to 0<!--= bike-split arcade-bike/arcade bike/mppi-10 10 -->")
        problems = self.check(doc)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("no rows of arcade", problems[0])

    def test_a_run_with_other_settings_pairs_with_the_bikes_at_every_speed(self):
        # Over 10 and 15 km/h the short run misses attempt 0 at 15 alone; attempt 0 at 10
        # pairs with attempt 0 at 10, not with its namesake at 15.
        short = self.folder / "bike" / "horizon" / "short"
        short.mkdir(parents=True)
        for folder, at_15 in ((self.folder / "bike", "g" * 4), (short, "f" + "g" * 3)):
            with (folder / "results.csv").open("w", newline="") as f:
                writer = csv.writer(f, lineterminator="\n")
                writer.writerow(FIELDS)
                writer.writerows(a.row() for a in rows(Config(10, MPPI), "g" * 4)
                                 + rows(Config(15, MPPI), at_15))
        doc = ("7 of 8<!--= bike-goals bike/horizon/short mppi-10 10-15 -->, "
               "0 to 1<!--= bike-split bike/horizon/short/mppi-10 bike/mppi-10 10-15 -->")
        self.assertEqual(self.check(doc), [])

    def test_a_fall_split_pools_the_scenarios_joined_by_a_plus(self):
        # Shoves: arcade fell on seed 0 alone; slalom: arcade on seed 1, learned on seed 2.
        with (self.folder / "scenarios.csv").open("a") as f:
            f.write("slalom,arcade,0,1,exact,true,1.0,0\nslalom,arcade,0,2,exact,false,1.0,0\n"
                    "slalom,learned,0,1,exact,false,1.0,0\nslalom,learned,0,2,exact,true,1.0,0\n")
        self.figures.update(scenario_figures.figures(
            scenario_figures.ScenarioRows(self.folder / "scenarios.csv")))
        doc = ("1 to 0<!--= scenario-fall-split push arcade learned -->, pooled "
               "2 to 1<!--= scenario-fall-split push+slalom arcade learned --> "
               "(p = 1<!--= scenario-fall-p push+slalom arcade learned -->)")
        self.assertEqual(self.check(doc), [])

    def test_unknown_figures_and_missing_rows_are_reported(self):
        self.assertIn("no figure or table called 'goalz'", self.check("8<!--= goalz x -->")[0])
        self.assertIn("no rows of optimizer-5", self.check("1 of 1<!--= goals optimizer-5 10 -->")[0])

    def test_number_formats(self):
        self.assertEqual(count(10000), "10 000")
        self.assertEqual(format_p(0.125), "0.12")
        self.assertEqual(format_p(1.0), "1")
        self.assertEqual(format_p(9.5e-7), "9.5·10⁻⁷")
        self.assertEqual(percent_range(0.981, 1.0), "98.1–100 %")

    def test_references_that_do_not_resolve_fail(self):
        root = Path(tempfile.mkdtemp())
        (root / "docs").mkdir()
        (root / "tools").mkdir()
        (root / "docs/a.md").write_text("# A\n\n## Lean reversals\n\n[b](b.md#nowhere) "
                                        "[self](#lean-reversals) [gone](gone.md)\n")
        (root / "docs/b.md").write_text("# B\n\ndocs/bike+net/r.md, docs/gone+net/r.md\n")
        (root / "docs/bike+net").mkdir()
        (root / "docs/bike+net/r.md").write_text("# R\n")
        (root / "tools/x.sh").write_text("# See docs/a.md, \"Lean\n# reversals\" and "
                                         "docs/a.md, \"Planners\" and tools/y.py.\n")
        subprocess.run(["git", "init", "-q"], cwd=root, check=True)
        found = sorted(b.text() for b in references.check(root))
        self.assertEqual(found, [
            "docs/a.md:5: link to a missing file: gone.md",
            "docs/a.md:5: link to a missing heading: b.md#nowhere",
            "docs/b.md:3: no such file or folder: docs/gone+net/r.md",
            'tools/x.sh:1: docs/a.md has no section "Planners"',
            "tools/x.sh:2: no such file or folder: tools/y.py",
        ])


if __name__ == "__main__":
    unittest.main()
