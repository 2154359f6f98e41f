import dataclasses
import tempfile
import unittest
from pathlib import Path

from cpbp_experiment import report
from cpbp_experiment.configs import Config, Controller
from cpbp_experiment.results import Attempt

ARCADE = Controller("arcade")
COMBINED = Controller("combined", 5)


def attempts(config: Config, goals: int, fell: int, timeouts: int = 0) -> list[Attempt]:
    outcomes = ["goal"] * goals + ["fell"] * fell + ["timeout"] * timeouts
    return [Attempt(config, i, 1000 + i, outcome, 9.0 if outcome == "goal" else 4.0, 36.0,
                    270, 0.0 if config.controller == ARCADE else 14.0, 2000.0)
            for i, outcome in enumerate(outcomes)]


class ReportTest(unittest.TestCase):
    def setUp(self):
        self.attempts = (attempts(Config(10, ARCADE), 81, 180, 2)
                         + attempts(Config(10, COMBINED), 15, 133)
                         + attempts(Config(25, COMBINED), 29, 0))
        self.summaries = report.summarise(self.attempts)

    def test_counts_and_wilson_intervals_in_the_table(self):
        table = report.success_table(self.summaries)
        self.assertIn("**30.8 %** (25.5–36.6) 81/263", table)  # Newcombe's 81/263
        self.assertIn("**10.1 %** (6.2–16.0) 15/148", table)
        self.assertIn("**100.0 %** (88.3–100.0) 29/29", table)
        self.assertIn("| arcade | **30.8 %** (25.5–36.6) 81/263 | – |", table)

    def test_outcomes_widths_and_costs(self):
        outcomes = report.outcome_table(self.summaries)
        self.assertIn("| arcade | 10 km/h | 263 | 81 | 180 | 2 | 11.1 pp | 9.00 s | 2.00 s |",
                      outcomes)
        costs = report.cost_table(self.summaries, self.attempts)
        self.assertIn("| combined-5 | 177 | 2.00 s | 2.00 s |", costs)
        self.assertIn("14.0 ms |", costs)

    def test_a_try_slowed_by_a_busy_machine_moves_the_mean_not_the_median(self):
        tries = attempts(Config(15, COMBINED), 3, 0)
        tries[2] = dataclasses.replace(tries[2], wall_ms=14000.0)  # beside a CI run: 7 times
        costs = report.cost_table(report.summarise(tries), tries)
        self.assertIn("| combined-5 | 3 | 6.00 s | 2.00 s |", costs)

    def test_paired_comparison_counts_the_same_attempts(self):
        paired = report.paired_table(self.attempts)
        # Attempts 0–147 of both at 10 km/h: combined reached the goal on 0–14, arcade
        # on 0–80, so arcade alone on 15–80 and neither on 81–147.
        self.assertIn("| 10 km/h | combined-5 | arcade | 148 | 15 | 0 | 66 | 67 | 2.7e-20 | **",
                      paired)
        self.assertNotIn("25 km/h", paired, "no arcade attempts at 25 km/h to pair with")

    def test_a_controller_in_the_exact_physics_pairs_with_itself_in_the_classic(self):
        exact = COMBINED.in_physics("exact")
        paired = report.paired_table(self.attempts + attempts(Config(25, exact), 20, 9))
        # Attempts 0–28 at 25 km/h: classic reached the goal on all, exact on 0–19.
        self.assertIn("| 25 km/h | combined-5:exact | combined-5 | 29 | 20 | 0 | 9 | 0 | 0.0039 | "
                      "**", paired)
        self.assertNotIn("| 25 km/h | combined-5:exact | arcade", paired,
                         "no exact arcade attempts to pair with")

    def test_a_baseline_pairs_with_both_cpbp_planners_at_its_n(self):
        mppi = Controller("mppi", 5)
        paired = report.paired_table(self.attempts + attempts(Config(25, mppi), 25, 4))
        # Attempts 0–28 at 25 km/h: combined-5 reached the goal on all, MPPI on 0–24.
        self.assertIn("| 25 km/h | mppi-5 | combined-5 | 29 | 25 | 0 | 4 | 0 | 0.12 | 0.12 |",
                      paired)
        self.assertNotIn("| 25 km/h | mppi-5 | optimizer-5", paired, "no optimizer rows")

    def test_holm_holds_the_family_of_paired_tests_to_five_percent(self):
        # Six attempts of arcade alone against combined-5 (p = 2/64 = 0.031) is
        # significant on its own; two such tests are not once corrected (2 · 0.031).
        one = attempts(Config(20, ARCADE), 6, 0) + attempts(Config(20, COMBINED), 0, 6)
        self.assertIn("| 6 | 0 | 0 | 6 | 0 | 0.031 | **0.031** |", report.paired_table(one))
        two = one + attempts(Config(15, ARCADE), 6, 0) + attempts(Config(15, COMBINED), 0, 6)
        paired = report.paired_table(two)
        self.assertIn("| 15 km/h | combined-5 | arcade | 6 | 0 | 0 | 6 | 0 | 0.031 | 0.062 |",
                      paired)
        self.assertIn("| 20 km/h | combined-5 | arcade | 6 | 0 | 0 | 6 | 0 | 0.031 | 0.062 |",
                      paired)

    def test_controller_labels_name_the_physics_and_parse_back(self):
        for label in ("arcade", "arcade:exact", "combined-15:exact", "optimizer-5",
                      "sampling-10:exact", "mppi-64"):
            self.assertEqual(Controller.parse(label).label, label)
        self.assertEqual(Controller.parse("combined-5:classic"), COMBINED)
        with self.assertRaisesRegex(ValueError, "unknown physics 'fast'"):
            Controller.parse("combined-5:fast")

    def test_charts_are_written(self):
        with tempfile.TemporaryDirectory() as directory:
            success = Path(directory) / "success.png"
            report.success_chart(self.summaries, success)
            timing = [{"controller": k, "trajectories": n, "mean_ms": 2.0 * n,
                       "median_ms": 2.0 * n, "p95_ms": 2.5 * n}
                      for k in ("optimizer", "combined") for n in (5, 10, 20)]
            planning = Path(directory) / "planning.png"
            report.planning_chart(timing, "test machine", planning)
            for path in (success, planning):
                self.assertEqual(path.read_bytes()[:4], b"\x89PNG")
            table = report.timing_table(timing)
            self.assertIn("| 20 | 40.0 / 50.0 | 40.0 / 50.0 | 25 Hz | 25 Hz | no |", table)
            self.assertIn("| 10 | 20.0 / 25.0 | 20.0 / 25.0 | 50 Hz | 50 Hz | yes |", table)


if __name__ == "__main__":
    unittest.main()
