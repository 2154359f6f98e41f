import tempfile
import unittest
from pathlib import Path

from doc_check import markers, sweep_figures

HEADER = "scenario,controller,trajectories,seed,physics,fell,metric,planning_ms\n"


def ride(folder: Path, n: int, slalom_shift: float, push_falls: int) -> None:
    """Ten seeds of slalom and push by combined-N: the slalom's error shifted, the push
    fallen on its first seeds."""
    folder.mkdir(parents=True, exist_ok=True)
    lines = [HEADER]
    for seed in range(10):
        wobble = 0.01 * ((seed * 7) % 5)
        lines.append(f"slalom,combined,{n},{seed},exact,false,{10 + slalom_shift + wobble},5\n")
        fell = "true" if seed < push_falls else "false"
        lines.append(f"push,combined,{n},{seed},exact,{fell},{12 + wobble},5\n")
    (folder / "scenarios.csv").write_text("".join(lines))


class SweepFiguresTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        root = Path(self.tmp.name)
        ride(root / "bike", 5, 0.0, 0)
        ride(root / "bike" / "horizon" / "short", 5, 1.0, 0)
        ride(root / "bike" / "horizon" / "fewer", 4, 0.0, 2)
        ride(root / "bike" / "horizon" / "superseded" / "value-old" / "short", 5, 1.0, 0)
        self.figures = sweep_figures.figures(root)

    def tearDown(self):
        self.tmp.cleanup()

    def check(self, text: str) -> list[str]:
        return [p.message for p in markers.check(text, self.figures, {})]

    def test_a_folder_is_held_against_the_bike_two_folders_up(self):
        # A whole degree on every seed is one test of four beyond chance, quoted signed.
        doc = ("1 of 4<!--= sweep-beyond bike/horizon/short combined-5 --> "
               "(slalom +1<!--= sweep-shift bike/horizon/short combined-5 slalom -->, push "
               "+0<!--= sweep-shift bike/horizon/short combined-5 push -->)")
        self.assertEqual(self.check(doc), [])
        wrong = doc.replace("slalom +1", "slalom +0.9").replace("1 of 4", "0 of 4")
        self.assertEqual(len(self.check(wrong)), 2)
        self.assertEqual(markers.update(wrong, self.figures, {}), doc)

    def test_a_folder_moved_aside_is_held_against_the_bike_above_it(self):
        doc = "1 of 4<!--= sweep-beyond bike/horizon/superseded/value-old/short combined-5 -->"
        self.assertEqual(self.check(doc), [])

    def test_fewer_trajectories_pair_with_the_defaults_only_when_asked(self):
        doc = "0 of 4<!--= sweep-beyond bike/horizon/fewer combined-4 5 -->"
        self.assertEqual(self.check(doc), [])
        problems = self.check(doc.replace(" 5 -->", " -->"))
        self.assertEqual(len(problems), 1)
        self.assertIn("holds no combined-4", problems[0])

    def test_falls_pool_every_ride_of_the_folders_named(self):
        doc = ("0 in 40<!--= sweep-falls bike/horizon/short,bike -->, "
               "2 in 20<!--= sweep-falls bike/horizon/fewer -->")
        self.assertEqual(self.check(doc), [])
        self.assertIn("no scenario rows",
                      self.check("0 in 1<!--= sweep-falls bike/horizon/none -->")[0])

    def test_falls_of_one_rider_in_one_scenario(self):
        doc = ("2 in 10<!--= sweep-falls bike/horizon/fewer combined-4 push -->, "
               "0 in 10<!--= sweep-falls bike/horizon/fewer combined-4 slalom -->, "
               "2 in 20<!--= sweep-falls bike/horizon/fewer combined-4 -->")
        self.assertEqual(self.check(doc), [])
        self.assertIn("no rides of combined-5",
                      self.check("0 in 1<!--= sweep-falls bike/horizon/fewer combined-5 -->")[0])


    def test_timing_is_the_paired_ratio_of_the_folders_timing_rows(self):
        folder = Path(self.tmp.name) / "bike" / "horizon" / "short"
        for name, ms in (("timing-defaults.csv", 10.0), ("timing-settings.csv", 4.0)):
            ride(folder / "t", 5, 0.0, 0)
            text = (folder / "t" / "scenarios.csv").read_text().replace(",5\n", f",{ms}\n")
            (folder / name).write_text(text)
        doc = "0.40 (0.40–0.40)<!--= sweep-timing bike/horizon/short combined-5 -->"
        self.assertEqual(self.check(doc), [])
        self.assertIn("no timing rows",
                      self.check("0.4 (0.4–0.4)<!--= sweep-timing bike/horizon/fewer -->")[0])


if __name__ == "__main__":
    unittest.main()
