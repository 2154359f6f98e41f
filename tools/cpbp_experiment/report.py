"""The report: success rates with 95 % Wilson intervals (Markdown and a Figure 5.1-style
bar chart), the cost of an attempt per controller, and the planning-time study
(a Figure 5.2-style chart of control rate against trajectory count)."""

from __future__ import annotations

import csv
from collections import defaultdict
from dataclasses import dataclass, replace
from pathlib import Path
from statistics import median

from .configs import (BASELINES, FOLLOWING_PLANNERS, PLANNERS, THESIS_PLANNERS, Config, Controller,
                      display_order)
from .results import Attempt
from .stats import holm, mcnemar_exact, mean, wilson_interval

# The game steps its controller at 30 Hz: a plan must take at most 33 ms to keep up.
CONTROL_RATE_HZ = 30.0
REAL_TIME_MS = 1000.0 / CONTROL_RATE_HZ
# What the thesis measured on its 4-core laptop (§5.2): frames per second by N, capped at 31 by its 32 ms step.
THESIS_FPS = {5: 31.0, 10: 15.0, 15: 11.0}
TIMING_FIELDS = ("controller", "trajectories", "threads", "samples", "mean_ms", "median_ms",
                 "p95_ms", "physics")


@dataclass
class Summary:
    config: Config
    tries: int
    goals: int
    fell: int
    timeouts: int
    goal_time_s: float
    wall_s: float

    @property
    def rate(self) -> float:
        return self.goals / self.tries

    @property
    def interval(self) -> tuple[float, float]:
        return wilson_interval(self.goals, self.tries)


def summarise(attempts: list[Attempt]) -> dict[Config, Summary]:
    grouped: dict[Config, list[Attempt]] = defaultdict(list)
    for attempt in attempts:
        grouped[attempt.config].append(attempt)
    summaries = {}
    for config, group in grouped.items():
        outcomes = [a.outcome for a in group]
        summaries[config] = Summary(
            config=config,
            tries=len(group),
            goals=outcomes.count("goal"),
            fell=outcomes.count("fell"),
            timeouts=outcomes.count("timeout"),
            goal_time_s=mean([a.time_s for a in group if a.outcome == "goal"]),
            wall_s=mean([a.wall_ms / 1000.0 for a in group]),
        )
    return summaries


def _axes(summaries: dict[Config, Summary]) -> tuple[list[Controller], list[int]]:
    controllers = sorted({c.controller for c in summaries}, key=display_order)
    speeds = sorted({c.speed_kmh for c in summaries})
    return controllers, speeds


