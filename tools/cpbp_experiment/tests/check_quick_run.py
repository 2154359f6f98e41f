"""The experiment's quick mode, end to end with real Godot workers (a `make test` step,
after the build): a run killed part-way resumes with no attempt lost or repeated, and
the report is written. Run alone:
`.venv/bin/python -m unittest -v cpbp_experiment.tests.check_quick_run`."""

import csv
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

from cpbp_experiment.runner import PROJECT_ROOT

QUICK = ["--tries", "4", "--speeds", "15,25", "--controllers", "arcade:exact,combined-5:exact",
         "--jobs", "2", "--seed", "500"]
CONFIGS = {(s, c, n) for s in ("15", "25") for c, n in (("arcade", "0"), ("combined", "5"))}


def experiment(*arguments: str) -> list[str]:
    return [str(PROJECT_ROOT / "tools" / "experiment"), *arguments]


def rows(path: Path) -> list[dict]:
    if not path.exists():
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def children(pid: int) -> set[int]:
    found = set()
    for task in Path(f"/proc/{pid}/task").glob("*"):
        found |= {int(p) for p in (task / "children").read_text().split()}
    return found


class QuickRunTest(unittest.TestCase):
    def test_a_killed_run_resumes_without_losses_or_duplicates(self):
        with tempfile.TemporaryDirectory() as directory:
            out = Path(directory)
            results = out / "results.csv"
            driver = subprocess.Popen(experiment("run", "--out", str(out), *QUICK),
                                      stderr=subprocess.DEVNULL)
            # Arcade's 8 attempts come at once; wait for a planner's too, then kill the
            # driver while planner attempts are still in progress.
            deadline = time.monotonic() + 120
            while len(rows(results)) < 10 and time.monotonic() < deadline:
                self.assertIsNone(driver.poll(), "the run ended before it could be killed")
                time.sleep(0.2)
            workers = children(driver.pid)
            driver.send_signal(signal.SIGKILL)
            driver.wait()
            before = rows(results)
            self.assertGreaterEqual(len(before), 10)
            self.assertLess(len(before), 16, "killed before the end")
            self._assert_workers_stop(workers)

            finished = subprocess.run(experiment("run", "--out", str(out), *QUICK),
                                      capture_output=True, text=True, timeout=300)
            self.assertEqual(finished.returncode, 0, finished.stderr)
            self.assertIn(f"{len(before)} already in", finished.stderr)
            after = rows(results)
            self.assertEqual(after[: len(before)], before, "saved attempts kept as they were")
            keys = [(r["speed_kmh"], r["controller"], r["trajectories"], r["attempt"]) for r in after]
            self.assertEqual(len(keys), len(set(keys)), "no attempt twice")
            self.assertEqual(set(keys), {(*c, str(i)) for c in CONFIGS for i in range(4)})
            for row in after:
                self.assertIn(row["outcome"], ("goal", "fell", "timeout"))
                self.assertEqual(int(row["seed"]), 500 + int(row["attempt"]))
                self.assertGreater(float(row["time_s"]), 0.0)
                self.assertGreater(int(row["steps"]), 0)

            again = subprocess.run(experiment("run", "--out", str(out), *QUICK),
                                   capture_output=True, text=True, timeout=60)
            self.assertEqual(again.returncode, 0, again.stderr)
            self.assertIn("16 already in", again.stderr)
            self.assertEqual(rows(results), after, "a finished run does nothing more")
            self._assert_report(out, after)

    def _assert_workers_stop(self, workers: set[int]) -> None:
        deadline = time.monotonic() + 10
        while any(Path(f"/proc/{pid}").exists() for pid in workers):
            self.assertLess(time.monotonic(), deadline, "workers outlived their driver")
            time.sleep(0.1)

    def _assert_report(self, out: Path, after: list[dict]) -> None:
        report = (out / "report.md").read_text()
        for speed in ("15", "25"):
            goals = sum(r["outcome"] == "goal" for r in after
                        if r["speed_kmh"] == speed and r["controller"] == "combined")
            self.assertIn(f"{goals}/4", report)
        self.assertIn("| arcade:exact |", report)
        self.assertIn("| combined-5:exact |", report)
        self.assertIn("Wilson", report)
        with open(out / "success.png", "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
