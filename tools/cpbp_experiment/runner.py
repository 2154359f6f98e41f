"""Runs the missing attempts with Godot workers, several at once, and saves each attempt
as it ends."""

from __future__ import annotations

import ctypes
import json
import os
import queue
import shutil
import signal
import subprocess
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

from .bikes import Bike
from .configs import Config
from .progress import Progress
from .results import REFERENCE_BIKE, Attempt, ResultsFile

PROJECT_ROOT = Path(__file__).resolve().parents[2]
WORKER_SCENE = "res://scenes/experiment/experiment_worker.tscn"
# Attempts per worker process for a planner: long enough that starting Godot (about a
# second) is a small share, short enough that every configuration advances together.
PLANNER_BLOCK = 10
# The arcade controller rides an attempt in milliseconds: give it long blocks.
ARCADE_BLOCK = 500
# A worker silent this long is stuck (the dearest attempt, combined N = 15 at 10 km/h,
# costs about 20 s on one thread): it is stopped and the run fails rather than hangs.
SILENCE_LIMIT_S = 600.0


class WorkerError(Exception):
    """A worker failed; the message carries its last words."""


@dataclass
class Block:
    """Consecutive attempts of one configuration, for one worker process."""

    config: Config
    first: int
    count: int

    def attempts(self) -> range:
        return range(self.first, self.first + self.count)


def plan_blocks(configs: list[Config], tries: int | dict[Config, int],
                done: set[tuple[Config, int]]) -> list[Block]:
    """The missing attempts as blocks, in rounds of PLANNER_BLOCK attempts over every
    configuration, so a run stopped early still has every configuration at about the
    same count. `tries` is one count for all or each configuration's own (a protocol's).
    Arcade blocks come first: they take seconds in all."""
    wanted = tries if isinstance(tries, dict) else {config: tries for config in configs}
    blocks = []
    for config in configs:
        if not config.controller.plans:
            blocks += _blocks_of(config, range(wanted[config]), done, ARCADE_BLOCK)
    for start in range(0, max(wanted.values(), default=0), PLANNER_BLOCK):
        for config in configs:
            if config.controller.plans and start < wanted[config]:
                window = range(start, min(start + PLANNER_BLOCK, wanted[config]))
                blocks += _blocks_of(config, window, done, PLANNER_BLOCK)
    return blocks


def _blocks_of(config: Config, window: range, done, size: int) -> list[Block]:
    blocks: list[Block] = []
    for attempt in window:
        if (config, attempt) in done:
            continue
        last = blocks[-1] if blocks else None
        if last and last.first + last.count == attempt and last.count < size:
            last.count += 1
        else:
            blocks.append(Block(config, attempt, 1))
    return blocks


def godot_command(arguments: list[str]) -> list[str]:
    return [
        str(PROJECT_ROOT / "tools" / "godot"),
        "--headless",
        "--path",
        str(PROJECT_ROOT),
        WORKER_SCENE,
        "--",
        *arguments,
    ]


# Each scratch folder's environment, made once per process; locked for threaded callers.
_ENVIRONMENTS: dict[str, dict[str, str]] = {}
_ENVIRONMENTS_LOCK = threading.Lock()


def worker_environment(scratch_name: str = "experiment") -> dict[str, str]:
    """The environment of every worker: a Godot data home of its own (build/scratch/
    SCRATCH_NAME, emptied once per driver, as tools/common.sh's use_scratch_user_data does
    for the other checks), so workers never write into the player's user:// folder. Each
    process that starts workers (the driver, or a cluster worker) names its own."""
    with _ENVIRONMENTS_LOCK:
        if scratch_name not in _ENVIRONMENTS:
            scratch = PROJECT_ROOT / "build" / "scratch" / scratch_name
            shutil.rmtree(scratch, ignore_errors=True)
            homes = {"XDG_DATA_HOME": scratch / "data", "XDG_CONFIG_HOME": scratch / "config"}
            for home in homes.values():
                home.mkdir(parents=True)
            _ENVIRONMENTS[scratch_name] = {
                **os.environ, **{name: str(home) for name, home in homes.items()},
                "COUNTER_STEER_SCRATCH": str(scratch)}
        return _ENVIRONMENTS[scratch_name]


