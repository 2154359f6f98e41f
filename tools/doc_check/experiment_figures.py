"""Figures from the experiment's rows (docs/experiment/results.csv and timing.csv).

A controller argument is a label as the experiment writes it (`arcade`, `combined-5`,
`guided-5`), in the exact physics unless it ends in `:classic`; several are joined with
commas and `*` stands for any N (`optimizer-*,combined-*`, or `*` for every controller).
Speeds are one (`10`), a range (`10-30`), a list (`5,30`) or every speed (`all`, the
default where a speed may be left out)."""

from __future__ import annotations

import fnmatch
import json
from functools import cached_property
from pathlib import Path
from statistics import median

from cpbp_experiment.configs import Controller
from cpbp_experiment.report import REAL_TIME_MS, PairedTest, paired_tests, read_timing
from cpbp_experiment.results import Attempt, ResultsFile
from cpbp_experiment.stats import mcnemar_exact, wilson_interval

from .formats import count, format_p, percent_range
from .markers import Figure, FigureError

COUNT = r"\d[\d ]*"
DECIMAL = r"-?[\d.]+"


class ExperimentRows:
    def __init__(self, folder: Path):
        self.folder = folder

    @cached_property
    def attempts(self) -> list[Attempt]:
        return ResultsFile(self.folder / "results.csv").load()

    @cached_property
    def exact_tests(self) -> list[PairedTest]:
        """The report's family of paired tests in the exact physics (Holm across them)."""
        exact = [a for a in self.attempts if a.config.controller.physics == "exact"]
        return paired_tests(exact, across=False)

    @cached_property
    def timing(self) -> list[dict]:
        return read_timing(self.folder / "timing.csv")

    def select(self, controllers: str, speeds: str = "all") -> list[Attempt]:
        patterns = [(c.partition(":")[0], c.partition(":")[2] or "exact")
                    for c in controllers.split(",")]
        wanted = _speeds(speeds)

        def matches(controller: Controller) -> bool:
            name = controller.in_physics("classic").label
            return any(controller.physics == physics and fnmatch.fnmatchcase(name, pattern)
                       for pattern, physics in patterns)

        chosen = [a for a in self.attempts
                  if (wanted is None or a.config.speed_kmh in wanted)
                  and matches(a.config.controller)]
        if not chosen:
            raise FigureError(f"no rows of {controllers} at {speeds} km/h")
        return chosen

    def test(self, first: str, second: str, speed: str) -> tuple[PairedTest, bool]:
        """The paired test of two controllers at a speed, and whether it names them the
        other way round."""
        a, b = (Controller.parse(c if ":" in c else f"{c}:exact") for c in (first, second))
        for t in self.exact_tests:
            if t.speed_kmh == int(speed) and {t.first, t.second} == {a, b}:
                return t, t.first != a
        raise FigureError(f"the report pairs no {first} with {second} at {speed} km/h")

    def split(self, first: str, second: str, speed: str) -> str:
        t, swapped = self.test(first, second, speed)
        mine, theirs = (t.only_second, t.only_first) if swapped else (t.only_first, t.only_second)
        return f"{mine} to {theirs}"

    @cached_property
    def platforms(self) -> list[dict]:
        """The platforms (platforms.json) the exact physics' rows were ridden on."""
        known = json.loads((self.folder / "platforms.json").read_text(encoding="utf-8"))
        used = {a.platform for a in self.attempts if a.config.controller.physics == "exact"}
        return [known.get(name, {}) for name in sorted(used)]

    def wall(self, controllers: str, how: str, speeds: str = "all") -> float:
        walls = [a.wall_ms / 1000.0 for a in self.select(controllers, speeds)]
        return median(walls) if how == "median" else sum(walls) / len(walls)

    def plan_ms(self, kind: str, trajectories: str) -> float:
        for row in self.timing:
            if row["controller"] == kind and int(row["trajectories"]) == int(trajectories) \
                    and row.get("physics", "exact") == "exact":
                return float(row["mean_ms"])
        raise FigureError(f"no timing row of {kind} at N = {trajectories}")

    def bike(self, folder: str) -> ExperimentRows:
        """Another bike's run, in a folder of its own here (docs/experiment/sport_600)."""
        return ExperimentRows(self.folder / folder)

    def real_time_count(self, kind: str) -> str:
        counts = [int(r["trajectories"]) for r in self.timing if r["controller"] == kind
                  and r.get("physics", "exact") == "exact" and float(r["mean_ms"]) <= REAL_TIME_MS]
        if not counts:
            raise FigureError(f"no N plans {kind} in real time")
        return str(max(counts))


