import math
import unittest

from cpbp_experiment.cli import planned_tries
from cpbp_experiment.configs import (Config, Controller, parse_controllers, parse_speeds,
                                     protocol_tries)
from cpbp_experiment.results import Attempt
from cpbp_experiment.progress import Progress
from cpbp_experiment.runner import ARCADE_BLOCK, PLANNER_BLOCK, plan_blocks

ARCADE = Controller("arcade")
COMBINED = Controller("combined", 5)
OPTIMIZER = Controller("optimizer", 15)


class PlanBlocksTest(unittest.TestCase):
    def test_every_missing_attempt_once_and_nothing_done_again(self):
        configs = [Config(s, c) for s in (10, 25) for c in (ARCADE, COMBINED, OPTIMIZER)]
        done = {(configs[1], 3), (configs[1], 4), (configs[4], 0), (configs[0], 7)}
        blocks = plan_blocks(configs, 25, done)
        planned = [(b.config, i) for b in blocks for i in b.attempts()]
        self.assertEqual(len(planned), len(set(planned)))
        expected = {(c, i) for c in configs for i in range(25)} - done
        self.assertEqual(set(planned), expected)

    def test_arcade_first_then_planners_in_rounds(self):
        configs = [Config(15, c) for c in (ARCADE, COMBINED, OPTIMIZER)]
        blocks = plan_blocks(configs, 3 * PLANNER_BLOCK, set())
        self.assertEqual(blocks[0].config.controller, ARCADE)
        self.assertEqual(blocks[0].count, 3 * PLANNER_BLOCK)
        planner_blocks = blocks[1:]
        self.assertTrue(all(b.count <= PLANNER_BLOCK for b in planner_blocks))
        # Round r holds attempts r·B … for both planners before round r + 1 begins.
        firsts = [b.first for b in planner_blocks]
        self.assertEqual(firsts, sorted(firsts))
        self.assertLessEqual(ARCADE_BLOCK, 1000)

    def test_blocks_are_consecutive_attempts(self):
        config = Config(15, COMBINED)
        done = {(config, 2), (config, 5)}
        blocks = plan_blocks([config], 8, done)
        self.assertEqual([(b.first, b.count) for b in blocks], [(0, 2), (3, 2), (6, 2)])


    def test_each_configuration_its_own_count_in_rounds(self):
        few, many = Config(15, COMBINED), Config(15, OPTIMIZER)
        blocks = plan_blocks([few, many], {few: 12, many: 25}, set())
        planned = [(b.config, i) for b in blocks for i in b.attempts()]
        self.assertEqual(set(planned), {(few, i) for i in range(12)}
                         | {(many, i) for i in range(25)})
        # Both advance together while both have attempts left.
        self.assertEqual([(b.config, b.first) for b in blocks][:4],
                         [(few, 0), (many, 0), (few, 10), (many, 10)])


class ProtocolTest(unittest.TestCase):
    def test_the_game_protocol_counts(self):
        tries = protocol_tries()
        exact = lambda label: Controller.parse(f"{label}:exact")  # noqa: E731
        for speed in (10, 15, 20, 25):
            self.assertEqual(tries[Config(speed, exact("arcade"))], 500)
            for planner in ("optimizer", "combined"):
                for n in (5, 10, 15):
                    self.assertEqual(tries[Config(speed, exact(f"{planner}-{n}"))], 200)
            for label in ("sampling-10", "mppi-10", "learned", "guided-5"):
                self.assertEqual(tries[Config(speed, exact(label))], 100)
        for speed in (5, 30):
            self.assertEqual(tries[Config(speed, exact("arcade"))], 500)
            for label in ("combined-5", "learned", "guided-5"):
                self.assertEqual(tries[Config(speed, exact(label))], 100)
        self.assertEqual(len(tries), 4 * 11 + 2 * 4)
        self.assertTrue(all(c.controller.physics == "exact" for c in tries))
        self.assertEqual(set(protocol_tries(300).values()), {300, 500})

    def test_named_configurations_ride_tries_each(self):
        self.assertEqual(planned_tries(None, None, None), protocol_tries())
        named = planned_tries([25], parse_controllers("arcade,combined-5"), 4)
        self.assertEqual(named, {Config(25, ARCADE): 4, Config(25, COMBINED): 4})
        thesis = planned_tries([10], None, None)
        self.assertEqual(len(thesis), 7)
        self.assertEqual(set(thesis.values()), {500})
        self.assertTrue(all(c.controller.physics == "exact" for c in thesis))


class ParseTest(unittest.TestCase):
    def test_controllers_in_the_thesis_order(self):
        labels = [c.label for c in
                  parse_controllers("mppi-10,combined-5,arcade,sampling-5,optimizer-10,combined-5")]
        self.assertEqual(labels, ["arcade", "optimizer-10", "combined-5", "sampling-5", "mppi-10"])

    def test_bad_names_and_speeds_are_explained(self):
        for text in ("arcade-5", "combined", "combined-0", "mpc-5"):
            with self.subTest(text=text), self.assertRaisesRegex(ValueError, "unknown controller"):
                parse_controllers(text)
        for text in ("0", "15,fast", "-3", "91"):
            with self.subTest(text=text), self.assertRaisesRegex(ValueError, "km/h"):
                parse_speeds(text)


class ProgressTest(unittest.TestCase):
    def test_eta_scales_untimed_planners_by_their_trajectory_count(self):
        progress = Progress(total=40, jobs=2, done_before=0)
        progress.remaining = {Config(15, COMBINED): 10, Config(15, OPTIMIZER): 10}
        progress.cost_ms = {Config(15, COMBINED): [5000.0]}
        # 10 × 5 s for N = 5, and 10 × 15 s guessed for N = 15, on 2 workers.
        self.assertAlmostEqual(progress.eta_s(), (50 + 150) / 2)

    def test_eta_counts_the_attempts_earlier_runs_saved(self):
        config = Config(15, COMBINED)
        progress = Progress(total=40, jobs=2, done_before=30)
        progress.remaining = {config: 10}
        earlier = [Attempt(config, i, 1000 + i, "goal", 6.0, 36.0, 180, 12.0, 4000.0)
                   for i in range(29)]
        legacy = Attempt(config, 29, 1029, "goal", 6.0, 36.0, 180, 12.0, math.nan)
        progress.remember(earlier + [legacy])
        # This run's first attempt shared the machine and took 8 s, twice the others: the
        # 9 left cost the mean of all 30 timed (the legacy row has no time), on 2 workers.
        progress.record(Attempt(config, 30, 1030, "goal", 6.0, 36.0, 180, 12.0, 8000.0))
        self.assertAlmostEqual(progress.eta_s(), 9 * (29 * 4 + 8) / 30 / 2)


if __name__ == "__main__":
    unittest.main()
