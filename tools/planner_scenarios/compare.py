"""Two bikes' scenario tables side by side: for every scenario, controller and N ridden on
both, each bike's falls and metric, and the paired difference over the seeds on which both
stayed up, so a ride that holds on one bike and falls on the other shows at a glance."""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

from .report import METRICS, _order
from .stats import paired_difference, t_interval


def _groups(rows: list[dict]) -> dict[tuple, dict[int, dict]]:
    groups: dict[tuple, dict[int, dict]] = defaultdict(dict)
    for row in rows:
        key = (row["scenario"], row["controller"], row["trajectories"], row["physics"])
        groups[key][row["seed"]] = row
    return groups


def side_by_side(first: list[dict], second: list[dict], names: tuple[str, str]) -> str:
    """The markdown tables, one per scenario both tables hold."""
    a, b = _groups(first), _groups(second)
    shared = sorted(set(a) & set(b),
                    key=lambda k: (list(METRICS).index(k[0]) if k[0] in METRICS else 99,
                                   k[2], _order(k[1])))
    parts, scenario = [], None
    for key in shared:
        if key[0] != scenario:
            scenario = key[0]
            parts += ["", f"**{METRICS.get(scenario, scenario)}**", "",
                      f"| controller | N | seeds | falls {names[0]} | falls {names[1]} | "
                      f"{names[0]} | {names[1]} | paired difference ({names[1]} − "
                      f"{names[0]}) |", "|---|---|---|---|---|---|---|---|"]
        seeds = sorted(set(a[key]) & set(b[key]))
        mine = [a[key][s] for s in seeds], [b[key][s] for s in seeds]
        up = [{r["seed"]: r["metric"] for r in side if not r["fell"]} for side in mine]
        falls = [sum(r["fell"] for r in side) for side in mine]
        parts.append(f"| {key[1]} | {key[2]} | {len(seeds)} | {falls[0]} | {falls[1]} | "
                     f"{t_interval(list(up[0].values())).text(2)} | "
                     f"{t_interval(list(up[1].values())).text(2)} | "
                     f"{paired_difference(up[1], up[0]).text(2)} |")
    return "\n".join(parts)


def write_comparison(first: list[dict], second: list[dict], names: tuple[str, str],
                     path: Path) -> None:
    text = side_by_side(first, second, names)
    path.write_text(
        f"# The scenarios on {names[0]} and on {names[1]}\n\n"
        "Made by `tools/planner-scenarios report --compare` from both tables: the same "
        "seeds, headings and draws on each bike; a configuration appears when both tables "
        "hold it, over the seeds both rode.\n" + (text or "\nNo configuration is in both.")
        + "\n")
