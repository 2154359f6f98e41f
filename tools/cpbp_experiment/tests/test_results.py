import tempfile
import unittest
from dataclasses import replace
from pathlib import Path

from cpbp_experiment.configs import Config, Controller
from cpbp_experiment.fingerprint import UNRECORDED
from cpbp_experiment.results import (FIELDS, LEGACY_FIELDS, PHYSICS_FIELDS, PLATFORM_FIELDS,
                                     REFERENCE_BIKE, Attempt, ResultsError, ResultsFile,
                                     check_bike, check_seed)


def attempt(index: int, controller: str = "combined-5", speed: int = 15, seed: int = 1000,
            outcome: str = "goal") -> Attempt:
    return Attempt(Config(speed, Controller.parse(controller)), index, seed + index, outcome,
                   9.1, 36.0, 273, 13.5, 3900.0)


class ResultsFileTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.path = Path(self.directory.name) / "results.csv"
        self.results = ResultsFile(self.path)

    def tearDown(self):
        self.directory.cleanup()

    def test_appended_attempts_read_back_equal(self):
        saved = [attempt(0), attempt(1, "arcade", 25, outcome="fell"), attempt(2)]
        for a in saved:
            self.results.append(a)
        self.assertEqual(self.results.load(), saved)
        self.assertEqual(self.path.read_text().count("speed_kmh"), 1, "one header")

    def test_a_line_cut_short_by_a_kill_is_dropped_and_the_file_repaired(self):
        self.results.append(attempt(0))
        self.results.append(attempt(1))
        text = self.path.read_text()
        self.path.write_text(text[:-9])  # the kill came mid-line
        self.assertEqual(self.results.load(), [attempt(0)])
        self.assertTrue(self.path.read_text().endswith("\n"))
        self.results.append(attempt(1))
        self.assertEqual(self.results.load(), [attempt(0), attempt(1)])

    def test_an_attempt_saved_twice_is_an_error(self):
        self.results.append(attempt(0))
        self.results.append(attempt(0))
        with self.assertRaisesRegex(ResultsError, "twice"):
            self.results.load()

    def test_a_corrupt_row_is_an_error_not_skipped(self):
        self.results.append(attempt(0))
        with open(self.path, "a") as f:
            f.write("15,combined,5,1,1001,exploded,1,2,3,4,5\n")
        with self.assertRaisesRegex(ResultsError, ":3: unreadable row"):
            self.results.load()

    def test_a_legacy_file_reads_with_its_platform_unrecorded_and_upgrades(self):
        legacy = attempt(0)
        self.path.write_text(",".join(LEGACY_FIELDS) + "\n" + ",".join(legacy.row()[:11]) + "\n")
        loaded = self.results.load()
        self.assertTrue(self.results.legacy)
        self.assertEqual(loaded, [legacy])
        self.assertEqual((loaded[0].platform, loaded[0].late_plans), (UNRECORDED, None))
        with self.assertRaisesRegex(ResultsError, "legacy columns"):
            self.results.append(attempt(1))
        self.results.upgrade(loaded)
        self.results.append(attempt(1))
        self.assertEqual(self.results.load(), [legacy, attempt(1)])
        self.assertTrue(self.path.read_text().startswith(",".join(FIELDS) + "\n"))

    def test_a_file_from_before_the_physics_column_reads_as_classic_and_upgrades(self):
        earlier = attempt(0)
        self.path.write_text(",".join(PLATFORM_FIELDS) + "\n" + ",".join(earlier.row()[:14])
                             + "\n")
        loaded = self.results.load()
        self.assertTrue(self.results.legacy)
        self.assertEqual(loaded, [earlier])
        self.assertEqual(loaded[0].config.controller.physics, "classic")
        self.results.upgrade(loaded)
        exact = attempt(0, "combined-5:exact")
        self.results.append(exact)
        self.assertEqual(self.results.load(), [earlier, exact], "the same attempt, two physics")
        self.assertTrue(self.path.read_text().endswith(f",exact,{REFERENCE_BIKE}\n"))

    def test_a_file_from_before_the_bike_column_reads_as_the_reference_bike_and_upgrades(self):
        earlier = attempt(0, "combined-5:exact")
        self.path.write_text(",".join(PHYSICS_FIELDS) + "\n" + ",".join(earlier.row()[:15])
                             + "\n")
        loaded = self.results.load()
        self.assertTrue(self.results.legacy)
        self.assertEqual([a.bike for a in loaded], [REFERENCE_BIKE])
        self.results.upgrade(loaded)
        self.assertEqual(self.results.load(), [earlier])
        self.assertTrue(self.path.read_text().endswith(f",exact,{REFERENCE_BIKE}\n"))

    def test_a_bikes_rows_read_back_with_it_and_another_bike_is_refused(self):
        dirt = replace(attempt(0), bike="dirt_125")
        self.results.append(dirt)
        loaded = self.results.load()
        self.assertEqual(loaded[0].bike, "dirt_125")
        check_bike(loaded, "dirt_125", self.path)
        with self.assertRaisesRegex(ResultsError, "ridden on dirt_125, not street_350"):
            check_bike(loaded, REFERENCE_BIKE, self.path)

    def test_another_csv_is_refused(self):
        self.path.write_text("name,score\nada,3\n")
        with self.assertRaisesRegex(ResultsError, "not an experiment results file"):
            self.results.load()

    def test_resuming_with_another_seed_is_refused(self):
        check_seed([attempt(3, seed=1000)], 1000, self.path)
        with self.assertRaisesRegex(ResultsError, "--seed 1000"):
            check_seed([attempt(3, seed=1000)], 7, self.path)


if __name__ == "__main__":
    unittest.main()
