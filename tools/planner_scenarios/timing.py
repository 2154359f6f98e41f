"""What a folder's settings cost, timed on rides (issue 59): the same seeds ridden at the
defaults and with the folder's settings, scenario by scenario in turn in one spell, so a
drift of the machine's load falls on both alike; each ride's mean planning time paired
seed by seed. `make bench` times plans made again and again from one state, which cannot
time a rule that plans the next step by how the last one went (a trajectory count that
follows the disagreement); a ride can.

The rows are kept beside the folder's (`timing-defaults.csv`, `timing-settings.csv`,
the scenario rows' columns) and rewritten whole by each timing: a timing is one spell."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from .rows import ScenarioRows, rider_name
from .stats import t_interval

DEFAULTS = "timing-defaults.csv"
SETTINGS = "timing-settings.csv"


@dataclass(frozen=True)
class Ratio:
    """A geometric mean of paired ratios (these settings ÷ the defaults) with its 95 %
    interval, over `pairs` rides."""
    ratio: float
    low: float
    high: float
    pairs: int

    def text(self) -> str:
        return f"{self.ratio:.2f} ({self.low:.2f}–{self.high:.2f})"


def timing_files(folder: Path) -> tuple[ScenarioRows, ScenarioRows]:
    return ScenarioRows(folder / DEFAULTS), ScenarioRows(folder / SETTINGS)


def start_timing(folder: Path) -> tuple[ScenarioRows, ScenarioRows]:
    """The two files, emptied for a new spell."""
    files = timing_files(folder)
    for rows in files:
        rows.path.unlink(missing_ok=True)
    return files


def paired_ratio(defaults: list[dict], settings: list[dict], rider: str | None = None,
                 scenario: str | None = None) -> Ratio:
    """Planning time with the settings over the defaults, ride by ride (scenario, planner,
    N, seed), for one rider (`combined-5`) or all, in one scenario or all; rides that fell
    in either count too (they planned until they fell)."""
    def key(row: dict) -> tuple:
        return row["scenario"], row["controller"], row["trajectories"], row["seed"]

    def chosen(row: dict) -> bool:
        return ((rider is None or rider_name(row) == rider)
                and (scenario is None or row["scenario"] == scenario)
                and row["planning_ms"] > 0)

    base = {key(r): r["planning_ms"] for r in defaults if chosen(r)}
    logs = [math.log(r["planning_ms"] / base[key(r)]) for r in settings
            if chosen(r) and key(r) in base]
    if len(logs) < 2:
        raise ValueError(f"{len(logs)} paired rides of {rider or 'every planner'} in "
                         f"{scenario or 'every scenario'}: too few to time")
    interval = t_interval(logs)
    return Ratio(math.exp(interval.mean), math.exp(interval.low), math.exp(interval.high),
                 interval.n)


def summary(folder: Path) -> list[str]:
    """Each rider's ratio and all riders' together, as lines to print."""
    defaults, settings = (rows.load() for rows in timing_files(folder))
    riders = sorted({rider_name(r) for r in settings})
    lines = [f"{rider}: {paired_ratio(defaults, settings, rider).text()}" for rider in riders]
    pooled = paired_ratio(defaults, settings)
    lines.append(f"all: {pooled.text()} over {pooled.pairs} paired rides")
    return lines
