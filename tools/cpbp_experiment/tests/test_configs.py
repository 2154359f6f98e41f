"""The experiment's controllers come from the registry's copy, not from a list of its own."""

import json
import unittest
from pathlib import Path

from cpbp_experiment.configs import (BASELINES, FOLLOWING_PLANNERS, MAX_TRAJECTORIES,
                                     MIN_TRAJECTORIES, PLANNERS, REGISTRY, THESIS_PLANNERS,
                                     Controller)


class RegistryTest(unittest.TestCase):
    def test_the_planners_are_the_registry_entries_that_plan(self):
        copy = json.loads((Path(__file__).parents[1] / "controllers.json").read_text("utf-8"))
        copy = copy["controllers"]
        self.assertEqual([e["name"] for e in copy if e["plans"]], list(PLANNERS))
        self.assertEqual(len(REGISTRY), len(copy))
        self.assertTrue(set(THESIS_PLANNERS) <= set(PLANNERS))
        self.assertEqual(set(BASELINES),
                         set(PLANNERS) - set(THESIS_PLANNERS) - set(FOLLOWING_PLANNERS))

    def test_every_planner_parses_with_a_count_and_the_arcade_without(self):
        for kind in PLANNERS:
            controller = Controller.parse(f"{kind}-7:exact")
            self.assertTrue(controller.plans)
            self.assertEqual(controller.label, f"{kind}-7:exact")
        self.assertFalse(Controller.parse("arcade").plans)

    def test_a_name_the_registry_lacks_is_refused_with_the_known_ones(self):
        with self.assertRaises(ValueError) as refusal:
            Controller.parse("autopilot-5")
        for kind in PLANNERS:
            self.assertIn(kind, str(refusal.exception))
        with self.assertRaises(ValueError):
            Controller.parse("manual-5")

    def test_the_trajectory_count_is_the_rides_range(self):
        self.assertEqual(Controller.parse(f"combined-{MAX_TRAJECTORIES}").trajectories,
                         MAX_TRAJECTORIES)
        for count in (MIN_TRAJECTORIES - 1, MAX_TRAJECTORIES + 1):
            with self.assertRaises(ValueError):
                Controller.parse(f"combined-{count}")


if __name__ == "__main__":
    unittest.main()
