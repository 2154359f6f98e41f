"""Figures from the planner-settings sweeps (issue 59): a folder of scenario rows ridden
with other planner settings, `docs/scenarios/<bike>/horizon/<folder>`, held against the
bike's own table (the nearest folder above with rows: two up, or further for a folder
moved aside to `horizon/superseded/…`), as `tools/planner-scenarios sweep` does.

A folder argument is its path under docs/scenarios (`dirt_125/horizon/value-0.6-n4`),
several joined with commas where a figure pools them; a rider is the planner with the N
the folder rode (`combined-4`); an optional last argument holds every N against the
defaults' rides at that N (`5`: the page's `--base-count 5`)."""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

from planner_scenarios.rows import ScenarioRows, rider_name
from planner_scenarios.sweep import RiderSweep, folder_sweep
from planner_scenarios.timing import paired_ratio, timing_files

from .experiment_figures import COUNT
from .formats import count
from .markers import Figure, FigureError

SHIFT = r"[+−-]?[\d.]+(?:e[+−-]?\d+)?"


def figures(scenarios: Path) -> dict[str, Figure]:
    @cache
    def rows(folder: str) -> tuple[dict, ...]:
        found = ScenarioRows(scenarios / folder / "scenarios.csv").load()
        if not found:
            raise FigureError(f"no scenario rows in docs/scenarios/{folder}")
        return tuple(found)

    def table_above(folder: str) -> str:
        for above in Path(folder).parents:
            if (scenarios / above / "scenarios.csv").exists():
                return str(above)
        raise FigureError(f"no bike's table above docs/scenarios/{folder}")

    def rider(folder: str, name: str, base_count: str | None) -> RiderSweep:
        base = table_above(folder)
        controller, _, n = name.rpartition("-")
        for found in folder_sweep(list(rows(base)), list(rows(folder)),
                                  int(base_count) if base_count else None):
            if found.controller == controller and str(found.ridden) == n:
                return found
        raise FigureError(f"docs/scenarios/{folder} holds no {name} paired with {base}'s "
                          f"rows")

    def beyond(folder: str, name: str, base_count: str | None = None) -> str:
        found = rider(folder, name, base_count)
        return f"{found.differing} of {found.tests}"

    def shift(folder: str, name: str, scenario: str, base_count: str | None = None) -> str:
        found = rider(folder, name, base_count)
        if scenario not in found.shifts or math.isnan(found.shifts[scenario]):
            raise FigureError(f"{name} in docs/scenarios/{folder} has no paired {scenario}")
        # As the sweep page writes its cells (two significant figures, signed), with the
        # prose's minus sign.
        return f"{found.shifts[scenario]:+.2g}".replace("-", "−")

    def falls(folders: str, name: str | None = None, scenario: str | None = None) -> str:
        ridden = [r for folder in folders.split(",") for r in rows(folder)]
        if name:
            ridden = [r for r in ridden if rider_name(r) == name]
        if scenario:
            ridden = [r for r in ridden if r["scenario"] == scenario]
        if not ridden:
            raise FigureError(f"docs/scenarios/{folders} holds no rides of "
                              f"{name or 'any planner'} in {scenario or 'any scenario'}")
        return f"{count(sum(r['fell'] for r in ridden))} in {count(len(ridden))}"

    def timing(folder: str, name: str | None = None) -> str:
        defaults, settings = (r.load() for r in timing_files(scenarios / folder))
        if not defaults or not settings:
            raise FigureError(f"docs/scenarios/{folder} has no timing rows "
                              f"(tools/planner-scenarios time)")
        try:
            return paired_ratio(defaults, settings, name).text()
        except ValueError as error:
            raise FigureError(f"docs/scenarios/{folder}: {error}") from None

    return {
        # "0.47 (0.44–0.50)": planning time with the folder's settings ÷ the defaults,
        # paired ride by ride in its timing rows (one rider's, or every rider's).
        "sweep-timing": Figure(timing, r"[\d.]+ \([\d.]+–[\d.]+\)"),
        # "1 of 16": a planner's paired tests beyond chance after Holm over its folder's.
        "sweep-beyond": Figure(beyond, r"\d+ of \d+"),
        # "+0.021": a scenario's mean paired difference, these settings − the defaults.
        "sweep-shift": Figure(shift, SHIFT),
        # "0 in 1 920": falls in every ride of the folders, every planner; or one rider's
        # ("combined-5"), optionally in one scenario ("push").
        "sweep-falls": Figure(falls, f"{COUNT} in {COUNT}"),
    }
