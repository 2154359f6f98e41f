"""The scenario report: per scenario, each planner and N with its falls, its metric's mean
and 95 % interval over the rides that stayed up, and its paired difference from combined
(C-PBP warm-started, the game's planner) at the same N over the seeds both stayed up."""

from __future__ import annotations

import textwrap
from collections import defaultdict
from pathlib import Path

from .stats import paired_difference, t_interval

METRICS = {
    "turn": "RMS lean error in a 15° turn at 20 km/h (°)",
    "carve": "RMS lean error at the 30° limit for 8 s near 40 km/h, knocked 3 s in (°)",
    "slalom": "RMS lean error in a ±15° slalom at 20 km/h (°)",
    "reversals": "settled RMS lean error in ±15° reversals every 2 s at 25 km/h (°)",
    "push": "largest lean in the 5 s after a 100–250 N·s shove at 15 km/h (°)",
    "walk": "speed held at walking pace, asked 8 km/h (km/h)",
    "stop10": "full brake from 10 km/h, then standing: stopping distance (m)",
    "stop25": "full brake from 25 km/h, then standing: stopping distance (m)",
    "stop40": "full brake from 40 km/h, then standing: stopping distance (m)",
    "brake-turn": "full brake in a 20° turn at 25 km/h: stopping distance (m)",
    "slope5": "stop on a 5° slope, stand, hill start: rolled back (m)",
    "slope10": "stop on a 10° slope, stand, hill start: rolled back (m)",
    "slope15": "stop on a 15° slope, stand, hill start: rolled back (m)",
    "downhill15": "stop facing down a 15° slope, stand, ride off: crept on the brake (m)",
    "brake60": "full brake from 60 km/h to rest: mean deceleration v₀²/2d from the trigger (g)",
    "brake90": "full brake from 90 km/h to rest: mean deceleration v₀²/2d from the trigger (g)",
    "brake-bend": "full brake in a 25 m bend at 25° of lean (38.5 km/h): mean deceleration (g)",
    "logs": "RMS lean over the test level's logs at 15 km/h (°)",
    **{f"camber{d}-{side}": f"stop on a road falling {d}° to the {side}, stand, ride off: "
                            "largest lean from upright (°)"
       for d in (5, 8, 10) for side in ("left", "right")},
    "slope10-across45": "stop across a 10° slope at 45°, stand, ride off: largest lean "
                        "from upright (°)",
    **{f"bend45-h{h}": f"45° asked at 60 km/h heading {deg}° (or the bike's deepest lean, "
                       "if less): RMS lean error over the last 3 s (°)"
       for h, deg in (("0", "0"), ("22", "22.5"), ("45", "45"))},
    "lowside-wet": "the deepest lean asked at 60 km/h on a wet road (μ 0.5): 1 if it fell "
                   "in a low-side",
}
# Scenarios whose metric is about the fall itself (what kind it was): averaged over every
# ride, not only those that stayed up.
FALL_METRICS = ("lowside-wet",)
# What a full brake reports beside its metric (the rows' `extra`), with its heading.
BRAKE_MEASURES = (("distance_m", "distance (m)"), ("peak_g", "peak 0.1 s (g)"),
                  ("least_step_g", "least step (g)"), ("pitch_deg", "nose down (°)"),
                  ("rear_lift_mm", "rear tyre up (mm)"),
                  ("foot_lift_mm", "rear up as a foot comes down (mm)"),
                  ("rear_on_road", "steps the rear touched"))
# What a deep bend and a stop across a slope report beside their metric: the lean held and
# the radius ridden (against eq. 4.3's for that lean), and the lean the bike stood at.
BEND_MEASURES = (("lean_deg", "lean held (°)"), ("radius_m", "radius ridden (m)"),
                 ("radius_eq43_m", "eq. 4.3's radius at that lean (m)"))
