import unittest

from cpbp_experiment.configs import Config, Controller, parse_controllers, parse_speeds
from cpbp_experiment.runner import ARCADE_BLOCK, PLANNER_BLOCK, Progress, plan_blocks

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


if __name__ == "__main__":
    unittest.main()
