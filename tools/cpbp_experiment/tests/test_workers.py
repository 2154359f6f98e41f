import json
import sys
import tempfile
import unittest
from pathlib import Path
from unittest import mock

from cpbp_experiment import runner
from cpbp_experiment.bikes import Bike
from cpbp_experiment.configs import Config, Controller
from cpbp_experiment.results import ResultsFile
from cpbp_experiment.progress import Progress
from cpbp_experiment.runner import Block, Platform, WorkerError, run_blocks

CONFIG = Config(15, Controller("combined", 5))
WORKER_PLATFORM = {"c_library": "glibc 2.43", "math_path": "fma"}
PLATFORM = Platform("abc123", WORKER_PLATFORM)
ROOT = runner.PROJECT_ROOT


def fake_worker(script: str):
    """Stands in for Godot: a Python process that prints what `script` prints."""
    return lambda arguments: [sys.executable, "-c", script, *arguments]


def try_line(attempt: int) -> str:
    return "TRY " + json.dumps({
        "controller": "combined", "trajectories": 5, "speed_kmh": 15.0, "attempt": attempt,
        "seed": 1000 + attempt, "outcome": "goal", "time": 9.1, "distance": 36.0,
        "steps": 273, "planning_ms": 13.0, "wall_ms": 10.0, "planner_seed": 77,
        "late_plans": 0,
    })


def platform_line(description: dict) -> str:
    return "PLATFORM " + json.dumps(description)


class RunBlocksTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.out = Path(self.directory.name)
        self.results = ResultsFile(self.out / "results.csv")

    def tearDown(self):
        self.directory.cleanup()

    def run_with(self, script: str, blocks: list[Block]) -> None:
        progress = Progress(total=10, jobs=2, done_before=0)
        with mock.patch.object(runner, "godot_command", fake_worker(script)), \
                mock.patch("sys.stderr"):
            run_blocks(blocks, self.results, progress, 1000, 2, 1, self.out / "workers.log",
                       PLATFORM)

    def test_every_reported_attempt_is_saved_with_its_seed_and_platform(self):
        script = (f"print({platform_line(WORKER_PLATFORM)!r}); print({try_line(0)!r}); "
                  f"print('noise'); print({try_line(1)!r})")
        self.run_with(script, [Block(CONFIG, 0, 2)])
        saved = self.results.load()
        self.assertEqual([a.attempt for a in saved], [0, 1])
        self.assertEqual({(a.platform, a.planner_seed, a.late_plans) for a in saved},
                         {("abc123", 77, 0)})

    def test_a_worker_on_another_platform_stops_the_run(self):
        other = dict(WORKER_PLATFORM, math_path="baseline")
        with self.assertRaisesRegex(WorkerError, "another platform"):
            self.run_with(f"print({platform_line(other)!r}); print({try_line(0)!r})",
                          [Block(CONFIG, 0, 1)])

    def test_a_failing_worker_stops_the_run_and_its_words_are_shown(self):
        script = (f"import sys; print({try_line(0)!r}); "
                  "print('ERROR: level broken', file=sys.stderr); sys.exit(3)")
        with self.assertRaisesRegex(WorkerError, "(?s)exited with code 3.*level broken"):
            self.run_with(script, [Block(CONFIG, 0, 2)])
        self.assertEqual([a.attempt for a in self.results.load()], [0], "what it did is kept")

    def test_a_worker_that_ends_early_is_a_failure(self):
        with self.assertRaisesRegex(WorkerError, "after 1 of them"):
            self.run_with(f"print({try_line(0)!r})", [Block(CONFIG, 0, 2)])

    def test_a_report_for_another_attempt_is_refused(self):
        with self.assertRaisesRegex(WorkerError, "reported another attempt"):
            self.run_with(f"print({try_line(7)!r})", [Block(CONFIG, 0, 2)])


if __name__ == "__main__":
    unittest.main()


class BikeTest(unittest.TestCase):
    def test_a_bike_file_in_the_project_rides_by_its_res_path_and_name(self):
        bike = Bike.of_file(ROOT, str(ROOT / "scenes/bike/bikes/dirt_125.tres"))
        self.assertEqual(bike, Bike("dirt_125", "res://scenes/bike/bikes/dirt_125.tres"))
        self.assertEqual(bike.label, "dirt_125")
        arguments = runner.block_arguments(Block(CONFIG, 0, 10), 1000, 1, bike)
        self.assertEqual(arguments[-1], "--bike=res://scenes/bike/bikes/dirt_125.tres")
        reference = Bike.of_file(ROOT, None)
        self.assertEqual(reference.label, "street_350")
        self.assertFalse(any(a.startswith("--bike") for a in
                             runner.block_arguments(Block(CONFIG, 0, 10), 1000, 1, reference)),
                         "the reference bike is the workers' own")

    def test_another_bikes_network_is_passed_and_named_in_the_label(self):
        bike = Bike.of_file(ROOT, str(ROOT / "tests/fixtures/bikes/pit_bike.tres"),
                                   str(ROOT / "models/policy-street_390.safetensors"))
        self.assertEqual(bike.label, "pit_bike+street_390")
        self.assertEqual(bike.arguments(), ["--bike=res://tests/fixtures/bikes/pit_bike.tres",
                                            "--model=res://models/policy-street_390.safetensors"])

    def test_planner_settings_are_passed_sorted_and_named_in_the_label(self):
        bike = Bike.of_file(ROOT, str(ROOT / "scenes/bike/bikes/street_390.tres"), None,
                            ["terminal_value=true", "horizon=0.6", "horizon=0.4"])
        self.assertEqual(bike.label, "street_390@horizon=0.4,terminal_value=true",
                         "the last of a name counts")
        self.assertEqual(bike.arguments()[1:], ["--set=horizon=0.4", "--set=terminal_value=true"])
        self.assertEqual(Bike.of_file(ROOT, None, None, []).label, "street_350")
        with self.assertRaisesRegex(ValueError, "NAME=VALUE"):
            Bike.of_file(ROOT, None, None, ["horizon"])

    def test_a_missing_file_or_one_outside_the_project_is_refused(self):
        with self.assertRaisesRegex(ValueError, "no such bike file"):
            Bike.of_file(ROOT, "scenes/bike/bikes/moped_50.tres")
        with self.assertRaisesRegex(ValueError, "--model .*: no such model file"):
            Bike.of_file(ROOT, None, "models/policy-moped_50.safetensors")
        with tempfile.NamedTemporaryFile(suffix=".tres") as outside:
            with self.assertRaisesRegex(ValueError, "must lie in the project"):
                Bike.of_file(ROOT, outside.name)
