"""Tables the docs carry between `<!-- figures: NAME -->` and `<!-- /figures -->`, made
from the committed rows as the figures are."""

from __future__ import annotations

import re
from collections import defaultdict
from pathlib import Path
from statistics import median
from typing import Callable

from learned_tools import report as learned_report
from cpbp_experiment.configs import Controller, display_order
from cpbp_experiment.report import timing_table
from cpbp_experiment.results import Attempt

from . import challenge_figures
from .experiment_figures import ExperimentRows
from .formats import count
from .markers import FigureError


def _exact(rows: ExperimentRows) -> list[Attempt]:
    return [a for a in rows.attempts if a.config.controller.physics == "exact"]


def _name(controller: Controller) -> str:
    return controller.in_physics("classic").label


def success_table(rows: ExperimentRows) -> str:
    """Goals of tries per controller and speed (the report has the intervals)."""
    cells: dict[Controller, dict[int, list[bool]]] = defaultdict(lambda: defaultdict(list))
    for a in _exact(rows):
        cells[a.config.controller][a.config.speed_kmh].append(a.outcome == "goal")
    speeds = sorted({s for by_speed in cells.values() for s in by_speed})
    lines = ["| controller | " + " | ".join(f"{s} km/h" for s in speeds) + " |",
             "|---|" + "---|" * len(speeds)]
    for controller in sorted(cells, key=display_order):
        row = [f"{sum(g)}/{len(g)}" if (g := cells[controller].get(s)) else "–" for s in speeds]
        lines.append(f"| {_name(controller)} | " + " | ".join(row) + " |")
    return "\n".join(lines)


def cost_table(rows: ExperimentRows) -> str:
    """Wall time per try on one planning thread per worker, by controller."""
    by_controller: dict[Controller, list[Attempt]] = defaultdict(list)
    for a in _exact(rows):
        by_controller[a.config.controller].append(a)
    lines = ["| controller | tries | wall time per try, mean / median | per simulated second | "
             "planning per control step |", "|---|---|---|---|---|"]
    for controller in sorted(by_controller, key=display_order):
        group = by_controller[controller]
        walls = [a.wall_ms / 1000.0 for a in group]
        per_second = sum(walls) / max(sum(a.time_s for a in group), 1e-9)
        planning = (f"{sum(a.planning_ms for a in group) / len(group):.1f} ms"
                    if controller.plans else "–")
        lines.append(f"| {_name(controller)} | {count(len(group))} | "
                     f"{sum(walls) / len(walls):.2f} / {median(walls):.2f} s | "
                     f"{per_second:.2f} s | {planning} |")
    return "\n".join(lines)


def tables(experiment: ExperimentRows, scenarios_csv: Path) -> dict[str, Callable[..., str]]:
    return {
        "success-table": lambda: success_table(experiment),
        "cost-table": lambda: cost_table(experiment),
        "timing-table": lambda: timing_table([r for r in experiment.timing
                                              if r.get("physics", "exact") == "exact"]),
        # The learned controller's report (docs/learned/training.md): its test-level and
        # scenario tables, as `make train` writes them.
        "learned-experiment": lambda: "\n".join(
            learned_report.experiment_tables(experiment.folder / "results.csv")),
        "learned-scenarios": lambda: "\n".join(learned_report.scenario_tables(scenarios_csv)),
        "make-test-steps": lambda: test_steps(experiment.folder.parents[1] / "tools/test.sh"),
        # The School's lessons and the levels' challenges with their medals' thresholds.
        "lessons": lambda: challenge_figures.table(experiment.folder.parents[1], "lessons"),
        "challenges": lambda: challenge_figures.table(experiment.folder.parents[1], "challenges"),
        # What the bot's gold rides earn on every bike (tools/challenge-survey.sh).
        "challenge-bots": lambda: challenge_figures.bot_table(experiment.folder.parents[1]),
    }


STEP = re.compile(r'^step "([^"]+)"')


def test_steps(script: Path) -> str:
    """make test's steps in order, each with the first sentence of the comment above it
    in tools/test.sh."""
    lines = ["| step | what it checks |", "|---|---|"]
    comment: list[str] = []
    for line in script.read_text(encoding="utf-8").splitlines():
        if line.startswith("#"):
            comment.append(line.lstrip("#").strip())
            continue
        if m := STEP.match(line):
            if not comment:
                raise FigureError(f"{script}: the step \"{m.group(1)}\" has no comment above it")
            text = " ".join(comment)
            sentence = re.match(r"(.+?)\.(\s|$)", text)
            lines.append(f"| {m.group(1)} | {sentence.group(1) if sentence else text} |")
        comment = []
    return "\n".join(lines)
