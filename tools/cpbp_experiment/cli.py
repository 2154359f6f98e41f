"""Command line of the experiment (tools/experiment; `make experiment` runs `all`)."""

from __future__ import annotations

import argparse
import os
import sys
from datetime import date
from pathlib import Path

from . import report
from .document import PLATFORMS, RESULTS, TIMING, write_report
from .compare import compare, held_at
from .bikes import Bike
from .configs import (THESIS_CONTROLLERS, THESIS_PLANNERS, THESIS_SPEEDS, TIMING_COUNTS, Config,
                      display_order, parse_attempts, parse_controllers, parse_counts,
                      parse_speeds, protocol_tries)
from .fingerprint import FingerprintError, PlatformStore, fingerprint, identity, refusal
from .results import Attempt, ResultsError, ResultsFile, check_bike, check_seed
from .progress import Progress
from .runner import (PROJECT_ROOT, Platform, WorkerError, cpu_description,
                     measure_planning, plan_blocks, run_blocks, worker_platform)
from .value_model import keep_value_record
from .verify import choose, parse_rows, verify

WORKER_LOG = "workers.log"
# Attempts per named configuration, as the thesis rode.
DEFAULT_TRIES = 500
# The planning-time study runs in the physics the game rides.
TIMING_PHYSICS = "exact"


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    # verify checks only the configurations named; everything else rides them all.
    named = args.speeds is not None or args.controllers is not None
    # compare filters by what was named, each on its own.
    args.named_speeds, args.named_controllers = args.speeds, args.controllers
    args.planned = planned_tries(args.speeds, args.controllers, args.tries)
    args.chosen_configs = set(args.planned) if named else None
    out = Path(args.out)
    try:
        args.bike = Bike.of_file(PROJECT_ROOT, args.bike, args.model, args.set)
        if args.command in ("timing", "all") and (args.command == "timing" or
                                                  not (out / TIMING).exists()):
            timing(args, out)
        if args.command in ("run", "all"):
            run(args, out)
        if args.command in ("run", "report", "all"):
            write_report(out)
        if args.command == "platform":
            for key, value in sorted(current_platform(out, record=False)[1].items()):
                print(f"{key}: {value}")
        if args.command == "verify":
            return check_rows(args, out)
        if args.command == "compare":
            return compare_with(args, out)
    except (ResultsError, WorkerError, FingerprintError, ValueError) as error:
        print(f"experiment: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"\nexperiment: stopped; every finished attempt is in {out / RESULTS}, and "
              "the same command resumes from there", file=sys.stderr)
        return 130
    return 0


def planned_tries(speeds: list[int] | None, controllers: list | None,
                  tries: int | None) -> dict[Config, int]:
    """What a run rides: the game protocol (configs.GAME_PROTOCOL, every count raised to
    --tries) unless --speeds or --controllers name configurations, which then ride --tries
    each (500, as the thesis, by default); a missing one of the two is the thesis's."""
    if speeds is None and controllers is None:
        return protocol_tries(tries or 0)
    speeds = speeds or list(THESIS_SPEEDS)
    controllers = controllers or parse_controllers(
        ",".join(f"{label}:exact" for label in THESIS_CONTROLLERS))
    return {Config(s, c): tries or DEFAULT_TRIES for s in speeds for c in controllers}


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="tools/experiment",
        description="The thesis's automatic test and planning-time study, headless, on the "
        "game's own test level. Results are appended to OUT/results.csv as each attempt "
        "ends; rerunning the same command resumes.",
    )
    parser.add_argument("command", choices=("all", "run", "timing", "report", "verify",
                                            "compare", "platform"), nargs="?",
                        default="all", help="all (default): timing if not measured yet, "
                        "run, report; verify: re-ride saved rows and compare; compare: pair "
                        "OUT's rows with --before's, attempt by attempt; platform: print "
                        "this machine's fingerprint")
    parser.add_argument("--out", default="build/experiment",
                        help="directory of results.csv, timing.csv and the report")
    parser.add_argument("--tries", type=_whole(1, 100_000), default=None,
                        help="attempts per configuration: with --speeds or --controllers "
                        f"each rides this many (default {DEFAULT_TRIES}, as the thesis); "
                        "without them, the game protocol's counts are raised to at least "
                        "this")
    parser.add_argument("--speeds", type=parse_speeds,
                        default=None, help="km/h, comma-separated (default: the game "
                        "protocol's, or 10,15,20,25 with --controllers)")
    parser.add_argument("--controllers", type=parse_controllers,
                        default=None,
                        help="comma-separated: arcade, learned, optimizer-N, combined-N, "
                        "guided-N, sampling-N, mppi-N, each with :exact for the exact physics "
                        "model (default: the game protocol's, or with --speeds arcade and "
                        "both C-PBP planners with N = 5, 10, 15, exact)")
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
    parser.add_argument("--cluster", nargs="?", const="", default=None, metavar="ADDRESS",
                        help="run: ride on a Dask cluster: ADDRESS of its scheduler (e.g. "
                        "tcp://host:8786), 'local' for one started here with --jobs "
                        "workers, or nothing for Dask's own DASK_SCHEDULER_ADDRESS "
                        "(docs/experiment.md, \"On several machines\")")
    parser.add_argument("--bike", default=None, metavar="FILE",
                        help="a bike file in the project to ride (default: the reference "
                        "bike, scenes/bike/bikes/street_350.tres); keep its rows in an --out "
                        "of their own")
    parser.add_argument("--model", default=None, metavar="FILE",
                        help="the learned controllers' network, a model file in the project "
                        "(default: the bike's own, models/policy-<bike>.safetensors): ride a "
                        "bike with another bike's network")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="plan with a planner's setting other than its default "
                        "(horizon=0.6, terminal_value=true), repeatable; the rows name "
                        "them (street_390@horizon=0.6) and keep to an --out of their own")
    parser.add_argument("--allow-mixed", action="store_true",
                        help="append to results made on another platform (the report "
                        "notes the mix)")
    parser.add_argument("--rows", type=parse_rows, default=None,
                        help="verify: line numbers of results.csv, e.g. 2-11,40")
    parser.add_argument("--attempts", type=lambda t: set(parse_attempts(t)), default=None,
                        help="verify: attempt numbers, e.g. 0-19, of the --speeds and "
                        "--controllers given (default: every row)")
    parser.add_argument("--before", default=None,
                        help="compare: the directory of the results made before a change "
                        "(its results.csv); exits 1 when OUT is significantly worse")
    parser.add_argument("--before-count", type=int, default=None,
                        help="compare: pair OUT's planners with the rows made before at "
                        "this N, whatever N they rode (fewer trajectories against five)")
    return parser


