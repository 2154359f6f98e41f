"""The learned controllers' rows follow the model they were ridden with
(tools/learned_tools/evaluation.py)."""

from __future__ import annotations

import tempfile
import unittest
from pathlib import Path

from learned_tools import evaluation

EXPERIMENT = ("speed_kmh,controller,trajectories,attempt\n10,arcade,0,0\n10,learned,0,0\n"
              "10,guided,5,0\n15,combined,5,0\n")
SCENARIOS = "scenario,controller,trajectories,seed\nturn,learned,0,0\nturn,arcade,0,0\n"


class SupersedeTest(unittest.TestCase):
    def setUp(self) -> None:
        self.root = Path(tempfile.mkdtemp())
        for path, text in (("docs/experiment/results.csv", EXPERIMENT),
                           ("docs/experiment/platforms.json", "{}\n"),
                           ("docs/scenarios/scenarios.csv", SCENARIOS),
                           ("models/policy-street_350.safetensors", "model one")):
            (self.root / path).parent.mkdir(parents=True, exist_ok=True)
            (self.root / path).write_text(text)
        self.model = self.root / "models/policy-street_350.safetensors"

    def read(self, path: str) -> str:
        return (self.root / path).read_text()

    def test_rows_of_another_model_move_and_the_rest_stay(self) -> None:
        (self.root / evaluation.RECORD).parent.mkdir(parents=True)
        (self.root / evaluation.RECORD).write_text("0123456789ab\n")
        said = evaluation.supersede(self.root, self.model)
        self.assertIn("2 experiment rows and 1 scenario rows", said)
        self.assertEqual(self.read("docs/experiment/results.csv"),
                         "speed_kmh,controller,trajectories,attempt\n10,arcade,0,0\n"
                         "15,combined,5,0\n")
        old = "docs/experiment/superseded/model-0123456789ab/"
        self.assertEqual(self.read(old + "results.csv"),
                         "speed_kmh,controller,trajectories,attempt\n10,learned,0,0\n"
                         "10,guided,5,0\n")
        self.assertEqual(self.read(old + "platforms.json"), "{}\n")
        self.assertEqual(self.read("docs/scenarios/superseded/model-0123456789ab/scenarios.csv"),
                         "scenario,controller,trajectories,seed\nturn,learned,0,0\n")
        self.assertEqual(self.read(str(evaluation.RECORD)).strip(),
                         evaluation.model_identity(self.model))

    def test_a_resumed_evaluation_keeps_the_rows_of_its_own_model(self) -> None:
        evaluation.supersede(self.root, self.model)
        (self.root / "docs/experiment/results.csv").write_text(EXPERIMENT)
        said = evaluation.supersede(self.root, self.model)
        self.assertIn("were ridden with model", said)
        self.assertEqual(self.read("docs/experiment/results.csv"), EXPERIMENT)

    def test_a_new_model_supersedes_again(self) -> None:
        evaluation.supersede(self.root, self.model)
        first = evaluation.model_identity(self.model)
        self.model.write_text("model two")
        (self.root / "docs/scenarios/scenarios.csv").write_text(SCENARIOS)
        evaluation.supersede(self.root, self.model)
        self.assertEqual(self.read(f"docs/scenarios/superseded/model-{first}/scenarios.csv"),
                         "scenario,controller,trajectories,seed\nturn,learned,0,0\n")


if __name__ == "__main__":
    unittest.main()