CAMBER_MEASURES = (("stood_downhill_deg", "stood, leaning downhill (°)"),
                   ("on_a_foot", "on a foot"))
ORDER = ("combined", "guided", "optimizer", "sampling", "mppi", "learned", "arcade")
REFERENCE = "combined"


def _order(controller: str) -> int:
    return ORDER.index(controller) if controller in ORDER else len(ORDER)


def scenario_table(rows: list[dict], scenario: str) -> str:
    groups: dict[tuple[str, int], list[dict]] = defaultdict(list)
    for row in rows:
        if row["scenario"] == scenario:
            groups[(row["controller"], row["trajectories"])].append(row)
    lines = [
        f"**{METRICS.get(scenario, scenario)}**",
        "",
        "| planner | N | rides | falls | mean (95 % CI), rides that stayed up | "
        f"paired difference from {REFERENCE} (95 % CI) | planning per step |",
        "|---|---|---|---|---|---|---|",
    ]
    for (controller, n) in sorted(groups, key=lambda k: (k[1], _order(k[0]))):
        mine = groups[(controller, n)]
        counted = (lambda r: True) if scenario in FALL_METRICS else (lambda r: not r["fell"])
        up = {r["seed"]: r["metric"] for r in mine if counted(r)}
        reference = {r["seed"]: r["metric"] for r in groups.get((REFERENCE, n), [])
                     if counted(r)}
        difference = ("–" if controller == REFERENCE
                      else paired_difference(up, reference).text(2))
        planning = sum(r["planning_ms"] for r in mine) / len(mine)
        every = ", every ride" if scenario in FALL_METRICS else ""
        lines.append(f"| {controller} | {n} | {len(mine)} | {sum(r['fell'] for r in mine)} | "
                     f"{t_interval(list(up.values())).text(2)}{every} | {difference} | "
                     f"{planning:.1f} ms |")
    return "\n".join(lines)


def measures_table(rows: list[dict], scenario: str) -> str:
    """What a scenario measured beside its metric, over the rides that stayed up: for the
    full brakes the mean and the worst ride's (for the rear: the most it rose and the
    least it touched), for the deep bends and the stops across slopes the mean and the
    range."""
    groups: dict[tuple[str, int], list[dict]] = defaultdict(list)
    for row in rows:
        if row["scenario"] == scenario and not row["fell"] and row["extra"]:
            groups[(row["controller"], row["trajectories"])].append(row)
    if not groups:
        return ""
    names = {name for group in groups.values() for r in group for name in r["extra"]}
    measures = next((m for m in (BRAKE_MEASURES, BEND_MEASURES, CAMBER_MEASURES)
                     if names & {name for name, _ in m}), None)
    if measures is None:
        return ""
    worst = {"distance_m": max, "peak_g": max, "least_step_g": min, "pitch_deg": max,
             "rear_lift_mm": max, "foot_lift_mm": max, "rear_on_road": min}
    braking = measures is BRAKE_MEASURES
    spread = "mean (worst ride)" if braking else "mean (least to most)"
    lines = [f"*{scenario}, beside the metric: {spread}*", "",
             "| planner | N | " + " | ".join(title for _, title in measures) + " |",
             "|---|---|" + "---|" * len(measures)]
    for (controller, n) in sorted(groups, key=lambda k: (k[1], _order(k[0]))):
        mine = groups[(controller, n)]
        cells = []
        for name, _ in measures:
            values = [r["extra"][name] for r in mine if name in r["extra"]]
            mean = sum(values) / len(values) if values else 0.0
            if not values:
                cells.append("–")
            elif braking:
                cells.append(f"{mean:.2f} ({worst[name](values):.2f})")
            else:
                cells.append(f"{mean:.2f} ({min(values):.2f} to {max(values):.2f})")
        lines.append(f"| {controller} | {n} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def write_report(rows: list[dict], out: Path, bike: str | None = None,
                 settings: dict[str, str] | None = None) -> None:
    scenarios = [s for s in METRICS if any(r["scenario"] == s for r in rows)]
    physics = sorted({r["physics"] for r in rows})
    changed = ", ".join(f"{name} = {value}" for name, value in sorted((settings or {}).items()))
    parts = [
        "# Planners side by side on scripted rides",
        "",
        *([f"On the bike {bike}.", ""] if bike else []),
        *([f"The planners planned with {changed} (`--set`), every other setting at its "
           "default.", ""] if changed else []),
        "Made by `tools/planner-scenarios` from `scenarios.csv` "
        f"({len(rows)} rides, {', '.join(physics) or 'no'} physics, on flat ground unless "
        "the scenario names a slope). Seed *i* "
        "sets the heading, the planner's seed and the scenario's draw, so every planner "
        "meets the same ride *i*; paired differences are over the seeds on which both "
        "stayed up. A negative difference in a lean error or a lean is better than "
        f"{REFERENCE}.",
        "",
        "![Scenario metrics by planner and N](scenarios.png)",
    ]
    for scenario in scenarios:
        parts += ["", scenario_table(rows, scenario)]
        extra = measures_table(rows, scenario)
        if extra:
            parts += ["", extra]
    (out / "scenarios.md").write_text("\n".join(parts) + "\n")
    if rows:
        chart(rows, scenarios, out / "scenarios.png")