def _whole(low: int, high: int):
    def parse(text: str) -> int:
        if not text.isdigit() or not low <= int(text) <= high:
            raise argparse.ArgumentTypeError(f"expected a whole number within {low}–{high}")
        return int(text)

    return parse


def current_platform(out: Path, record: bool = True,
                     bike: Bike | None = None) -> tuple[Platform, dict]:
    """This machine's platform, as a worker and the checkout describe it, riding `bike`
    (the reference without one); `record` adds it to OUT/platforms.json for the rows
    about to be written."""
    worker = worker_platform(out / WORKER_LOG)
    description = fingerprint(PROJECT_ROOT, worker)
    name = PlatformStore(out / PLATFORMS).add(description) if record else identity(description)
    return Platform(name, worker, description, bike or Bike.reference()), description


def run(args: argparse.Namespace, out: Path) -> None:
    results = ResultsFile(out / RESULTS)
    saved = results.load()
    check_seed(saved, args.seed, results.path)
    check_bike(saved, args.bike.label, results.path)
    keep_value_record(out, PROJECT_ROOT, args.bike.name,
                      dict(s.split("=", 1) for s in args.bike.settings))
    store = PlatformStore(out / PLATFORMS)
    known = store.load()
    platform, description = current_platform(out, bike=args.bike)
    mix = refusal({a.platform for a in saved}, description, known, results.path)
    if mix and not args.allow_mixed:
        raise ResultsError(mix)
    if results.legacy:
        results.upgrade(saved)
    configs = sorted(args.planned, key=lambda c: (display_order(c.controller), c.speed_kmh))
    done = {a.key for a in saved}
    blocks = plan_blocks(configs, args.planned, done)
    total = sum(args.planned.values())
    missing = sum(b.count for b in blocks)
    if args.cluster is not None:
        run_on_cluster(args, blocks, results, platform, saved, total, missing)
        return
    threads = args.threads if args.threads is not None else (1 if args.jobs > 1 else 0)
    counts = sorted(set(args.planned.values()))
    each = f"{counts[0]}" if len(counts) == 1 else f"{counts[0]}–{counts[-1]}"
    print(f"experiment: {len(configs)} configurations × {each} tries; {total - missing} "
          f"already in {results.path}, {missing} to run with {args.jobs} workers "
          f"({threads or 'all'} planning thread(s) each)", file=sys.stderr, flush=True)
    progress = Progress(total=total, jobs=args.jobs, done_before=total - missing)
    progress.remember(saved)
    run_blocks(blocks, results, progress, args.seed, args.jobs, threads, out / WORKER_LOG,
               platform)