def _speeds(speeds: str) -> set[int] | None:
    """The speeds `10`, `10-30` or `5,30` name (None: every speed)."""
    if speeds == "all":
        return None
    chosen: set[int] = set()
    for item in speeds.split(","):
        first, _, last = item.partition("-")
        if not first.isdigit() or not (last or first).isdigit():
            raise FigureError(f"speeds are km/h like 10, 10-30 or 5,30, not '{speeds}'")
        chosen.update(range(int(first), int(last or first) + 1))
    return chosen


def _goals(attempts: list[Attempt]) -> int:
    return sum(a.outcome == "goal" for a in attempts)


P_FORM = r"[\d.]+(?:·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?"


def _bike_split(rows: ExperimentRows, first: str, second: str, speed: str) -> tuple[int, int]:
    """Two bikes' runs (`street_390/arcade`, a folder under docs/experiment and a
    controller; the folder may be a bike's superseded rows,
    `sport_600/superseded/before-wrists-follow/arcade`) paired attempt by attempt at a
    speed (or speeds, `10-25`, each attempt paired with the same attempt at its speed):
    the tries only the first reached the goal in, and those only the second did. The folder
    may be a run with other planner settings
    (`dirt_125/horizon/value-0.6-n4/combined-4`)."""
    outcomes = []
    for rider in (first, second):
        folder, _, controller = rider.rpartition("/")
        outcomes.append({(a.config.speed_kmh, a.attempt): a.outcome == "goal"
                         for a in rows.bike(folder).select(controller, speed)})
    shared = outcomes[0].keys() & outcomes[1].keys()
    return (sum(outcomes[0][i] and not outcomes[1][i] for i in shared),
            sum(outcomes[1][i] and not outcomes[0][i] for i in shared))


