"""Figures from the scenario tool's rows (docs/scenarios/scenarios.csv).

A rider argument is `arcade`, `learned` or a planner with its N (`combined-15`), in the
exact physics; a scenario is the tool's name for it (`turn`, `push`, `stop40`). A rider
ending in `@FOLDER` is read from the rows a change superseded, `superseded/FOLDER/` beside
the table; one starting `BIKE/` from another bike's table, `BIKE/` beside it
(`street_390/optimizer-10@trial-frame-roll-cost`). A metric is averaged over the rides that
stayed up, as the scenario report does."""

from __future__ import annotations

import csv
from collections import defaultdict
from functools import cached_property
from pathlib import Path

from planner_scenarios.stats import paired_difference, t_interval

from cpbp_experiment.stats import mcnemar_exact

from .experiment_figures import P_FORM
from .formats import count, format_p
from .markers import Figure, FigureError

DECIMAL = r"−?-?[\d.]+"


class ScenarioRows:
    def __init__(self, path: Path):
        self.path = path
        self._others: dict[Path, ScenarioRows] = {}

    @cached_property
    def rides(self) -> dict[tuple[str, str], dict[int, tuple[bool, float]]]:
        """(scenario, rider) → seed → (fell, metric), exact physics."""
        rides: dict[tuple[str, str], dict[int, tuple[bool, float]]] = defaultdict(dict)
        if not self.path.exists():
            raise FigureError(f"no scenario rows at {self.path}")
        with self.path.open(newline="") as f:
            for row in csv.DictReader(f):
                if row["physics"] != "exact":
                    continue
                n = int(row["trajectories"])
                rider = row["controller"] if row["controller"] in ("arcade", "learned") \
                    else f"{row['controller']}-{n}"
                rides[(row["scenario"], rider)][int(row["seed"])] = (
                    row["fell"].lower() == "true", float(row["metric"]))
        return rides

    def of(self, scenario: str, rider: str) -> dict[int, tuple[bool, float]]:
        bike, slash, rest = rider.partition("/")
        if slash:
            return self._other(Path(bike)).of(scenario, rest)
        rider, _, folder = rider.partition("@")
        if folder:
            return self._other(Path("superseded") / folder).of(scenario, rider)
        found = self.rides.get((scenario, rider))
        if not found:
            raise FigureError(f"no {scenario} rows of {rider}")
        return found

    def _other(self, folder: Path) -> ScenarioRows:
        """The rows of a table in `folder`, beside this one."""
        if folder not in self._others:
            self._others[folder] = ScenarioRows(self.path.parent / folder / self.path.name)
        return self._others[folder]

    def standing(self, scenario: str, rider: str) -> dict[int, float]:
        return {seed: metric for seed, (fell, metric) in self.of(scenario, rider).items()
                if not fell}


def _signed(x: float, digits: int) -> str:
    """A signed decimal with a real minus sign, as the prose writes it."""
    return f"{x:.{digits}f}".replace("-", "−")


def figures(rows: ScenarioRows) -> dict[str, Figure]:
    def mean(scenario: str, rider: str, digits: str = "2") -> str:
        return _signed(t_interval(list(rows.standing(scenario, rider).values())).mean,
                       int(digits))

    def difference(scenario: str, first: str, second: str, digits: str = "2") -> str:
        d = paired_difference(rows.standing(scenario, first), rows.standing(scenario, second))
        n = int(digits)
        return f"{_signed(d.mean, n)} ({_signed(d.low, n)} to {_signed(d.high, n)})"

    def falls(scenario: str, rider: str) -> str:
        ridden = rows.of(scenario, rider)
        return f"{count(sum(fell for fell, _ in ridden.values()))} in {count(len(ridden))}"

    def fall_split(scenarios: str, first: str, second: str) -> tuple[int, int]:
        # "bend45-h0+bend45-h22": the seeds of each scenario pooled, each paired with itself.
        only_first = only_second = 0
        for scenario in scenarios.split("+"):
            a, b = rows.of(scenario, first), rows.of(scenario, second)
            shared = a.keys() & b.keys()
            only_first += sum(a[s][0] and not b[s][0] for s in shared)
            only_second += sum(b[s][0] and not a[s][0] for s in shared)
        return only_first, only_second

    return {
        # "4 to 0": the seeds where only the first fell, to those where only the second did.
        "scenario-fall-split": Figure(lambda sc, a, b: "{} to {}".format(*fall_split(sc, a, b)),
                                      r"\d+ to \d+"),
        # The exact McNemar test of those falls.
        "scenario-fall-p": Figure(lambda sc, a, b: format_p(mcnemar_exact(*fall_split(sc, a, b))),
                                  P_FORM),
        # "0.43": the metric's mean over the rides that stayed up.
        "scenario-mean": Figure(mean, DECIMAL),
        # "−0.06 (−0.15 to 0.04)": the paired difference first − second with its interval.
        "scenario-difference": Figure(difference,
                                      rf"{DECIMAL} \({DECIMAL} to {DECIMAL}\)"),
        # "11 in 30": falls in rides.
        "scenario-falls": Figure(falls, r"\d[\d ]* in \d[\d ]*"),
    }
