"""Two scenario tables side by side (two bikes, or one bike planned two ways): for every
scenario, controller and N ridden in both, each table's falls and metric, the paired
difference over the seeds on which both stayed up, the planning time's ratio, and whether
the two differ beyond chance. A seed is the same ride in both tables (its heading, its
draws), so falls pair up (exact McNemar) and metrics pair up (paired t-test); Holm's
correction holds the whole page's tests to a family-wise 5 %."""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass
from pathlib import Path

from scipy import stats

from cpbp_experiment.stats import ALPHA, holm, mcnemar_exact

from .report import METRICS, _order
from .stats import paired_difference, t_interval


def _groups(rows: list[dict]) -> dict[tuple, dict[int, dict]]:
    groups: dict[tuple, dict[int, dict]] = defaultdict(dict)
    for row in rows:
        key = (row["scenario"], row["controller"], row["trajectories"], row["physics"])
        groups[key][row["seed"]] = row
    return groups


@dataclass
class Pairing:
    """One configuration in both tables, over the seeds both rode."""
    key: tuple
    seeds: int
    falls: tuple[int, int]
    up: tuple[dict[int, float], dict[int, float]]
    planning_ratio: float
    falls_p: float
    metric_p: float


def _metric_p(first: dict[int, float], second: dict[int, float]) -> float:
    """Two-sided paired t-test over the seeds both stayed up on. Fewer than two pairs
    cannot tell (1); pairs that all differ by the same amount have no spread for the
    test: the same number on every seed is no difference (1), another is one (0)."""
    shared = sorted(first.keys() & second.keys())
    differences = [second[s] - first[s] for s in shared]
    if len(differences) < 2:
        return 1.0
    if all(d == differences[0] for d in differences):
        return 1.0 if differences[0] == 0 else 0.0
    return float(stats.ttest_rel([second[s] for s in shared], [first[s] for s in shared]).pvalue)


def pair(first: dict[int, dict], second: dict[int, dict], key: tuple) -> Pairing:
    seeds = sorted(set(first) & set(second))
    sides = [first[s] for s in seeds], [second[s] for s in seeds]
    up = tuple({r["seed"]: r["metric"] for r in side if not r["fell"]} for side in sides)
    falls = tuple(sum(r["fell"] for r in side) for side in sides)
    only_first = sum(first[s]["fell"] and not second[s]["fell"] for s in seeds)
    only_second = sum(second[s]["fell"] and not first[s]["fell"] for s in seeds)
    planning = [sum(r["planning_ms"] for r in side) for side in sides]
    ratio = planning[1] / planning[0] if planning[0] > 0 else math.nan
    return Pairing(key, len(seeds), falls, up, ratio, mcnemar_exact(only_first, only_second),
                   _metric_p(*up))


def pairings(first: list[dict], second: list[dict]) -> list[Pairing]:
    """Every configuration both tables hold, in the report's order."""
    a, b = _groups(first), _groups(second)
    shared = sorted(set(a) & set(b),
                    key=lambda k: (list(METRICS).index(k[0]) if k[0] in METRICS else 99,
                                   k[2], _order(k[1])))
    return [pair(a[key], b[key], key) for key in shared]


def side_by_side(first: list[dict], second: list[dict], names: tuple[str, str]) -> str:
    """The markdown: a line counting the differences, then a table per scenario."""
    found = pairings(first, second)
    if not found:
        return ""
    p_values = [p for f in found for p in (f.falls_p, f.metric_p)]
    reject, adjusted = holm(p_values, ALPHA)
    differing = sum(reject)
    parts = ["", f"{differing} of {len(p_values)} paired tests (falls and metric of each "
             f"configuration) differ beyond chance after Holm at a family-wise "
             f"{ALPHA * 100:.0f} %."]
    scenario = None
    for i, f in enumerate(found):
        if f.key[0] != scenario:
            scenario = f.key[0]
            parts += ["", f"**{METRICS.get(scenario, scenario)}**", "",
                      f"| controller | N | seeds | falls {names[0]} | falls {names[1]} | "
                      f"{names[0]} | {names[1]} | paired difference ({names[1]} − "
                      f"{names[0]}) | planning {names[1]} / {names[0]} | Holm p: falls, "
                      f"metric |", "|---|---|---|---|---|---|---|---|---|---|"]
        marks = [f"**{_p_text(p)}**" if r else _p_text(p)
                 for p, r in zip(adjusted[2 * i:2 * i + 2], reject[2 * i:2 * i + 2])]
        ratio = "–" if math.isnan(f.planning_ratio) else f"{f.planning_ratio:.2f}"
        parts.append(f"| {f.key[1]} | {f.key[2]} | {f.seeds} | {f.falls[0]} | {f.falls[1]} | "
                     f"{t_interval(list(f.up[0].values())).text(2)} | "
                     f"{t_interval(list(f.up[1].values())).text(2)} | "
                     f"{paired_difference(f.up[1], f.up[0]).text(2)} | "
                     f"{ratio} | {marks[0]}, {marks[1]} |")
    return "\n".join(parts)


def _p_text(p: float) -> str:
    return "< 0.0001" if p < 1e-4 else f"{p:.2g}"


def write_comparison(first: list[dict], second: list[dict], names: tuple[str, str],
                     path: Path) -> None:
    text = side_by_side(first, second, names)
    path.write_text(
        f"# The scenarios of {names[0]} and of {names[1]}\n\n"
        "Made by `tools/planner-scenarios report --compare` from both tables: the same "
        "seeds, headings and draws in each; a configuration appears when both tables hold "
        "it, over the seeds both rode. Falls pair by seed (exact McNemar), metrics over the "
        "seeds both stayed up on (paired t-test); the p-values are Holm's, adjusted over "
        "every test on the page, in bold where they reject. Planning is the ratio of the "
        "rides' mean planning times, timed as the rows were ridden (a loaded machine's "
        "figure: `make bench` gives the cost ratios).\n" + (text or "\nNo configuration is "
                                                             "in both.") + "\n")