def run_on_cluster(args: argparse.Namespace, blocks, results: ResultsFile, platform: Platform,
                   saved: list[Attempt], total: int, missing: int) -> None:
    """The run's blocks as tasks of a Dask cluster (tools/cpbp_experiment/cluster.py)."""
    from . import cluster

    address = args.cluster or cluster.default_address()
    if not address:
        raise ValueError("--cluster needs a scheduler's address, 'local', or Dask's "
                         "DASK_SCHEDULER_ADDRESS")
    client, local = cluster.connect(address, args.jobs)
    try:
        slots = cluster.cluster_size(client)
        # One planning thread per task unless asked: a worker thread is a core.
        threads = args.threads if args.threads is not None else 1
        print(f"experiment: {total - missing} of {total} attempts already in {results.path}, "
              f"{missing} to ride on the Dask cluster at {client.scheduler.address} "
              f"({slots} worker threads, {threads} planning thread(s) each)",
              file=sys.stderr, flush=True)
        progress = Progress(total=total, jobs=slots, done_before=total - missing)
        progress.remember(saved)
        repeated = cluster.run_blocks_on_cluster(blocks, results, progress, args.seed,
                                                 threads, platform,
                                                 {a.key for a in saved}, client)
        if repeated:
            print(f"experiment: {repeated} attempts ridden again after a lost worker were "
                  "saved once", file=sys.stderr)
    finally:
        client.close()
        if local is not None:
            local.close()


def check_rows(args: argparse.Namespace, out: Path) -> int:
    """Re-rides the chosen rows; 0 when every one repeats exactly."""
    saved = ResultsFile(out / RESULTS).load()
    if not saved:
        raise ResultsError(f"{out / RESULTS} has no rows to verify")
    chosen = choose(saved, args.rows, args.attempts, args.chosen_configs)
    if not chosen:
        raise ResultsError("no saved row matches the rows asked for")
    check_bike(chosen, args.bike.label, out / RESULTS)
    platform, description = current_platform(out, record=False, bike=args.bike)
    mix = refusal({a.platform for a in chosen}, description, PlatformStore(out / PLATFORMS)
                  .load(), out / RESULTS)
    if mix:
        details = mix.splitlines()[1:-1]
        print("\n".join(["experiment: note: the rows checked were made on another platform; "
                         "a difference may come from that:", *details]), file=sys.stderr)
    base_seed = saved[0].seed - saved[0].attempt
    jobs = args.jobs
    threads = args.threads if args.threads is not None else (1 if jobs > 1 else 0)
    print(f"experiment: re-riding {len(chosen)} rows with {jobs} workers", file=sys.stderr,
          flush=True)
    verdict = verify(chosen, base_seed, jobs, threads, out / WORKER_LOG, platform)
    print("\n".join(verdict.lines()))
    return 0 if not verdict.differing else 1


def compare_with(args: argparse.Namespace, out: Path) -> int:
    """Prints OUT's rows paired with the rows made before a change; 1 when worse."""
    if args.before is None:
        raise ValueError("compare needs --before DIR, the results made before the change")
    before_path = Path(args.before) / RESULTS
    if not before_path.exists():
        raise ResultsError(f"{before_path} does not exist")
    before = ResultsFile(before_path).load()
    after = ResultsFile(out / RESULTS).load()
    if args.before_count is not None:
        after = held_at(after, args.before_count)
    configs = {a.config for a in after}
    chosen = {c for c in configs
              if (args.named_speeds is None or c.speed_kmh in args.named_speeds)
              and (args.named_controllers is None or c.controller in args.named_controllers)}
    comparison = compare(before, after, chosen)
    if not comparison.pairings:
        raise ResultsError(f"{before_path} and {out / RESULTS} share no configuration "
                           "(with the --speeds and --controllers given)")
    held = ("" if args.before_count is None else
            f" (its planners' rows against N = {args.before_count} before, whatever their N)")
    print(f"Before: {before_path}; after: {out / RESULTS}{held}.\n")
    print(comparison.table())
    return 1 if comparison.worse else 0


def timing(args: argparse.Namespace, out: Path) -> None:
    print(f"experiment: timing the planners on {args.bike.label} on {cpu_description()} "
          "(nothing else should run)",
          file=sys.stderr, flush=True)
    rows = []
    for kind in THESIS_PLANNERS:
        for row in measure_planning(kind, args.counts, args.steps, 15, args.seed,
                                    out / WORKER_LOG, TIMING_PHYSICS, args.bike):
            rows.append(row)
    report.write_timing(rows, out / TIMING)
    (out / "machine.txt").write_text(f"{cpu_description()}, measured {date.today()}\n")
