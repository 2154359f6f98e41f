import math
import tempfile
import unittest
from pathlib import Path

from planner_scenarios.cli import main
from planner_scenarios.timing import paired_ratio, start_timing, summary


def rows(controller: str, planning: list[float], scenario: str = "slalom") -> list[dict]:
    return [{"scenario": scenario, "controller": controller, "trajectories": 5, "seed": seed,
             "planning_ms": ms} for seed, ms in enumerate(planning)]


class TimingTest(unittest.TestCase):
    def test_a_constant_halving_is_a_ratio_of_one_half_with_no_spread(self):
        defaults = rows("combined", [8.0, 10.0, 12.0])
        ratio = paired_ratio(defaults, rows("combined", [4.0, 5.0, 6.0]))
        self.assertAlmostEqual(ratio.ratio, 0.5)
        self.assertAlmostEqual(ratio.low, 0.5)
        self.assertEqual((ratio.pairs, ratio.text()), (3, "0.50 (0.50–0.50)"))

    def test_rides_pair_seed_by_seed_and_a_rider_or_scenario_is_chosen(self):
        defaults = rows("combined", [10.0, 10.0]) + rows("guided", [10.0, 10.0])
        settings = rows("combined", [5.0, 5.0]) + rows("guided", [10.0, 10.0, 3.0])
        self.assertAlmostEqual(paired_ratio(defaults, settings, "guided-5").ratio, 1.0)
        pooled = paired_ratio(defaults, settings)
        self.assertEqual(pooled.pairs, 4, "guided's third seed has no defaults' ride")
        self.assertAlmostEqual(pooled.ratio, math.sqrt(0.5))
        self.assertLess(pooled.low, pooled.ratio)
        with self.assertRaisesRegex(ValueError, "too few"):
            paired_ratio(defaults, settings, scenario="push")

    def test_the_summary_reads_the_folders_files_and_a_new_spell_empties_them(self):
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp)
            defaults, these = start_timing(folder)
            for seed, (base, ms) in enumerate([(10.0, 5.0), (12.0, 6.0)]):
                defaults.append(f"slalom,combined,5,{seed},exact,false,1.0,{base},")
                these.append(f"slalom,combined,5,{seed},exact,false,1.0,{ms},")
            self.assertEqual(summary(folder), ["combined-5: 0.50 (0.50–0.50)",
                                               "all: 0.50 (0.50–0.50) over 2 paired rides"])
            start_timing(folder)
            self.assertFalse(any(folder.iterdir()))

    def test_timing_needs_the_settings_and_named_scenarios(self):
        with tempfile.TemporaryDirectory() as tmp:
            self.assertEqual(main(["time", "--out", tmp, "--scenarios", "slalom"]), 2)
            self.assertEqual(main(["time", "--out", tmp, "--set", "horizon=0.6"]), 2)


if __name__ == "__main__":
    unittest.main()
