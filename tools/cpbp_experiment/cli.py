"""Command line of the experiment (tools/experiment; `make experiment` runs `all`)."""

from __future__ import annotations

import argparse
import os
import sys
from datetime import date
from pathlib import Path

from . import report
from .configs import (THESIS_CONTROLLERS, THESIS_SPEEDS, TIMING_COUNTS, Config, parse_controllers,
                      parse_counts, parse_speeds)
from .results import ResultsError, ResultsFile, check_seed
from .runner import Progress, WorkerError, cpu_description, measure_planning, plan_blocks, run_blocks

RESULTS = "results.csv"
TIMING = "timing.csv"
REPORT = "report.md"
SUCCESS_CHART = "success.png"
PLANNING_CHART = "planning.png"
WORKER_LOG = "workers.log"


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    out = Path(args.out)
    try:
        if args.command in ("timing", "all") and (args.command == "timing" or
                                                  not (out / TIMING).exists()):
            timing(args, out)
        if args.command in ("run", "all"):
            run(args, out)
        if args.command in ("run", "report", "all"):
            write_report(out)
    except (ResultsError, WorkerError, ValueError) as error:
        print(f"experiment: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"\nexperiment: stopped; every finished attempt is in {out / RESULTS}, and "
              "the same command resumes from there", file=sys.stderr)
        return 130
    return 0


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="tools/experiment",
        description="The thesis's automatic test and planning-time study, headless, on the "
        "game's own test level. Results are appended to OUT/results.csv as each attempt "
        "ends; rerunning the same command resumes.",
    )
    parser.add_argument("command", choices=("all", "run", "timing", "report"), nargs="?",
                        default="all", help="all (default): timing if not measured yet, "
                        "run, report")
    parser.add_argument("--out", default="build/experiment",
                        help="directory of results.csv, timing.csv and the report")
    parser.add_argument("--tries", type=_whole(1, 100_000), default=500,
                        help="attempts per configuration (default 500, as the thesis)")
    parser.add_argument("--speeds", type=parse_speeds,
                        default=list(THESIS_SPEEDS), help="km/h, comma-separated "
                        "(default 10,15,20,25)")
    parser.add_argument("--controllers", type=parse_controllers,
                        default=parse_controllers(",".join(THESIS_CONTROLLERS)),
                        help="comma-separated: arcade, optimizer-N, combined-N (default "
                        "arcade and both planners with N = 5, 10, 15)")
    parser.add_argument("--seed", type=_whole(0, 1_000_000_000), default=1000,
                        help="attempt i meets the bumps of seed SEED + i (default 1000)")
    parser.add_argument("--jobs", type=_whole(1, 256), default=os.cpu_count() or 1,
                        help="workers at once (default: one per core)")
    parser.add_argument("--threads", type=_whole(0, 64), default=None,
                        help="planning threads per worker (default 1 with several jobs, "
                        "else 0: one per core)")
    parser.add_argument("--counts", type=parse_counts, default=list(TIMING_COUNTS),
                        help="trajectory counts of the timing study")
    parser.add_argument("--steps", type=_whole(10, 100_000), default=150,
                        help="control steps timed per trajectory count (default 150)")
    return parser


def _whole(low: int, high: int):
    def parse(text: str) -> int:
        if not text.isdigit() or not low <= int(text) <= high:
            raise argparse.ArgumentTypeError(f"expected a whole number within {low}–{high}")
        return int(text)

    return parse


def run(args: argparse.Namespace, out: Path) -> None:
    results = ResultsFile(out / RESULTS)
    saved = results.load()
    check_seed(saved, args.seed, results.path)
    configs = [Config(s, c) for s in args.speeds for c in args.controllers]
    done = {a.key for a in saved}
    blocks = plan_blocks(configs, args.tries, done)
    total = len(configs) * args.tries
    missing = sum(b.count for b in blocks)
    threads = args.threads if args.threads is not None else (1 if args.jobs > 1 else 0)
    print(f"experiment: {len(configs)} configurations × {args.tries} tries; {total - missing} "
          f"already in {results.path}, {missing} to run with {args.jobs} workers "
          f"({threads or 'all'} planning thread(s) each)", file=sys.stderr, flush=True)
    progress = Progress(total=total, jobs=args.jobs, done_before=total - missing)
    run_blocks(blocks, results, progress, args.seed, args.jobs, threads, out / WORKER_LOG)


def timing(args: argparse.Namespace, out: Path) -> None:
    print(f"experiment: timing the planners on {cpu_description()} (nothing else should run)",
          file=sys.stderr, flush=True)
    rows = []
    for kind in ("optimizer", "combined"):
        for row in measure_planning(kind, args.counts, args.steps, 15, args.seed,
                                    out / WORKER_LOG):
            rows.append(row)
    report.write_timing(rows, out / TIMING)
    (out / "machine.txt").write_text(f"{cpu_description()}, measured {date.today()}\n")


def write_report(out: Path) -> None:
    attempts = ResultsFile(out / RESULTS).load()
    sections = ["# Experiment report", "",
                "Generated by `tools/experiment report` from `results.csv` and `timing.csv`; "
                "see docs/results.md for the discussion.", ""]
    if attempts:
        summaries = report.summarise(attempts)
        report.success_chart(summaries, out / SUCCESS_CHART)
        sections += [
            "## Success rate (reached the goal), 95 % Wilson score intervals", "",
            report.success_table(summaries), "", f"![success rates]({SUCCESS_CHART})", "",
            "## Outcomes and interval widths", "", report.outcome_table(summaries), "",
            "## Paired comparisons", "",
            "Attempt *i* of every controller meets the same bumps, so the attempts pair up. "
            "*only A*: A reached the goal and B did not. The exact two-sided McNemar test "
            "asks whether such a split could be chance; **bold** is p < 0.05, not "
            "corrected for the number of comparisons.", "",
            report.paired_table(attempts), "",
            "## Cost of an attempt (one planning thread per worker)", "",
            report.cost_table(summaries, attempts), "",
        ]
    if (out / TIMING).exists():
        rows = report.read_timing(out / TIMING)
        machine_file = out / "machine.txt"
        machine = machine_file.read_text().strip() if machine_file.exists() else "this machine"
        report.planning_chart(rows, machine, out / PLANNING_CHART)
        sections += [
            "## Planning time per control step (every core planning, as in the game)", "",
            f"Measured on {machine}.", "", report.timing_table(rows), "",
            f"![planning time]({PLANNING_CHART})", "",
        ]
    temporary = out / (REPORT + ".tmp")
    out.mkdir(parents=True, exist_ok=True)
    temporary.write_text("\n".join(sections), encoding="utf-8")
    temporary.replace(out / REPORT)
    print(f"experiment: report written to {out / REPORT}", file=sys.stderr)
