"""The experiment on a Dask cluster (`tools/experiment run --cluster`; docs/experiment.md,
"On several machines").

Dask distributed, not Ray: it is pure Python (about 5 MB of wheels against Ray's 80 MB),
its scheduler and workers start from one command each on any machine with the project,
and it reschedules the tasks of a lost worker by itself. Each block of attempts is one
task: a cluster worker runs one headless Godot worker on its own node, exactly as the
local pool does, and passes each line the Godot worker prints (its platform, then one per
attempt) to the driver through a Dask queue as it comes. The driver alone writes the
results file, so the resume rules stay the local pool's: a row is saved once, when its
line arrives; a task that ran again on another worker after its first one was lost
rides the same attempts to the same rows, which are already saved and are skipped."""

from __future__ import annotations

import functools
import json
import os
import queue as local_queue
import threading
import time
import uuid
from dataclasses import dataclass

from .fingerprint import COMPARED, fingerprint, identity
from .progress import Progress
from .runner import (PROJECT_ROOT, SILENCE_LIMIT_S, Block, Platform, WorkerError, attempt_of,
                     log_tail, block_arguments, start_worker)
from .results import ResultsFile

# How often the driver looks for lines and finished tasks.
POLL_S = 0.5
# How often a task riding a block asks whether its driver still wants it.
ABANDON_CHECK_S = 2.0


@functools.cache
def node_description(worker_platform_line: str) -> dict:
    """This node's platform fingerprint, from its checkout and what its worker printed."""
    return fingerprint(PROJECT_ROOT, json.loads(worker_platform_line))


def ride_block(arguments: list[str], count: int, queue_name: str, tag: str) -> int:
    """Runs on a cluster worker: one Godot worker rides a block of attempts and every line
    it prints goes to the driver's queue as "TAG PLATFORM {identity} {json}" or "TAG TRY
    {json}". Returns the attempts ridden; raises WorkerError when the Godot worker fails,
    stops short or falls silent for SILENCE_LIMIT_S (with its log's tail)."""
    from distributed import Queue, get_worker

    lines_out = Queue(queue_name)
    worker = get_worker()
    key = worker.get_current_task()
    # Each cluster worker process has a data home and a log of its own on its node.
    name = f"experiment-node-{os.getpid()}"
    log = PROJECT_ROOT / "build" / "scratch" / name / "workers.log"
    process = start_worker(arguments, log, scratch=name)
    lines: local_queue.Queue = local_queue.Queue()

    def pump() -> None:
        with process.stdout:
            for text in process.stdout:
                lines.put(text)
        lines.put(None)

    threading.Thread(target=pump, daemon=True).start()
    ridden = 0
    heard = time.monotonic()
    try:
        while True:
            try:
                text = lines.get(timeout=ABANDON_CHECK_S)
            except local_queue.Empty:
                text = ""
            if _abandoned(worker, key):
                # The driver is gone (killed, or stopped on another task's failure): the
                # rest of the block would be saved by nobody.
                return ridden
            if text is None:
                break
            if text:
                heard = time.monotonic()
            elif time.monotonic() - heard > SILENCE_LIMIT_S:
                raise WorkerError(f"a worker on {os.uname().nodename} said nothing for "
                                  f"{SILENCE_LIMIT_S:.0f} s and was stopped; see {log}:\n"
                                  f"{log_tail(log)}")
            if text.startswith("PLATFORM "):
                description = node_description(text[9:].strip())
                lines_out.put(f"{tag} PLATFORM {identity(description)} "
                              f"{json.dumps(description)}")
            elif text.startswith("TRY "):
                ridden += 1
                lines_out.put(f"{tag} TRY {text[4:].strip()}")
    finally:
        if process.poll() is None:
            process.kill()
    code = process.wait()
    if code != 0 or ridden < count:
        raise WorkerError(f"a worker on {os.uname().nodename} exited with code {code} after "
                          f"{ridden} of {count} attempts; see {log} there:\n{log_tail(log)}")
    return ridden


def _abandoned(worker, key: str) -> bool:
    """Whether the scheduler has dropped this task (its driver disconnected or cancelled
    it): the worker then marks the running task cancelled or forgets it."""
    task = worker.state.tasks.get(key)
    return task is None or task.state in ("cancelled", "released")