def chart(rows: list[dict], scenarios: list[str], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    styles = {"combined": ("tab:orange", "s"), "optimizer": ("tab:blue", "o"),
              "sampling": ("tab:green", "^"), "mppi": ("tab:purple", "D"),
              "guided": ("tab:red", "v"), "learned": ("tab:brown", "X"),
              "arcade": ("black", "P")}
    # Rows of at most four panels, so the chart stays readable however many scenarios.
    columns = min(4, len(scenarios))
    rows_of_panels = -(-len(scenarios) // columns)
    fig, axes = plt.subplots(rows_of_panels, columns, figsize=(4.2 * columns, 4 * rows_of_panels),
                             dpi=110, squeeze=False)
    for ax in axes.flat[len(scenarios):]:
        ax.set_visible(False)
    legend = {}
    for ax, scenario in zip(axes.flat, scenarios):
        mine = [r for r in rows if r["scenario"] == scenario]
        controllers = sorted({r["controller"] for r in mine}, key=_order)
        # N as categories, not a log axis: arcade and learned ride as N = 0, and a scenario ridden at
        # one N alone still shows its controllers side by side.
        counts = sorted({r["trajectories"] for r in mine})
        for k, controller in enumerate(controllers):
            ns = sorted({r["trajectories"] for r in mine if r["controller"] == controller})
            counted = scenario in FALL_METRICS
            intervals = [t_interval([r["metric"] for r in mine if r["controller"] == controller
                                     and r["trajectories"] == n and (counted or not r["fell"])])
                         for n in ns]
            colour, marker = styles.get(controller, ("tab:gray", "x"))
            spread = 0.08 * (k - (len(controllers) - 1) / 2)
            legend[controller] = ax.errorbar(
                [counts.index(n) + spread for n in ns], [i.mean for i in intervals],
                yerr=[[i.mean - i.low for i in intervals], [i.high - i.mean for i in intervals]],
                color=colour, marker=marker, capsize=3, label=controller)
        ax.set_xticks(range(len(counts)), ["alone" if n == 0 else str(n) for n in counts])
        ax.set_xlim(-0.6, len(counts) - 0.4)
        ax.set_xlabel("trajectories N")
        # Wrapped by hand: matplotlib wraps a title only at the figure's edge, so long
        # ones ran into their neighbours' panels.
        ax.set_title(textwrap.fill(METRICS[scenario], 48), fontsize=8.5)
        ax.grid(alpha=0.3)
    ordered = sorted(legend, key=_order)
    axes[0][0].legend([legend[c] for c in ordered], ordered, fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
