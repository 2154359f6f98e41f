"""The learned controller's report (docs/learned/training.md and losses.png): how the
network was trained (data, rounds, losses, wall time) and how it and the guided planner
ride beside arcade and combined on the same seeds (the test-level experiment's rows and
the scenario tool's, when they have been ridden). `make train` writes it."""

from __future__ import annotations

import argparse
import csv
import json
import struct
import sys
from collections import defaultdict
from pathlib import Path

from cpbp_experiment.stats import mcnemar_exact, wilson_interval
from planner_scenarios.report import METRICS
from planner_scenarios.stats import paired_difference, t_interval

# (controller, N) in the exact physics, as the experiment's rows name them.
RIDERS = (("arcade", 0), ("learned", 0), ("guided", 4), ("guided", 5), ("combined", 5),
          ("combined", 15))
# Pairs compared on the same attempts: the targets (guided at N = 4 is the count
# whose planning costs a third of combined's at N = 15 on 2 threads; docs/benchmarks.md).
PAIRS = ((("learned", 0), ("arcade", 0)), (("guided", 5), ("combined", 15)),
         (("guided", 4), ("combined", 15)), (("guided", 5), ("combined", 5)))
SCENARIOS = ("turn", "carve", "slalom", "push", "walk", "stop40", "slope10")


def model_metadata(path: Path) -> dict:
    data = path.read_bytes()
    (length,) = struct.unpack("<Q", data[:8])
    return json.loads(data[8:8 + length]).get("__metadata__", {})


def losses(data: Path, rounds: int, prefix: str = "round") -> dict[int, list[tuple[int, float,
                                                                                   float]]]:
    """Each round's curve from PREFIX-R.losses.csv (round: the policy's; value: the
    cost-to-go's), for the rounds that have one."""
    curves = {}
    for r in range(rounds + 1):
        path = data / f"{prefix}-{r}.losses.csv"
        if path.exists():
            with path.open() as f:
                curves[r] = [(int(row["epoch"]), float(row["train"]), float(row["held_out"]))
                             for row in csv.DictReader(f)]
    return curves


