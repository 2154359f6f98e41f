"""The learned controller's report (tools/learned_tools/report.py): its tables from the
experiment's and the scenarios' rows, and the model file's metadata."""

from __future__ import annotations

import json
import struct
import tempfile
import unittest
from pathlib import Path

from learned_tools import report

RESULTS = "speed_kmh,controller,trajectories,attempt,outcome,physics\n" + "".join(
    f"10,{rider},0,{attempt},{outcome},exact\n"
    for attempt in range(4)
    for rider, outcome in (("arcade", "goal" if attempt else "fell"), ("learned", "goal"))
) + "10,arcade,0,9,goal,classic\n"
SCENARIOS = "scenario,controller,trajectories,seed,physics,fell,metric,planning_ms\n" + "".join(
    f"turn,{rider},{n},{seed},exact,false,{metric + seed / 100:.3f},0\n"
    for seed in range(3)
    for rider, n, metric in (("arcade", 0, 0.05), ("learned", 0, 0.04))
)


class ReportTest(unittest.TestCase):
    def setUp(self) -> None:
        self.folder = Path(tempfile.mkdtemp())

    def write(self, name: str, text: str) -> Path:
        path = self.folder / name
        path.write_text(text, "utf-8")
        return path

    def test_the_experiment_table_counts_goals_in_the_exact_model_only(self):
        lines = report.experiment_tables(self.write("results.csv", RESULTS))
        row = next(line for line in lines if line.startswith("| 10 km/h | 3/4"))
        self.assertIn("| 4/4 (", row, "learned reached the goal every time")
        pair = next(line for line in lines if "| learned | arcade |" in line)
        self.assertIn("| 4 | 1 | 0 |", pair, "one attempt only learned finished")

    def test_missing_rows_say_so(self):
        self.assertIn("not been ridden", report.experiment_tables(self.folder / "none.csv")[0])
        self.assertIn("not been ridden", report.scenario_tables(self.folder / "none.csv")[0])

    def test_the_scenario_table_pairs_riders_on_the_same_seeds(self):
        lines = report.scenario_tables(self.write("scenarios.csv", SCENARIOS))
        learned = next(line for line in lines if line.startswith("| turn | learned |"))
        arcade = next(line for line in lines if line.startswith("| turn | arcade |"))
        self.assertIn("| 3 | 0 |", learned)
        self.assertIn("learned − this:", arcade)

    def test_another_bikes_report_claims_none_of_the_references_rows(self):
        text = "\n".join(report.evaluation_of_bike("street_390"))
        self.assertIn("docs/scenarios/street_390/", text)
        self.assertNotIn("<!-- figures", text, "doc-check would hold it to the reference's rows")
        self.assertNotIn("km/h |", text)

    def test_the_models_metadata_is_read_from_its_header(self):
        header = json.dumps({"__metadata__": {"training": "2 rounds"}}).encode()
        path = self.folder / "model.safetensors"
        path.write_bytes(struct.pack("<Q", len(header)) + header)
        self.assertEqual(report.model_metadata(path), {"training": "2 rounds"})

    def test_the_cost_to_go_reports_each_round_and_nothing_when_none_was_trained(self):
        header = json.dumps({"__metadata__": {"format": "counter-steer-value"}}).encode()
        model = self.folder / "value.safetensors"
        self.assertEqual(report.value_section(self.folder, model), [], "no model, no losses")
        model.write_bytes(struct.pack("<Q", len(header)) + header)
        self.write("value-0.losses.csv", "epoch,train,held_out\n0,0.5,0.6\n1,0.4,0.5\n")
        self.write("value-1.losses.csv", "epoch,train,held_out\n0,0.3,0.45\n")
        text = "\n".join(report.value_section(self.folder, model))
        self.assertIn("counter-steer-value", text)
        self.assertIn("| 0 | the expert's and the policy rounds' recorded plans | 2 | 0.4000 | "
                      "0.5000 |", text)
        self.assertIn("| 1 | those and 1 round the short-horizon planner drove | 1 |", text)

    def test_a_cost_to_go_only_run_rewrites_its_section_and_keeps_the_policys(self):
        header = json.dumps({"__metadata__": {"format": "counter-steer-value"}}).encode()
        model = self.folder / "value.safetensors"
        model.write_bytes(struct.pack("<Q", len(header)) + header)
        self.write("value-0.losses.csv", "epoch,train,held_out\n0,0.5,0.6\n")
        out = self.folder / "report"
        out.mkdir()
        with self.assertRaises(ValueError, msg="no policy report to add to"):
            report.write_value_only(self.folder, model, out)
        policy = "# T\n\n## Losses\n\n| 3 | 8 | 0.4 | 0.5 |\n\n## Evaluation\n\nrows\n"
        (out / "training.md").write_text(policy, "utf-8")
        report.write_value_only(self.folder, model, out)
        first = (out / "training.md").read_text("utf-8")
        self.assertIn("| 3 | 8 | 0.4 | 0.5 |\n\n## The cost-to-go", first)
        self.assertIn("| 0 | the expert's recorded plans | 1 |", first)
        self.assertTrue(first.endswith("## Evaluation\n\nrows\n"))
        self.write("value-1.losses.csv", "epoch,train,held_out\n0,0.3,0.45\n")
        report.write_value_only(self.folder, model, out)
        second = (out / "training.md").read_text("utf-8")
        self.assertEqual(second.count("## The cost-to-go"), 1, "replaced, not added")
        self.assertIn("| 1 | those and 1 round the short-horizon planner drove |", second)
        self.assertTrue(second.endswith("## Evaluation\n\nrows\n"))


if __name__ == "__main__":
    unittest.main()