def connect(address: str, jobs: int):
    """A Dask client: of a cluster started here with `jobs` single-threaded workers
    ("local"), or of the cluster at `address`. Returns (client, local cluster or None)."""
    from distributed import Client, LocalCluster

    if address == "local":
        cluster = LocalCluster(n_workers=jobs, threads_per_worker=1, processes=True,
                               dashboard_address=None)
        return Client(cluster), cluster
    try:
        return Client(address, timeout="30s"), None
    except OSError as error:
        raise WorkerError(f"no Dask scheduler answered at {address}: {error}") from None


@dataclass
class ClusterRun:
    """What the driver keeps while the cluster rides."""

    results: ResultsFile
    progress: Progress
    platform: Platform
    done: set
    blocks: dict
    repeated: int = 0

    def take(self, message: str) -> None:
        """Saves an attempt's line or checks a node's platform line."""
        tag, kind, payload = message.split(" ", 2)
        block = self.blocks[tag]
        if kind == "PLATFORM":
            node, description = payload.split(" ", 1)
            if node != self.platform.identity:
                theirs = json.loads(description)
                raise WorkerError(
                    f"a cluster node rides on another platform than the run's ({node}, not "
                    f"{self.platform.identity}); its rows are refused:\n" + "\n".join(
                        f"  {key}: the run's {self.platform.description.get(key, '?')}, "
                        f"the node's {theirs.get(key, '?')}" for key in COMPARED
                        if self.platform.description.get(key) != theirs.get(key)))
            return
        attempt = attempt_of(payload, block, self.platform.identity,
                             self.platform.bike.label)
        if attempt.key in self.done:
            # A task ran again after its worker was lost: the row is saved already.
            self.repeated += 1
            return
        self.done.add(attempt.key)
        self.results.append(attempt)
        self.progress.record(attempt)
        progress = self.progress
        progress.report(attempt, force=progress.done_before + progress.done == progress.total)


def run_blocks_on_cluster(blocks: list[Block], results: ResultsFile, progress: Progress,
                          base_seed: int, threads: int, platform: Platform, done: set,
                          client) -> int:
    """Rides every block as a task on the cluster behind `client`, saving each attempt as
    its line arrives; returns how many repeated rides were skipped. Raises WorkerError when
    a task fails (after saving what others finished)."""
    from distributed import Queue

    queue_name = f"cpbp-experiment-{uuid.uuid4().hex}"
    lines = Queue(queue_name, client=client)
    run = ClusterRun(results, progress, platform, done,
                     {f"b{i}": block for i, block in enumerate(blocks)})
    # Higher priority runs first: the blocks in the order plan_blocks gave them.
    bike = platform.bike
    futures = [client.submit(ride_block, block_arguments(block, base_seed, threads, bike),
                             block.count, queue_name, f"b{i}", key=f"{queue_name}-b{i}", pure=False,
                             priority=len(blocks) - i)
               for i, block in enumerate(blocks)]
    try:
        while True:
            finished = all(f.done() for f in futures)
            for message in lines.get(batch=True):
                run.take(message)
            failed = next((f for f in futures if f.status == "error"), None)
            if failed is not None:
                raise _failure(failed, run.blocks[failed.key.rsplit("-", 1)[1]])
            if finished:
                # Every task put its lines before it finished; the queue holds the rest.
                for message in lines.get(batch=True):
                    run.take(message)
                return run.repeated
            time.sleep(POLL_S)
    finally:
        client.cancel(futures)


def _failure(future, block: Block) -> WorkerError:
    error = future.exception()
    if isinstance(error, WorkerError):
        return error
    return WorkerError(f"the task riding {block.config.label} attempts {block.first}–"
                       f"{block.first + block.count - 1} failed on the cluster: "
                       f"{type(error).__name__}: {error}")


def cluster_size(client) -> int:
    """Tasks the cluster runs at once: its workers' threads."""
    return max(1, sum(client.nthreads().values()))


def default_address() -> str | None:
    """Dask's own setting (DASK_SCHEDULER_ADDRESS or its configuration file), if any."""
    import dask

    return dask.config.get("scheduler-address", default=None)
