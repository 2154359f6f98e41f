"""The run's progress line: attempts done of the total and an ETA from the measured cost
of each configuration (docs/experiment.md, "Running it")."""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass, field

from .results import Attempt


@dataclass
class Progress:
    """Counts and an ETA from the measured cost of each configuration."""

    total: int
    jobs: int
    done_before: int
    started: float = field(default_factory=time.monotonic)
    done: int = 0
    cost_ms: dict = field(default_factory=dict)
    remaining: dict = field(default_factory=dict)
    last_print: float = 0.0

    def record(self, attempt: Attempt) -> None:
        self.done += 1
        costs = self.cost_ms.setdefault(attempt.config, [])
        costs.append(attempt.wall_ms)
        self.remaining[attempt.config] = self.remaining.get(attempt.config, 1) - 1

    def remember(self, saved: list[Attempt]) -> None:
        """Counts the cost of the attempts earlier runs saved into the estimate, so a
        resumed run's ETA starts from many attempts of each configuration rather than
        from its first few (the first attempt of a slow configuration, or one that shared
        the machine with a build, made a 4-hour run's first ETA read 9 hours)."""
        for attempt in saved:
            if math.isfinite(attempt.wall_ms) and attempt.wall_ms > 0:
                self.cost_ms.setdefault(attempt.config, []).append(attempt.wall_ms)

    def eta_s(self) -> float:
        """Seconds left: each configuration's mean cost so far times its attempts left. A
        planner not timed yet is guessed from the others' cost per trajectory, as the
        cost grows with N; with none timed there is no estimate."""
        per_trajectory = [
            c / config.controller.trajectories
            for config, costs in self.cost_ms.items()
            if config.controller.plans
            for c in costs
        ]
        work_ms = 0.0
        for config, left in self.remaining.items():
            costs = self.cost_ms.get(config)
            if costs:
                work_ms += max(left, 0) * sum(costs) / len(costs)
            elif left > 0 and config.controller.plans and per_trajectory:
                guess = sum(per_trajectory) / len(per_trajectory)
                work_ms += left * guess * config.controller.trajectories
            elif left > 0:
                return math.nan
        return work_ms / 1000.0 / self.jobs

    def line(self, attempt: Attempt) -> str:
        finished = self.done_before + self.done
        share = 100.0 * finished / max(self.total, 1)
        return (
            f"[{finished}/{self.total} {share:5.1f} %] {attempt.config.label} "
            f"#{attempt.attempt}: {attempt.outcome} after {attempt.time_s:.1f} s "
            f"({attempt.wall_ms / 1000:.1f} s to simulate) · elapsed "
            f"{_clock(time.monotonic() - self.started)} · ETA {_clock(self.eta_s())}"
        )

    def report(self, attempt: Attempt, force: bool = False) -> None:
        now = time.monotonic()
        # One line per attempt on a terminal; every 10 s in a log.
        if force or sys.stderr.isatty() or now - self.last_print >= 10.0:
            print(self.line(attempt), file=sys.stderr, flush=True)
            self.last_print = now


def _clock(seconds: float) -> str:
    if math.isnan(seconds):
        return "--:--:--"
    seconds = int(seconds)
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}"