def _die_with_parent() -> None:
    # A worker whose driver was killed stops too, instead of riding on unheard.
    libc = ctypes.CDLL("libc.so.6", use_errno=True)
    libc.prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG


def start_worker(arguments: list[str], log: Path,
                 scratch: str = "experiment") -> subprocess.Popen:
    log.parent.mkdir(parents=True, exist_ok=True)
    with open(log, "a", encoding="utf-8") as stderr:
        return subprocess.Popen(
            godot_command(arguments),
            stdout=subprocess.PIPE,
            stderr=stderr,
            text=True,
            env=worker_environment(scratch),
            preexec_fn=_die_with_parent,
        )


def block_arguments(block: Block, base_seed: int, threads: int,
                    bike: Bike | None = None) -> list[str]:
    """A worker's arguments for `block`, riding `bike` (None: the reference)."""
    controller = block.config.controller
    return [
        f"--speed={block.config.speed_kmh}",
        f"--controller={controller.kind}",
        f"--trajectories={max(controller.trajectories, 1)}",
        f"--seed={base_seed}",
        f"--first={block.first}",
        f"--count={block.count}",
        f"--threads={threads}",
        f"--physics={controller.physics}",
    ] + (bike.arguments() if bike else [])


def worker_platform(log: Path) -> dict:
    """What a worker reports of the engine, the native module and the machine."""
    process = start_worker(["--platform"], log)
    output, _ = process.communicate(timeout=120)
    for text in output.splitlines():
        if text.startswith("PLATFORM "):
            return json.loads(text[9:])
    raise WorkerError(f"a worker did not describe its platform (exit code "
                      f"{process.returncode}); see {log}:\n{log_tail(log)}")


@dataclass(frozen=True)
class Platform:
    """The run's platform: its identity for the rows, what every worker must report, and
    the whole fingerprint (to say what differs on a cluster node that is not the same)."""

    identity: str
    worker: dict
    description: dict = field(default_factory=dict)
    # The bike every row rides (`Bike`): not a property of the machine, but carried with
    # it to every worker a run starts.
    bike: Bike = field(default_factory=Bike.reference)


def run_blocks(
    blocks: list[Block],
    results: ResultsFile,
    progress: Progress,
    base_seed: int,
    jobs: int,
    threads: int,
    log: Path,
    platform: Platform,
) -> None:
    """Keeps `jobs` workers busy until every block is done; saves each attempt as its
    line arrives. Raises WorkerError when a worker fails or reports another platform
    (after saving what others finished); the attempts it did not finish run again on
    the next run."""
    pending = list(blocks)
    for block in blocks:
        for _ in block.attempts():
            progress.remaining[block.config] = progress.remaining.get(block.config, 0) + 1
    lines: queue.Queue = queue.Queue()
    running: dict[int, tuple[subprocess.Popen, Block]] = {}
    reported: dict[int, int] = {}
    heard: dict[int, float] = {}
    failure = None

    def pump(worker_id: int, process: subprocess.Popen) -> None:
        with process.stdout:
            for text in process.stdout:
                lines.put((worker_id, text))
        lines.put((worker_id, None))

    next_id = 0
    try:
        while pending or running:
            while pending and len(running) < jobs and failure is None:
                block = pending.pop(0)
                process = start_worker(
                    block_arguments(block, base_seed, threads, platform.bike), log)
                running[next_id] = (process, block)
                reported[next_id] = 0
                heard[next_id] = time.monotonic()
                threading.Thread(target=pump, args=(next_id, process), daemon=True).start()
                next_id += 1
            if not running:
                break
            try:
                worker_id, text = lines.get(timeout=5.0)
            except queue.Empty:
                failure = failure or _silent_worker(running, heard, log)
                continue
            process, block = running[worker_id]
            heard[worker_id] = time.monotonic()
            if text is None:
                code = process.wait()
                del running[worker_id]
                short = reported[worker_id] < block.count
                if (code != 0 or short) and failure is None:
                    failure = WorkerError(
                        f"a worker for {block.config.label} attempts {block.first}–"
                        f"{block.first + block.count - 1} exited with code {code} after "
                        f"{reported[worker_id]} of them; see {log}:\n{log_tail(log)}"
                    )
                continue
            if text.startswith("PLATFORM ") and json.loads(text[9:]) != platform.worker:
                process.kill()
                failure = failure or WorkerError(
                    f"a worker reported another platform than the run's: {text[9:].strip()}")
            elif text.startswith("TRY "):
                reported[worker_id] += 1
                attempt = attempt_of(text[4:], block, platform.identity, platform.bike.label)
                results.append(attempt)
                progress.record(attempt)
                progress.report(attempt, force=not pending and len(running) == 1)
    finally:
        for process, _ in running.values():
            process.kill()
    if failure:
        raise failure


