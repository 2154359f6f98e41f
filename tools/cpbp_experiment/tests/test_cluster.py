"""The cluster driver's bookkeeping (tools/cpbp_experiment/cluster.py), without a cluster:
what it saves, skips and refuses of the lines tasks send. The end-to-end run on a real
Dask cluster is check_cluster.py."""

import io
import json
import tempfile
import unittest
from contextlib import redirect_stderr
from pathlib import Path

from cpbp_experiment.cluster import ClusterRun
from cpbp_experiment.progress import Progress
from cpbp_experiment.runner import Block, Platform, WorkerError
from cpbp_experiment.results import ResultsFile
from cpbp_experiment.tests.test_workers import CONFIG, try_line

DESCRIPTION = {"code": "c0de", "godot": "4.6.3", "c_library": "glibc 2.43"}


class ClusterRunTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.results = ResultsFile(Path(self.directory.name) / "results.csv")
        self.run = ClusterRun(self.results, Progress(total=3, jobs=2, done_before=0),
                              Platform("abc123", {}, DESCRIPTION), set(),
                              {"b0": Block(CONFIG, 0, 3)})

    def tearDown(self):
        self.directory.cleanup()

    def take(self, message: str) -> None:
        with redirect_stderr(io.StringIO()):
            self.run.take(message)

    def test_saves_each_attempt_once_when_a_lost_task_rides_it_again(self):
        self.take(f"b0 PLATFORM abc123 {json.dumps(DESCRIPTION)}")
        for attempt in (0, 1, 0, 1, 2):
            self.take(f"b0 {try_line(attempt)}")
        self.assertEqual([a.attempt for a in self.results.load()], [0, 1, 2])
        self.assertEqual(self.run.repeated, 2)
        self.assertEqual({a.platform for a in self.results.load()}, {"abc123"})

    def test_refuses_a_node_of_another_platform_before_its_rows(self):
        other = dict(DESCRIPTION, c_library="glibc 2.0")
        with self.assertRaisesRegex(WorkerError, "c_library: the run's glibc 2.43, the node's glibc 2.0"):
            self.take(f"b0 PLATFORM 0ther00000 {json.dumps(other)}")
        self.assertEqual(self.results.load(), [])

    def test_refuses_a_line_of_another_attempt(self):
        with self.assertRaisesRegex(WorkerError, "reported another attempt"):
            self.take(f"b0 {try_line(7)}")


if __name__ == "__main__":
    unittest.main()
