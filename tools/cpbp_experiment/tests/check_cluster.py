"""The experiment on a Dask cluster, end to end with real Godot workers (a `make test`
step, after the build): a scheduler and two single-threaded workers start here as on any
machine (docs/experiment.md, "On several machines"); a run on them is killed part-way,
resumed, and one worker process is killed under the resumed run; no attempt is lost or
saved twice, and the rows equal a local-pool run of the same seeds, row for row."""

import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

from cpbp_experiment.runner import PROJECT_ROOT
from cpbp_experiment.tests.check_quick_run import experiment, rows

SEED = "900"
TRIES = 6
RUN = ["--tries", str(TRIES), "--speeds", "25", "--controllers", "arcade:exact,combined-5:exact",
       "--seed", SEED]
# What must repeat exactly; wall time, planning time and platform name need not.
COMPARED = ("speed_kmh", "controller", "trajectories", "attempt", "seed", "outcome", "time_s",
            "distance_m", "steps", "planner_seed", "late_plans", "physics")


def descendants(pid: int) -> set[int]:
    found = set()
    for task in Path(f"/proc/{pid}/task").glob("*"):
        try:
            children = {int(p) for p in (task / "children").read_text().split()}
        except OSError:
            continue
        for child in children:
            found |= {child} | descendants(child)
    return found


def command_of(pid: int) -> str:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode()
    except OSError:
        return ""


def comparable(table: list[dict]) -> list[tuple]:
    return sorted(tuple(r[k] for k in COMPARED) for r in table)


class Cluster:
    """A Dask scheduler and two workers, each its own process group, as on a real node."""

    def __init__(self, directory: Path):
        dask = str(PROJECT_ROOT / ".venv" / "bin" / "dask")
        self.file = directory / "scheduler.json"
        self.logs = [open(directory / f"{name}.log", "w")
                     for name in ("scheduler", "worker-1", "worker-2")]
        self.processes = [subprocess.Popen(
            [dask, "scheduler", "--scheduler-file", str(self.file), "--port", "0",
             "--no-dashboard"], stdout=subprocess.DEVNULL,
            stderr=self.logs[0], start_new_session=True)]
        deadline = time.monotonic() + 60
        while not self.file.exists():
            if time.monotonic() > deadline:
                raise AssertionError("the Dask scheduler did not start")
            time.sleep(0.2)
        self.address = json.loads(self.file.read_text())["address"]
        self.processes += [subprocess.Popen(
            [dask, "worker", self.address, "--nthreads", "1", "--no-dashboard", "--name",
             f"node-{n}"], stdout=subprocess.DEVNULL,
            stderr=self.logs[n], start_new_session=True)
            for n in (1, 2)]

    def riding_worker(self) -> int | None:
        """A worker process (a nanny's child) that has a Godot worker riding under it."""
        for nanny in self.processes[1:]:
            for pid in descendants(nanny.pid):
                if "godot" not in command_of(pid) and any(
                        "experiment_worker" in command_of(c) for c in descendants(pid)):
                    return pid
        return None

    def close(self) -> None:
        for process in reversed(self.processes):
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            process.wait()
        for log in self.logs:
            log.close()


class ClusterRunTest(unittest.TestCase):
    def test_killed_driver_and_worker_lose_nothing_and_repeat_the_local_pool(self):
        with tempfile.TemporaryDirectory() as directory:
            base = Path(directory)
            local = subprocess.run(experiment("run", "--out", str(base / "local"), *RUN,
                                              "--jobs", "2"),
                                   capture_output=True, text=True, timeout=600)
            self.assertEqual(local.returncode, 0, local.stderr)
            reference = rows(base / "local" / "results.csv")
            self.assertEqual(len(reference), 2 * TRIES)

            cluster = Cluster(base)
            try:
                self._ride_killing_the_driver_then_a_worker(base / "cluster", cluster)
            finally:
                cluster.close()
            ridden = rows(base / "cluster" / "results.csv")
            keys = [(r["controller"], r["attempt"]) for r in ridden]
            self.assertEqual(len(keys), len(set(keys)), "no attempt saved twice")
            self.assertEqual(comparable(ridden), comparable(reference),
                             "the cluster's rows are the local pool's, row for row")

    def _ride_killing_the_driver_then_a_worker(self, out: Path, cluster: Cluster) -> None:
        results = out / "results.csv"
        command = experiment("run", "--out", str(out), *RUN, "--cluster", cluster.address)
        driver = subprocess.Popen(command, stderr=subprocess.DEVNULL)
        # Arcade's attempts come at once; kill the driver once a planner's have come too.
        self._wait_for(lambda: len(rows(results)) >= TRIES + 2, driver, "the first run")
        driver.send_signal(signal.SIGKILL)
        driver.wait()
        before = rows(results)
        self.assertLess(len(before), 2 * TRIES, "killed before the end")
        # The tasks of a driver that is gone stop riding within seconds.
        deadline = time.monotonic() + 30
        while cluster.riding_worker() is not None:
            self.assertLess(time.monotonic(), deadline, "a Godot worker outlived its driver")
            time.sleep(0.2)

        with open(out / "resumed.log", "w") as log:
            resumed = subprocess.Popen(command, stderr=log)
            # Kill the worker riding the rest once it has sent an attempt: the scheduler
            # gives its task to the other worker, which rides that attempt again.
            worker = self._wait_for(
                lambda: cluster.riding_worker() if len(rows(results)) > len(before) else None,
                resumed, "the resumed run")
            os.kill(worker, signal.SIGKILL)
            code = resumed.wait(timeout=600)
        said = (out / "resumed.log").read_text()
        self.assertEqual(code, 0, said)
        self.assertIn(f"{len(before)} of {2 * TRIES} attempts already in", said)
        self.assertRegex(said, r"[1-9]\d* attempts ridden again after a lost worker were "
                         "saved once")
        self.assertEqual(rows(results)[: len(before)], before, "saved attempts kept")

    def _wait_for(self, condition, process: subprocess.Popen, what: str):
        """Waits until `condition()` gives something; returns it."""
        deadline = time.monotonic() + 300
        while not (found := condition()):
            self.assertIsNone(process.poll(), f"{what} ended before it could be interrupted")
            self.assertLess(time.monotonic(), deadline, f"{what} made no progress")
            time.sleep(0.1)
        return found


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