def _silent_worker(running, heard, log: Path) -> WorkerError | None:
    for worker_id, (process, block) in running.items():
        if time.monotonic() - heard[worker_id] > SILENCE_LIMIT_S:
            process.kill()
            return WorkerError(
                f"a worker for {block.config.label} said nothing for {SILENCE_LIMIT_S:.0f} s "
                f"and was stopped; see {log}:\n{log_tail(log)}"
            )
    return None


def attempt_of(payload: str, block: Block, platform: str, bike: str = REFERENCE_BIKE) -> Attempt:
    data = json.loads(payload)
    controller = block.config.controller
    ok = (
        data["controller"] == controller.kind
        and int(data["trajectories"]) == controller.trajectories
        and data.get("physics", "classic") == controller.physics
        and round(float(data["speed_kmh"])) == block.config.speed_kmh
        and int(data["attempt"]) in block.attempts()
    )
    if not ok:
        raise WorkerError(f"a worker for {block.config.label} reported another attempt: {payload}")
    return Attempt(
        config=block.config,
        attempt=int(data["attempt"]),
        seed=int(data["seed"]),
        outcome=data["outcome"],
        time_s=float(data["time"]),
        distance_m=float(data["distance"]),
        steps=int(data["steps"]),
        planning_ms=float(data["planning_ms"]),
        wall_ms=float(data["wall_ms"]),
        planner_seed=int(data["planner_seed"]),
        late_plans=int(data["late_plans"]),
        platform=platform,
        bike=bike,
    )


def log_tail(log: Path, lines: int = 8) -> str:
    try:
        return "\n".join(log.read_text(encoding="utf-8", errors="replace").splitlines()[-lines:])
    except OSError:
        return "(no log)"


def measure_planning(controller_kind: str, counts: list[int], steps: int, speed: int,
                     seed: int, log: Path, physics: str, bike: Bike | None = None) -> list[dict]:
    """The planning-time study: one worker, every core for the planner, as in the game;
    `bike` as `block_arguments` takes it."""
    arguments = [
        "--timing",
        f"--physics={physics}",
        f"--controller={controller_kind}",
        f"--trajectories={','.join(str(c) for c in counts)}",
        f"--steps={steps}",
        f"--speed={speed}",
        f"--seed={seed}",
        "--threads=0",
    ] + (bike.arguments() if bike else [])
    process = start_worker(arguments, log)
    rows = []
    for text in process.stdout:
        if text.startswith("TIMING "):
            row = {**json.loads(text[7:]), "physics": physics}
            print(f"  {controller_kind} N={row['trajectories']}: {row['mean_ms']:.1f} ms "
                  f"per plan (median {row['median_ms']:.1f}, p95 {row['p95_ms']:.1f})",
                  file=sys.stderr, flush=True)
            rows.append(row)
    if process.wait() != 0:
        raise WorkerError(f"the timing worker exited with code {process.returncode}; "
                          f"see {log}:\n{log_tail(log)}")
    return rows


def cpu_description() -> str:
    model = "unknown CPU"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} cores"