def success_table(summaries: dict[Config, Summary]) -> str:
    controllers, speeds = _axes(summaries)
    lines = [
        "| controller | " + " | ".join(f"{s} km/h" for s in speeds) + " |",
        "|---|" + "---|" * len(speeds),
    ]
    for controller in controllers:
        cells = []
        for speed in speeds:
            s = summaries.get(Config(speed, controller))
            if s is None:
                cells.append("–")
                continue
            low, high = s.interval
            cells.append(f"**{100 * s.rate:.1f} %** ({100 * low:.1f}–{100 * high:.1f}) "
                         f"{s.goals}/{s.tries}")
        lines.append(f"| {controller.label} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def outcome_table(summaries: dict[Config, Summary]) -> str:
    controllers, speeds = _axes(summaries)
    lines = [
        "| controller | speed | tries | goal | fell | timeout | 95 % CI width | "
        "mean time to goal | simulation cost per try |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for controller in controllers:
        for speed in speeds:
            s = summaries.get(Config(speed, controller))
            if s is None:
                continue
            low, high = s.interval
            lines.append(
                f"| {controller.label} | {speed} km/h | {s.tries} | {s.goals} | {s.fell} | "
                f"{s.timeouts} | {100 * (high - low):.1f} pp | {s.goal_time_s:.2f} s | "
                f"{s.wall_s:.2f} s |"
            )
    return "\n".join(lines)


def cost_table(summaries: dict[Config, Summary], attempts: list[Attempt]) -> str:
    by_controller: dict[Controller, list[Attempt]] = defaultdict(list)
    for attempt in attempts:
        by_controller[attempt.config.controller].append(attempt)
    # The median beside the mean: tries that shared the machine with a build or a CI run
    # take several times their usual wall time, which moves the mean and not the median.
    lines = [
        "| controller | tries | mean wall time per try | median | per simulated second | "
        "planning per control step | wall time in all (one core) |",
        "|---|---|---|---|---|---|---|",
    ]
    total = 0.0
    for controller in sorted(by_controller, key=display_order):
        group = by_controller[controller]
        wall = sum(a.wall_ms for a in group) / 1000.0
        total += wall
        simulated = sum(a.time_s for a in group)
        planning = mean([a.planning_ms for a in group]) if controller.plans else 0.0
        lines.append(
            f"| {controller.label} | {len(group)} | {wall / len(group):.2f} s | "
            f"{median(a.wall_ms for a in group) / 1000.0:.2f} s | "
            f"{wall / max(simulated, 1e-9):.2f} s | "
            + (f"{planning:.1f} ms |" if controller.plans else "– |")
            + f" {_hours(wall)} |"
        )
    lines.append(f"| all | {len(attempts)} | | | | | {_hours(total)} |")
    return "\n".join(lines)


def _hours(seconds: float) -> str:
    return f"{seconds / 3600:.2f} h" if seconds >= 360 else f"{seconds / 60:.1f} min"


@dataclass(frozen=True)
class PairedTest:
    """Controller A against B at one speed on the attempts both rode (the same bumps)."""

    speed_kmh: int
    first: Controller
    second: Controller
    pairs: int
    both: int
    only_first: int
    only_second: int
    p: float
    holm_p: float = 1.0
    significant: bool = False


def paired_tests(attempts: list[Attempt], across: bool | None = None) -> list[PairedTest]:
    """Each controller against arcade, combined against the optimizer, guided against
    combined at the same N, and each baseline
    (sampling, MPPI) against both C-PBP planners at the same N (in the same physics), and
    each controller in the exact physics against itself in the classic, on the attempts
    both rode (the same bumps), with the exact McNemar test and Holm's correction across
    every test of the family. `across` keeps only the pairs across physics models (True) or
    only those within one (False)."""
    outcome = {(a.config, a.attempt): a.outcome == "goal" for a in attempts}
    configs = {a.config for a in attempts}
    controllers = sorted({c.controller for c in configs}, key=display_order)
    pairs = [(c, Controller("arcade", 0, c.physics)) for c in controllers
             if c.kind != "arcade"]
    pairs += [(c, Controller("optimizer", c.trajectories, c.physics)) for c in controllers
              if c.kind == "combined"]
    pairs += [(c, Controller("combined", c.trajectories, c.physics)) for c in controllers
              if c.kind in FOLLOWING_PLANNERS]
    pairs += [(c, Controller(cpbp, c.trajectories, c.physics)) for c in controllers
              if c.kind in BASELINES for cpbp in THESIS_PLANNERS]
    twins = [(c, c.in_physics("classic")) for c in controllers if c.physics != "classic"]
    # across: only each controller against its classic twin; False: only within a model.
    pairs = twins if across else pairs if across is False else pairs + twins
    tests = []
    for speed in sorted({c.speed_kmh for c in configs}):
        for first, second in pairs:
            a_config, b_config = Config(speed, first), Config(speed, second)
            shared = sorted({i for (c, i) in outcome if c == a_config}
                            & {i for (c, i) in outcome if c == b_config})
            if not shared:
                continue
            a_goal = [outcome[(a_config, i)] for i in shared]
            b_goal = [outcome[(b_config, i)] for i in shared]
            only_a = sum(x and not y for x, y in zip(a_goal, b_goal))
            only_b = sum(y and not x for x, y in zip(a_goal, b_goal))
            tests.append(PairedTest(speed, first, second, len(shared),
                                    sum(x and y for x, y in zip(a_goal, b_goal)), only_a,
                                    only_b, mcnemar_exact(only_a, only_b)))
    reject, adjusted = holm([t.p for t in tests])
    return [replace(t, holm_p=p, significant=r) for t, p, r in zip(tests, adjusted, reject)]


def paired_table(attempts: list[Attempt], across: bool | None = None) -> str:
    """The paired tests (paired_tests) as a Markdown table, Holm's rejections in bold."""
    lines = [
        "| speed | A | B | pairs | both goal | only A | only B | neither | McNemar p | "
        "Holm p |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for t in paired_tests(attempts, across):
        neither = t.pairs - t.both - t.only_first - t.only_second
        holm_p = f"**{t.holm_p:.2g}**" if t.significant else f"{t.holm_p:.2g}"
        lines.append(f"| {t.speed_kmh} km/h | {t.first.label} | {t.second.label} | {t.pairs} | "
                     f"{t.both} | {t.only_first} | {t.only_second} | {neither} | {t.p:.2g} | "
                     f"{holm_p} |")
    return "\n".join(lines)


PLATFORM_COLUMNS = ("godot", "c_library", "cpu_model", "math_path", "code", "commit")


def platform_notes(attempts: list[Attempt], known: dict[str, dict]) -> str:
    """Which platforms the rows were made on (a mix is stated: rows of two platforms need
    not repeat each other's rides) and any row that used a late plan."""
    counts: dict[str, int] = defaultdict(int)
    for attempt in attempts:
        counts[attempt.platform] += 1
    lines = []
    if len(counts) > 1:
        lines += [f"**The rows come from {len(counts)} platforms**, so a ride of one need not "
                  "repeat exactly on another (docs/experiment.md, \"Reproducibility\").", ""]
    lines += ["| platform | rows | " + " | ".join(PLATFORM_COLUMNS) + " |",
              "|---" * (len(PLATFORM_COLUMNS) + 2) + "|"]
    for name, count in sorted(counts.items(), key=lambda item: -item[1]):
        description = known.get(name, {})
        cells = [description.get(c, "not recorded") for c in PLATFORM_COLUMNS]
        lines.append(f"| {name} | {count} | " + " | ".join(cells) + " |")
    late = [a for a in attempts if a.late_plans]
    unknown = sum(1 for a in attempts if a.late_plans is None)
    lines.append("")
    if late:
        lines.append(f"**{len(late)} rows drove a step without its plan** and may not repeat: "
                     + ", ".join(f"{a.config.label} #{a.attempt}" for a in late[:20]))
    else:
        lines.append("No recorded row drove a step without its plan.")
    if unknown:
        lines.append(f"{unknown} rows predate the record of late plans.")
    return "\n".join(lines)


def success_chart(summaries: dict[Config, Summary], path: Path, physics: str = "") -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    controllers, speeds = _axes(summaries)
    # Two legend rows of up to 7 need more width than one.
    fig, ax = plt.subplots(figsize=(10 if len(controllers) <= 7 else 13.5, 5.2), dpi=110)
    width = 0.8 / max(len(controllers), 1)
    colours = _controller_colours(controllers)
    for i, controller in enumerate(controllers):
        xs, rates, below, above = [], [], [], []
        for j, speed in enumerate(speeds):
            s = summaries.get(Config(speed, controller))
            if s is None:
                continue
            low, high = s.interval
            xs.append(j + (i - (len(controllers) - 1) / 2) * width)
            rates.append(100 * s.rate)
            below.append(max(0.0, 100 * (s.rate - low)))
            above.append(max(0.0, 100 * (high - s.rate)))
        # In a chart of both models the exact model's bars are hatched beside the classic.
        hatched = not physics and controller.physics != "classic"
        ax.bar(xs, rates, width * 0.92, label=controller.label, color=colours[controller],
               hatch="//" if hatched else None, edgecolor="white",
               yerr=[below, above], capsize=2.5, error_kw={"elinewidth": 0.8})
    ax.set_xticks(range(len(speeds)), [f"{s} km/h" for s in speeds])
    ax.set_ylim(0, 105)
    ax.set_ylabel("reached the goal (%)")
    ax.set_xlabel("auto-accelerate speed")
    tries = sorted({s.tries for s in summaries.values()})
    count = f"{tries[0]}" if len(tries) == 1 else f"{tries[0]}–{tries[-1]}"
    model = f", {physics} physics" if physics else ""
    ax.set_title(f"Automatic test{model}: success rate per controller ({count} tries each, "
                 "95 % Wilson intervals)")
    ax.grid(axis="y", alpha=0.3)
    ax.legend(ncol=min(len(controllers), 7), fontsize=8, loc="lower center",
              bbox_to_anchor=(0.5, -0.3))
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def _controller_colours(controllers: list[Controller]) -> dict[Controller, str]:
    import matplotlib

    families = {"arcade": "Greys", "optimizer": "Blues", "combined": "Oranges",
                "sampling": "Greens", "mppi": "Purples", "learned": "Reds", "guided": "RdPu"}
    # A controller registered later than these charts gets a family of its own.
    spare = iter(["YlOrBr", "BuGn", "PuBu"])
    for kind in dict.fromkeys(c.kind for c in controllers):
        families.setdefault(kind, next(spare, "Greys"))
    colours = {}
    for kind, cmap_name in families.items():
        members = [c for c in controllers if c.kind == kind]
        cmap = matplotlib.colormaps[cmap_name]
        for k, controller in enumerate(members):
            colours[controller] = matplotlib.colors.to_hex(cmap(0.45 + 0.45 * (k + 1) / len(members)))
    return colours


def read_timing(path: Path) -> list[dict]:
    with open(path, encoding="utf-8") as f:
        return [
            {**row, "trajectories": int(row["trajectories"]), "mean_ms": float(row["mean_ms"]),
             "median_ms": float(row["median_ms"]), "p95_ms": float(row["p95_ms"]),
             # Studies made before the column existed ran the classic model.
             "physics": row.get("physics") or "classic"}
            for row in csv.DictReader(f)
        ]


def write_timing(rows: list[dict], path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    temporary = path.with_suffix(".tmp")
    with open(temporary, "w", encoding="utf-8", newline="") as f:
        writer = csv.DictWriter(f, TIMING_FIELDS, extrasaction="ignore", lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    temporary.replace(path)


def timing_table(rows: list[dict]) -> str:
    lines = [
        "| N | " + " | ".join(f"{k} ms (mean / p95)" for k in _kinds(rows))
        + " | " + " | ".join(f"{k} control rate" for k in _kinds(rows)) + " | real time (≤ 33 ms) |",
        "|---|" + "---|" * (2 * len(_kinds(rows)) + 1),
    ]
    for n in sorted({r["trajectories"] for r in rows}):
        cells, rates, keeps_up = [], [], []
        for kind in _kinds(rows):
            row = next((r for r in rows if r["controller"] == kind and r["trajectories"] == n), None)
            if row is None:
                cells.append("–")
                rates.append("–")
                continue
            cells.append(f"{row['mean_ms']:.1f} / {row['p95_ms']:.1f}")
            rates.append(f"{min(1000 / row['mean_ms'], 999):.0f} Hz")
            keeps_up.append(row["mean_ms"] <= REAL_TIME_MS)
        verdict = "yes" if keeps_up and all(keeps_up) else ("no" if not any(keeps_up) else "partly")
        lines.append(f"| {n} | " + " | ".join(cells) + " | " + " | ".join(rates) + f" | {verdict} |")
    return "\n".join(lines)


def _kinds(rows: list[dict]) -> list[str]:
    return [k for k in PLANNERS if any(r["controller"] == k for r in rows)]


def planning_chart(rows: list[dict], machine: str, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (rate_ax, ms_ax) = plt.subplots(1, 2, figsize=(11, 4.6), dpi=110)
    styles = {"optimizer": ("tab:blue", "o"), "combined": ("tab:orange", "s"),
              "sampling": ("tab:green", "^"), "mppi": ("tab:purple", "D")}
    for kind in _kinds(rows):
        mine = sorted((r for r in rows if r["controller"] == kind), key=lambda r: r["trajectories"])
        ns = [r["trajectories"] for r in mine]
        colour, marker = styles.get(kind, ("tab:red", "x"))
        rate_ax.plot(ns, [1000 / r["mean_ms"] for r in mine], marker=marker, color=colour,
                     label=f"{kind} (this machine)")
        ms_ax.plot(ns, [r["mean_ms"] for r in mine], marker=marker, color=colour,
                   label=f"{kind} mean")
        ms_ax.fill_between(ns, [r["median_ms"] for r in mine], [r["p95_ms"] for r in mine],
                           color=colour, alpha=0.15, label=f"{kind} median–p95")
    rate_ax.plot(list(THESIS_FPS), list(THESIS_FPS.values()), "k^--",
                 label="thesis (4-core laptop, fps)")
    rate_ax.axhline(CONTROL_RATE_HZ, color="tab:red", lw=1, ls=":", label="30 Hz (33 ms) real time")
    ms_ax.axhline(REAL_TIME_MS, color="tab:red", lw=1, ls=":", label="33 ms real-time budget")
    for ax in (rate_ax, ms_ax):
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel("trajectories N")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    ticks = sorted({r["trajectories"] for r in rows})
    for ax in (rate_ax, ms_ax):
        ax.set_xticks(ticks, [str(t) for t in ticks])
    rate_ax.set_ylabel("achievable control rate (Hz)")
    ms_ax.set_ylabel("planning time per control step (ms)")
    fig.suptitle(f"Planning time against trajectory count ({machine})", fontsize=10)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)
