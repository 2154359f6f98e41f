"""A bike's scenario table ridden again with other planner settings (issue 59's shorter
horizons, alone or ended by the learned cost-to-go), each folder against the bike's own
table at the defaults: one row per settings and controller with what it saves in planning
and what it changes in every scenario.

Each folder is one claim ("these settings plan as well"), so each is its own family of
tests: falls pair by seed (exact McNemar), metrics over the seeds both stayed up on (paired
t-test), Holm's correction over that folder's tests, as `--compare` does for one page."""

from __future__ import annotations

import json
import math
from collections import defaultdict
from dataclasses import dataclass
from pathlib import Path

from cpbp_experiment.stats import ALPHA, holm

from .compare import Pairing, _p_text, pairings
from .report import METRICS
from .stats import paired_difference


def variant_folders(under: Path) -> list[Path]:
    """The folders under `under` that hold rows, by name."""
    return sorted(p.parent for p in under.glob("*/scenarios.csv"))


def settings_text(folder: Path) -> str:
    """`horizon=0.6`, or `terminal_value=true, value_horizon=0.6`: the folder's
    settings.json (written by `run --set`), or the folder's name without one."""
    path = folder / "settings.json"
    if not path.exists():
        return folder.name
    settings = json.loads(path.read_text("utf-8"))
    return ", ".join(f"{name}={value}" for name, value in sorted(settings.items()))


def _cell(found: Pairing, falls_rejects: bool, metric_rejects: bool, p: float) -> str:
    """The paired difference's mean (this − defaults), bold where it is beyond chance,
    with the falls when they differ at all."""
    difference = paired_difference(found.up[1], found.up[0])
    text = "–" if difference.n == 0 else f"{difference.mean:+.2g}"
    if metric_rejects:
        text = f"**{text}** (p {_p_text(p)})"
    if found.falls[0] != found.falls[1]:
        falls = f"falls {found.falls[0]}→{found.falls[1]}"
        text += f", **{falls}**" if falls_rejects else f", {falls}"
    return text


@dataclass(frozen=True)
class RiderSweep:
    """One planner of one folder held against the defaults: what the sweep page's row
    says, and what the docs quote from it (doc-check's `sweep-*` figures)."""

    controller: str
    against: int      # the defaults' N its rides are paired with
    ridden: int       # the N the folder rode (fewer with `base_count`)
    seeds: int
    planning_ratio: float  # geometric mean over the scenarios; NaN where untimed
    falls: tuple[int, int]  # defaults, these settings, over every scenario
    differing: int    # tests beyond chance after Holm over the folder's
    tests: int
    shifts: dict[str, float]  # scenario → mean paired difference (these − defaults)
    cells: dict[str, str]     # scenario → the page's cell

    @property
    def label(self) -> str:
        text = f"{self.controller}-{self.ridden}"
        if self.ridden != self.against:
            text += f" (against {self.controller}-{self.against})"
        return text


def folder_sweep(base: list[dict], variant: list[dict],
                 base_count: int | None = None) -> list[RiderSweep]:
    """One folder's planners against the base's table, Holm over the folder's tests; with
    `base_count`, every N of the folder's is held against the base's rides at that N
    (fewer trajectories against the defaults' five)."""
    ridden = {}
    if base_count is not None:
        ridden = {(r["controller"], base_count): r["trajectories"] for r in variant}
        variant = [{**r, "trajectories": base_count} for r in variant]
    found = pairings(base, variant)
    if not found:
        return []
    p_values = [p for f in found for p in (f.falls_p, f.metric_p)]
    reject, adjusted = holm(p_values, ALPHA)
    by_rider: dict[tuple, list[int]] = defaultdict(list)
    for i, f in enumerate(found):
        by_rider[(f.key[1], f.key[2])].append(i)
    riders = []
    for (controller, n), indices in by_rider.items():
        planning = [found[i].planning_ratio for i in indices
                    if not math.isnan(found[i].planning_ratio)]
        ratio = (math.exp(sum(map(math.log, planning)) / len(planning)) if planning
                 else math.nan)
        shifts = {}
        for i in indices:
            difference = paired_difference(found[i].up[1], found[i].up[0])
            shifts[found[i].key[0]] = difference.mean if difference.n else math.nan
        riders.append(RiderSweep(
            controller=controller, against=n, ridden=ridden.get((controller, n), n),
            seeds=min(found[i].seeds for i in indices), planning_ratio=ratio,
            falls=tuple(sum(found[i].falls[side] for i in indices) for side in (0, 1)),
            differing=sum(reject[2 * i] + reject[2 * i + 1] for i in indices),
            tests=2 * len(indices), shifts=shifts,
            cells={found[i].key[0]: _cell(found[i], reject[2 * i], reject[2 * i + 1],
                                          adjusted[2 * i + 1]) for i in indices}))
    return riders


def sweep_rows(base: list[dict], variant: list[dict], settings: str,
               scenarios: list[str], base_count: int | None = None) -> list[str]:
    """The markdown rows of one folder: one per planner and N it shares with the base."""
    rows = []
    for rider in folder_sweep(base, variant, base_count):
        ratio = "–" if math.isnan(rider.planning_ratio) else f"{rider.planning_ratio:.2f}"
        rows.append(f"| {settings} | {rider.label} | {rider.seeds} | {ratio} | "
                    f"{rider.falls[0]} → {rider.falls[1]} | {rider.differing} of "
                    f"{rider.tests} | "
                    + " | ".join(rider.cells.get(s, "–") for s in scenarios) + " |")
    return rows


def write_sweep(base_rows: list[dict], folders: list[tuple[str, list[dict]]], bike: str,
                path: Path, base_count: int | None = None) -> None:
    """The page: the scenarios every folder shares with the base, as columns."""
    ridden = {r["scenario"] for _, rows in folders for r in rows}
    scenarios = [s for s in METRICS if s in ridden and any(r["scenario"] == s
                                                           for r in base_rows)]
    lines = [
        f"# The {bike}'s scenarios with other planner settings",
        "",
        "Made by `tools/planner-scenarios sweep` from the bike's own table (the defaults: "
        "1.2 s planned, no cost-to-go) and each folder here, ridden with the same seeds, "
        "headings and draws. A row is one folder's settings and one planner: the seeds it "
        "rode in every scenario, its planning time over the defaults' (the geometric mean "
        "over the scenarios of the rides' mean planning times, timed as the rows were "
        "ridden on a loaded machine: `make bench` gives the cost ratios), the falls of the "
        "defaults and of the settings over every scenario, and how many of its paired "
        "tests (falls and metric of each scenario) differ beyond chance after Holm over "
        "the folder's tests at a family-wise "
        f"{ALPHA * 100:.0f} %. Each scenario's cell is the mean paired difference of its "
        "metric (these settings − the defaults, over the seeds both stayed up on; the "
        "metrics are the scenario report's), in bold with its Holm p where it is beyond "
        "chance, and the falls where they differ.",
        "",
    ]
    for scenario in scenarios:
        lines.append(f"- **{scenario}**: {METRICS[scenario]}")
    lines += ["", "| settings | planner | seeds | planning ÷ defaults | falls defaults → "
              "these | beyond chance | " + " | ".join(scenarios) + " |",
              "|---" * (6 + len(scenarios)) + "|"]
    for settings, rows in folders:
        lines += sweep_rows(base_rows, rows, settings, scenarios, base_count)
    path.write_text("\n".join(lines) + "\n", "utf-8")