def loss_chart(curves: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4), dpi=110)
    for r, curve in curves.items():
        epochs = [c[0] for c in curve]
        line, = ax.plot(epochs, [c[1] for c in curve], label=f"round {r}: training")
        ax.plot(epochs, [c[2] for c in curve], "--", color=line.get_color(),
                label=f"round {r}: held-out episodes")
    ax.set_yscale("log")
    ax.set_xlabel("epoch")
    ax.set_ylabel("mean squared error (normalised controls)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def experiment_tables(results: Path) -> list[str]:
    if not results.exists():
        return ["The test-level experiment has not been ridden yet (`make train` does)."]
    goal = {}
    with results.open() as f:
        for row in csv.DictReader(f):
            if row.get("physics") != "exact":
                continue
            key = (row["controller"], int(row["trajectories"]))
            goal[(key, int(row["speed_kmh"]), int(row["attempt"]))] = row["outcome"] == "goal"
    speeds = sorted({s for (_, s, _) in goal})
    lines = ["| speed | " + " | ".join(f"{c}{f'-{n}' if n else ''}" for c, n in RIDERS) + " |",
             "|---|" + "---|" * len(RIDERS)]
    for speed in speeds:
        cells = []
        for rider in RIDERS:
            outcomes = [v for (k, s, _), v in goal.items() if k == rider and s == speed]
            if not outcomes:
                cells.append("–")
                continue
            low, high = wilson_interval(sum(outcomes), len(outcomes))
            cells.append(f"{sum(outcomes)}/{len(outcomes)} ({low:.0%}–{high:.0%})")
        lines.append(f"| {speed} km/h | " + " | ".join(cells) + " |")
    lines += ["", "| speed | A | B | pairs | only A | only B | McNemar p |", "|---|---|---|---|---|---|---|"]
    for a, b in PAIRS:
        for speed in speeds:
            attempts = {at for (k, s, at) in goal if k == a and s == speed}
            attempts &= {at for (k, s, at) in goal if k == b and s == speed}
            if not attempts:
                continue
            only_a = sum(goal[(a, speed, t)] and not goal[(b, speed, t)] for t in attempts)
            only_b = sum(goal[(b, speed, t)] and not goal[(a, speed, t)] for t in attempts)
            name = lambda r: f"{r[0]}{f'-{r[1]}' if r[1] else ''}"  # noqa: E731
            lines.append(f"| {speed} km/h | {name(a)} | {name(b)} | {len(attempts)} | {only_a} | "
                         f"{only_b} | {mcnemar_exact(only_a, only_b):.3f} |")
    return lines


def scenario_tables(path: Path) -> list[str]:
    if not path.exists():
        return ["The scenarios have not been ridden yet (`make train` does)."]
    rows: dict[tuple, dict[int, dict]] = defaultdict(dict)
    with path.open() as f:
        for row in csv.DictReader(f):
            if row["physics"] == "exact":
                key = (row["scenario"], row["controller"], int(row["trajectories"]))
                rows[key][int(row["seed"])] = {"fell": row["fell"].lower() == "true",
                                               "metric": float(row["metric"])}
    lines = ["| scenario | rider | rides | falls | mean (95 % CI) | paired difference |",
             "|---|---|---|---|---|---|"]
    for scenario in SCENARIOS:
        for a, b in PAIRS[:3]:
            for rider, reference in ((a, None), (b, a)):
                mine = rows.get((scenario, *rider), {})
                if not mine:
                    continue
                up = {s: r["metric"] for s, r in mine.items() if not r["fell"]}
                difference = "–"
                if reference is not None:
                    theirs = rows.get((scenario, *reference), {})
                    ref_up = {s: r["metric"] for s, r in theirs.items() if not r["fell"]}
                    them = f"{reference[0]}{f'-{reference[1]}' if reference[1] else ''}"
                    difference = (f"{them} − this: "
                                  f"{paired_difference(ref_up, up).text(2)}")
                    shared = mine.keys() & theirs.keys()
                    only_them = sum(theirs[s]["fell"] and not mine[s]["fell"] for s in shared)
                    only_this = sum(mine[s]["fell"] and not theirs[s]["fell"] for s in shared)
                    if only_them or only_this:
                        difference += (f"; fell only {them}: {only_them}, only this: "
                                       f"{only_this} (McNemar p = "
                                       f"{mcnemar_exact(only_them, only_this):.3f})")
                name = f"{rider[0]}{f'-{rider[1]}' if rider[1] else ''}"
                lines.append(f"| {scenario} | {name} | {len(mine)} | "
                             f"{sum(r['fell'] for r in mine.values())} | "
                             f"{t_interval(list(up.values())).text(2)} | {difference} |")
    lines += ["", "Metrics: " + "; ".join(f"{s}: {METRICS[s]}" for s in SCENARIOS if s in METRICS)]
    return lines


def reference_evaluation() -> list[str]:
    """The reference bike's evaluation: the test-level experiment and the scenarios."""
    return [
        "## The test level (exact physics, the experiment's attempts; 95 % Wilson intervals)",
        "",
        # Between markers that tools/doc-check holds equal to the rows as they grow.
        "<!-- figures: learned-experiment -->",
        *experiment_tables(Path("docs/experiment/results.csv")),
        "<!-- /figures -->",
        "",
        "## Scenarios (exact physics, seeds from 0: the rides column says how many)",
        "",
        "<!-- figures: learned-scenarios -->",
        *scenario_tables(Path("docs/scenarios/scenarios.csv")),
        "<!-- /figures -->",
        "",
    ]


def evaluation_of_bike(bike: str) -> list[str]:
    """Where another bike's model is evaluated: the test-level experiment and the
    reference's scenario rows ride the reference bike, so neither says anything of it."""
    table = f"docs/scenarios/{bike}"
    return [
        "## Evaluation",
        "",
        "The test-level experiment and the reference's scenario table ride the thesis's "
        "bike, not this one, so `make train BIKE=` leaves them alone. This bike's network "
        f"is measured beside the other controllers in its own scenario table, `{table}/` "
        f"(`tools/planner-scenarios run --bike FILE --out {table} --controllers learned,guided`, "
        "then `report`).",
        "",
    ]


VALUE_HEADING = "## The cost-to-go"


def _value_data(round_: int, policy_rounds: bool) -> str:
    """What the cost-to-go of round R was trained on."""
    if round_ == 0:
        return ("the expert's and the policy rounds' recorded plans" if policy_rounds
                else "the expert's recorded plans")
    return f"those and {round_} round{'s' if round_ > 1 else ''} the short-horizon planner drove"


def value_section(data: Path, model: Path | None, policy_rounds: bool = True) -> list[str]:
    """The cost-to-go trained beside the policy (issue 59): its model and each round's
    last losses; nothing when the run trained none. POLICY_ROUNDS: whether the run's
    policy rounds' plans were among its data (not in a cost-to-go-only run)."""
    curves = losses(data, len(list(data.glob("value-*.losses.csv"))), "value")
    if model is None or not model.exists() or not curves:
        return []
    meta = model_metadata(model)
    return [
        VALUE_HEADING,
        "",
        f"- Model: `{model}` ({model.stat().st_size / 1024:.0f} KiB), format "
        f"{meta.get('format')} v{meta.get('format_version')}, {meta.get('layers')} layers, "
        f"{meta.get('activation')}; it predicts ln(1 + the planner's cost over the rest of "
        "its horizon).",
        f"- Training run: {meta.get('training')}.",
        "",
        "| round | trained on | epochs | training loss | held-out loss |",
        "|---|---|---|---|---|",
        *[f"| {r} | {_value_data(r, policy_rounds)} | {c[-1][0] + 1} | {c[-1][1]:.4f} | {c[-1][2]:.4f} |"
          for r, c in curves.items() if c],
        "",
    ]


def with_value_section(report: str, section: list[str]) -> str:
    """REPORT with its cost-to-go section replaced by SECTION, or SECTION put before the
    section after the losses (the evaluation) when it had none: the policy's losses and
    evaluation, which a cost-to-go-only run cannot redo, are kept as they were."""
    lines = report.split("\n")
    if VALUE_HEADING in lines:
        start = lines.index(VALUE_HEADING)
        end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")),
                   len(lines))
    else:
        losses_at = next((i for i, line in enumerate(lines) if line == "## Losses"), None)
        if losses_at is None:
            raise ValueError("the training report has no losses section to follow")
        start = end = next((i for i in range(losses_at + 1, len(lines))
                            if lines[i].startswith("## ")), len(lines))
    return "\n".join(lines[:start] + section + lines[end:])


