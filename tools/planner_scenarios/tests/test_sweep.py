import json
import tempfile
import unittest
from pathlib import Path

from planner_scenarios.cli import main
from planner_scenarios.rows import ScenarioRows


def line(scenario, seed, fell, metric, planning_ms, n=5):
    return (f"{scenario},combined,{n},{seed},exact,{'true' if fell else 'false'},{metric},"
            f"{planning_ms},")


def ride(folder: Path, slalom_shift: float, push_falls: int, planning_ms: float,
         settings: dict | None = None, n: int = 5) -> None:
    """Ten seeds of slalom and push; the slalom's error shifted, the first seeds of the
    push fallen, every ride planned in `planning_ms`."""
    folder.mkdir(parents=True)
    rows = ScenarioRows(folder / "scenarios.csv")
    for seed in range(10):
        wobble = 0.01 * ((seed * 7) % 5)
        rows.append(line("slalom", seed, False, 10.0 + slalom_shift + wobble, planning_ms, n))
        rows.append(line("push", seed, seed < push_falls, 12.0 + wobble, planning_ms, n))
    if settings:
        (folder / "settings.json").write_text(json.dumps(settings))


class SweepTest(unittest.TestCase):
    def test_each_folder_is_held_against_the_defaults_with_its_own_holm(self):
        with tempfile.TemporaryDirectory() as tmp:
            base = Path(tmp) / "bike"
            ride(base, 0.0, 0, 10.0)
            ride(base / "horizon" / "alone-0.6", 1.0, 0, 6.0, {"horizon": "0.6"})
            ride(base / "horizon" / "value-0.6", 0.0, 2, 7.0,
                 {"terminal_value": "true", "value_horizon": "0.6"})
            self.assertEqual(main(["sweep", "--out", str(base)]), 0)
            page = (base / "horizon" / "sweep.md").read_text()
        rows = [r for r in page.splitlines() if r.startswith("| horizon=0.6")
                or r.startswith("| terminal_value")]
        self.assertEqual(len(rows), 2)
        alone, value = rows
        # A whole-degree shift on every seed is beyond chance; the push is untouched.
        self.assertIn("| combined-5 | 10 | 0.60 | 0 → 0 | 1 of 4 |", alone)
        self.assertIn("**+1** (p < 0.0001)", alone)
        # Two falls in ten pairs are not beyond chance (McNemar p = 0.5): shown, not bold.
        self.assertIn("| 0.70 | 0 → 2 | 0 of 4 |", value)
        self.assertIn(", falls 0→2", value)
        self.assertNotIn("**falls", value)

    def test_fewer_trajectories_are_held_against_the_defaults_five_when_asked(self):
        with tempfile.TemporaryDirectory() as tmp:
            base = Path(tmp) / "bike"
            ride(base, 0.0, 0, 10.0)
            ride(base / "horizon" / "n4", 0.0, 0, 8.0, n=4)
            self.assertEqual(main(["sweep", "--out", str(base)]), 0)
            alone = (base / "horizon" / "sweep.md").read_text()
            self.assertEqual(main(["sweep", "--out", str(base), "--base-count", "5"]), 0)
            against = (base / "horizon" / "sweep.md").read_text()
        # Without it N = 4 has nothing to pair with; with it, the five's rides.
        self.assertNotIn("| combined-4", alone)
        self.assertIn("| combined-4 (against combined-5) | 10 | 0.80 | 0 → 0 | 0 of 4 |",
                      against)

    def test_no_folder_of_rows_is_an_error_not_an_empty_page(self):
        with tempfile.TemporaryDirectory() as tmp:
            base = Path(tmp) / "bike"
            ride(base, 0.0, 0, 10.0)
            self.assertEqual(main(["sweep", "--out", str(base)]), 2)
            self.assertFalse((base / "horizon" / "sweep.md").exists())


if __name__ == "__main__":
    unittest.main()