def figures(rows: ExperimentRows) -> dict[str, Figure]:
    def chosen(c: str, s: str = "all") -> tuple[int, int]:
        attempts = rows.select(c, s)
        return _goals(attempts), len(attempts)

    def bike_chosen(b: str, c: str, s: str = "all") -> tuple[int, int]:
        attempts = rows.bike(b).select(c, s)
        return _goals(attempts), len(attempts)

    def goals(c: str, s: str = "all") -> str:
        return "{} of {}".format(*map(count, chosen(c, s)))

    def fails(c: str, s: str = "all") -> str:
        g, n = chosen(c, s)
        return count(n - g)

    def rate(c: str, s: str) -> str:
        g, n = chosen(c, s)
        return f"{100 * g / n:.1f}".removesuffix(".0") + " %"

    def width(c: str, s: str) -> str:
        low, high = wilson_interval(*chosen(c, s))
        return f"{100 * (high - low):.1f}"

    def clean_width(n: str) -> str:
        return f"{100 * (1 - wilson_interval(int(n), int(n))[0]):.1f}"

    def median_ratio(a: str, b: str) -> str:
        return f"{rows.wall(a, 'median') / rows.wall(b, 'median'):.2f}×"

    def core_hours() -> str:
        exact = [a for a in rows.attempts if a.config.controller.physics == "exact"]
        return f"{sum(a.wall_ms for a in exact) / 3.6e6:.1f}"

    def distinct(field: str) -> str:
        return str(len({p.get(field) for p in rows.platforms}))

    return {
        # "497 of 500": goals of tries; "497/500", as the tables write it.
        "goals": Figure(goals, f"{COUNT} of {COUNT}"),
        "cell": Figure(lambda c, s: "{}/{}".format(*chosen(c, s)), r"\d+/\d+"),
        "tries": Figure(lambda c, s="all": count(chosen(c, s)[1]), COUNT),
        "fails": Figure(fails, COUNT),
        # "87 %": the success rate, to a tenth where it is not whole.
        "rate": Figure(rate, rf"{DECIMAL} %"),
        # "97.2–99.9 %": the 95 % Wilson interval; "2.7": its width in percentage points.
        "interval": Figure(lambda c, s: percent_range(*wilson_interval(*chosen(c, s))),
                           rf"{DECIMAL}–{DECIMAL} %"),
        "width": Figure(width, DECIMAL),
        # The interval of a clean record of n tries: "98.1–100 %" and "1.9".
        "clean-interval": Figure(lambda n: percent_range(*wilson_interval(int(n), int(n))),
                                 rf"{DECIMAL}–{DECIMAL} %"),
        "clean-width": Figure(clean_width, DECIMAL),
        # "21 to 0": the first's goals the second missed, to the second's the first missed.
        "split": Figure(rows.split, f"{COUNT} to {COUNT}"),
        # The exact McNemar test's p of a pair in the report, alone and after Holm.
        "p": Figure(lambda a, b, s: format_p(rows.test(a, b, s)[0].p), P_FORM),
        "holm": Figure(lambda a, b, s: format_p(rows.test(a, b, s)[0].holm_p), P_FORM),
        "tests": Figure(lambda: str(len(rows.exact_tests)), COUNT),
        # Wall time per try, one planning thread per worker: "4.52 s".
        "median-wall": Figure(lambda c, s="all": f"{rows.wall(c, 'median', s):.2f} s",
                              rf"{DECIMAL} s"),
        "mean-wall": Figure(lambda c, s="all": f"{rows.wall(c, 'mean', s):.2f} s",
                            rf"{DECIMAL} s"),
        "median-ratio": Figure(median_ratio, rf"{DECIMAL}×"),
        "core-hours": Figure(core_hours, DECIMAL),
        # How many platforms the exact rows come from, the commits whose code they ran and
        # the distinct native-library builds among them.
        "platforms": Figure(lambda: str(len(rows.platforms)), COUNT),
        "platform-commits": Figure(lambda: distinct("commit"), COUNT),
        "native-builds": Figure(lambda: distinct("native_build"), COUNT),
        # Figure 5.2: mean planning time per control step (ms), its rate, and the largest N
        # in real time.
        "plan-ms": Figure(lambda k, n: f"{rows.plan_ms(k, n):.1f}", DECIMAL),
        "plan-hz": Figure(lambda k, n: f"{min(1000 / rows.plan_ms(k, n), 999):.0f} Hz",
                          r"\d+ Hz"),
        "real-time-n": Figure(rows.real_time_count, COUNT),
        # Another bike's run (docs/experiment/<folder>): "149/200" and, paired with a
        # second bike's on the same attempts, "50 to 0" and its exact McNemar p.
        "bike-cell": Figure(lambda b, c, s: "{}/{}".format(*bike_chosen(b, c, s)), r"\d+/\d+"),
        "bike-goals": Figure(lambda b, c, s="all": "{} of {}".format(
            *map(count, bike_chosen(b, c, s))), f"{COUNT} of {COUNT}"),
        "bike-split": Figure(lambda a, b, s: "{} to {}".format(*_bike_split(rows, a, b, s)),
                             f"{COUNT} to {COUNT}"),
        "bike-p": Figure(lambda a, b, s: format_p(mcnemar_exact(*_bike_split(rows, a, b, s))),
                         P_FORM),
    }