def write_value_only(data: Path, model: Path, out: Path) -> None:
    """`make train POLICY=0`: the cost-to-go's section of OUT/training.md, written anew."""
    section = value_section(data, model, policy_rounds=False)
    if not section:
        raise ValueError(f"no cost-to-go to report: {model} or {data}/value-*.losses.csv missing")
    path = out / "training.md"
    if not path.exists():
        raise ValueError(f"{path} does not exist: a cost-to-go-only run reports beside the "
                         "policy's training report")
    path.write_text(with_value_section(path.read_text("utf-8"), section), "utf-8")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--data", type=Path, required=True)
    parser.add_argument("--rounds", type=int, required=True)
    parser.add_argument("--model", type=Path, required=True)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--minutes", type=int, required=True)
    parser.add_argument("--value-model", type=Path, help="the cost-to-go the run trained")
    parser.add_argument("--bike", help="the bike file's name when the model is another bike's "
                        "than the reference (its evaluation is its own scenario table)")
    parser.add_argument("--value-only", action="store_true", help="only the cost-to-go "
                        "was trained (make train POLICY=0): rewrite its section of "
                        "OUT/training.md and keep the rest")
    args = parser.parse_args()
    if args.value_only:
        try:
            write_value_only(args.data, args.value_model, args.out)
        except (ValueError, OSError) as error:
            print(f"learned report: {error}", file=sys.stderr)
            return 2
        print(f"learned report: the cost-to-go in {args.out / 'training.md'}")
        return 0
    args.out.mkdir(parents=True, exist_ok=True)
    curves = losses(args.data, args.rounds)
    if curves:
        loss_chart(curves, args.out / "losses.png")
    meta = model_metadata(args.model)
    last = {r: c[-1] for r, c in curves.items() if c}
    lines = [
        "# The learned controller: training and evaluation",
        "",
        f"Written by `make train`, whose last invocation took {args.minutes} min on this "
        "machine (a resumed run counts only what it did itself; docs/learned-controller.md "
        "itemises the run that made the committed model and says what the network sees).",
        "",
        f"- Model: `{args.model}` ({args.model.stat().st_size / 1024:.0f} KiB), "
        f"format {meta.get('format')} v{meta.get('format_version')}, "
        f"feature list v{meta.get('features_version')}, {meta.get('layers')} layers, "
        f"{meta.get('activation')}.",
        f"- Training run: {meta.get('training')}.",
        "",
        "## Losses",
        "",
        "![losses](losses.png)",
        "",
        "| round | epochs | training loss | held-out loss |",
        "|---|---|---|---|",
        *[f"| {r} | {c[0] + 1} | {c[1]:.4f} | {c[2]:.4f} |" for r, c in last.items()],
        "",
        *value_section(args.data, args.value_model),
        *(evaluation_of_bike(args.bike) if args.bike else reference_evaluation()),
    ]
    (args.out / "training.md").write_text("\n".join(lines))
    print(f"learned report: {args.out / 'training.md'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
