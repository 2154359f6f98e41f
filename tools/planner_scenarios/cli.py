"""Command line: ride the scenarios (resumable) and write the paired report."""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

from cpbp_experiment.configs import PLANNERS
from cpbp_experiment.results import REFERENCE_BIKE
from cpbp_experiment.value_model import keep_value_record

from .compare import write_comparison
from .report import write_report
from .rows import FIELDS, ScenarioRows
from .sweep import settings_text, variant_folders, write_sweep
from .timing import start_timing, summary

PROJECT_ROOT = Path(__file__).resolve().parents[2]
BINARY = PROJECT_ROOT / "native" / "target" / "release" / "cpbp-scenarios"
ROWS = "scenarios.csv"
# The planners' settings a folder's rows were ridden with, where they are not the defaults.
SETTINGS = "settings.json"


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = ScenarioRows(out / ROWS)
    try:
        if args.command == "sweep":
            return sweep(out, Path(args.variants) if args.variants else out / "horizon",
                         args.base_count)
        rows.load()
        settings = _settings(args, out, rows)
        if args.command == "time":
            return time_settings(args, out, settings)
        if args.command in ("run", "all"):
            bike = Path(args.bike).stem if args.bike else REFERENCE_BIKE
            keep_value_record(out, PROJECT_ROOT, bike, settings)
            build_binary()
            ride(args, rows)
        if args.command in ("report", "all"):
            write_report(rows.load(), out, args.bike, settings)
            print(f"planner-scenarios: report written to {out / 'scenarios.md'}", file=sys.stderr)
            if args.compare:
                other = Path(args.compare)
                names = (_table_name(other), _table_name(out))
                write_comparison(ScenarioRows(other / ROWS).load(), rows.load(), names,
                                 out / "comparison.md")
                print(f"planner-scenarios: {out / 'comparison.md'} compares it with {other}",
                      file=sys.stderr)
    except (ValueError, OSError, subprocess.CalledProcessError) as error:
        print(f"planner-scenarios: {error}", file=sys.stderr)
        return 2
    return 0


def sweep(out: Path, under: Path, base_count: int | None = None) -> int:
    """OUT's table against each folder of rows under `under`, into `under`/sweep.md (each
    folder's rides against OUT's at `base_count` trajectories when it is given)."""
    folders = variant_folders(under)
    if not folders:
        print(f"planner-scenarios: no folder of rows under {under}", file=sys.stderr)
        return 2
    write_sweep(ScenarioRows(out / ROWS).load(),
                [(settings_text(f), ScenarioRows(f / ROWS).load()) for f in folders],
                _table_name(out), under / "sweep.md", base_count)
    print(f"planner-scenarios: {under / 'sweep.md'} holds {len(folders)} folder(s) against "
          f"{out}", file=sys.stderr)
    return 0


def time_settings(args: argparse.Namespace, out: Path, settings: dict[str, str]) -> int:
    """Rides OUT's seeds at the defaults and with OUT's settings, scenario by scenario in
    turn, into OUT's timing files, and prints the paired planning-time ratios."""
    if not settings or not args.scenarios or args.scenarios == "all":
        raise ValueError("time takes the folder's --set settings and the --scenarios to "
                         "time them on, by name")
    build_binary()
    defaults, these = start_timing(out)
    for scenario in args.scenarios.split(","):
        ride(args, defaults, sets=[], scenarios=scenario)
        ride(args, these, sets=args.set, scenarios=scenario)
    for line in summary(out):
        print(f"planner-scenarios: planning with {settings_text(out)} ÷ the defaults, "
              f"{line}")
    return 0


def _settings(args: argparse.Namespace, out: Path, rows: ScenarioRows) -> dict[str, str]:
    """The planners' settings of OUT's rows: a run's `--set` NAME=VALUE pairs, kept in
    OUT/settings.json so that rows ridden with one horizon never join a folder of another
    (a folder without the file holds rows ridden at the defaults)."""
    path = out / SETTINGS
    kept = json.loads(path.read_text("utf-8")) if path.exists() else {}
    if args.command == "report" and not args.set:
        return kept
    given = {}
    for assignment in args.set:
        name, equals, value = assignment.partition("=")
        if not equals:
            raise ValueError(f"--set takes NAME=VALUE, not {assignment}")
        given[name] = value
    if given != kept and (kept or rows.path.exists()):
        raise ValueError(f"{out}'s rows were ridden with {kept or 'the defaults'}, not "
                         f"{given or 'the defaults'}: give each setting its own --out")
    if given and not path.exists():
        path.write_text(json.dumps(given, indent=1, sort_keys=True) + "\n", "utf-8")
    return given


def _table_name(folder: Path) -> str:
    """What a comparison calls a table: the reference bike's is the default folder's, any
    other bike's the folder named for it (docs/scenarios/street_390)."""
    if folder.resolve() == (PROJECT_ROOT / "docs" / "scenarios").resolve():
        return "street_350 (reference)"
    return folder.name


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="tools/planner-scenarios",
        description="C-PBP, predictive sampling, MPPI and arcade on the same scripted rides "
                    "(a turn, a long hard turn at speed (carve), a slalom, lean reversals, a push, walking "
                    "pace; hard stops, slopes and hill "
                    "starts: stop10, stop25, stop40, brake-turn, slope5, slope10, slope15, "
                    "downhill15; across slopes: camber5/8/10-left/right, slope10-across45; deep "
                    "bends: bend45-h0/h22/h45, lowside-wet; full "
                    "brakes: brake60, brake90, brake-bend; the test level's "
                    "logs: logs), paired by seed. Rows are "
                    "appended to OUT/scenarios.csv as each ride ends; rerunning resumes.")
    parser.add_argument("command", nargs="?",
                        choices=("all", "run", "report", "sweep", "time"),
                        default="all", help="sweep: OUT's table against each folder of "
                        "rows under --variants, ridden with other settings (sweep.md there); "
                        "time: OUT's settings against the defaults on the same seeds, ridden "
                        "in turn (OUT/timing-*.csv), the planning times paired")
    parser.add_argument("--out", default="docs/scenarios", help="directory of scenarios.csv "
                        "and the report (default docs/scenarios)")
    parser.add_argument("--controllers", default=",".join(PLANNERS),
                        help="planning controllers of the registry (default: all of them), or "
                             "arcade and learned (ridden once per seed, as N = 0), comma-separated")
    parser.add_argument("--counts", default="5,10", help="trajectory counts N")
    parser.add_argument("--seeds", default="0-9", help="FIRST-LAST: ride i for each")
    parser.add_argument("--scenarios", default=None, help="comma-separated, or all (every "
                        "scenario, as a bike's table is ridden again; default: cpbp-scenarios's "
                        "manoeuvres, turn to walk)")
    parser.add_argument("--physics", default="exact", choices=("classic", "exact"))
    parser.add_argument("--bike", default=None, help="a bike file to ride (default: the "
                        "reference bike); keep its rows in an --out of their own")
    parser.add_argument("--model", default=None, help="the network learned and guided "
                        "ride (default: the bike's own, models/policy-<bike>.safetensors): "
                        "another bike's, to see how far it carries")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="plan with a planner's setting other than its default "
                             "(horizon=0.6), repeatable; kept in OUT/settings.json, and a "
                             "folder holds rows of one set of settings only")
    parser.add_argument("--compare", default=None, help="report: another table's directory "
                        "(another bike's), compared side by side in OUT/comparison.md")
    parser.add_argument("--variants", default=None, help="sweep: the folder whose "
                        "subfolders hold the rows ridden with other settings (default "
                        "OUT/horizon)")
    parser.add_argument("--base-count", type=int, default=None, help="sweep: hold every "
                        "folder's rides against OUT's at this N, whatever N they rode "
                        "(fewer trajectories against the defaults' five)")
    return parser


def build_binary() -> None:
    """Builds cpbp-scenarios as the tree has it, once a command."""
    subprocess.run([str(PROJECT_ROOT / "tools" / "cargo"), "build", "--quiet", "--release",
                    "-p", "cpbp-core", "--bin", "cpbp-scenarios"], check=True)


def ride(args: argparse.Namespace, rows: ScenarioRows, sets: list[str] | None = None,
         scenarios: str | None = None) -> None:
    """Streams cpbp-scenarios's rows into the file, skipping saved ones (with `sets` and
    `scenarios` instead of the command line's, when given)."""
    command = [str(BINARY), "--controllers", args.controllers, "--counts", args.counts,
               "--seeds", args.seeds, "--physics", args.physics]
    if scenarios or args.scenarios:
        command += ["--scenarios", scenarios or args.scenarios]
    if args.bike:
        command += ["--bike", args.bike]
    if args.model:
        command += ["--model", args.model]
    for assignment in args.set if sets is None else sets:
        command += ["--set", assignment]
    if rows.path.exists():
        command += ["--skip", str(rows.path)]
    with subprocess.Popen(command, stdout=subprocess.PIPE, text=True) as process:
        assert process.stdout is not None
        header = process.stdout.readline().strip().split(",")
        if header != list(FIELDS):
            process.kill()
            raise ValueError(f"cpbp-scenarios printed columns {header}, expected {FIELDS}")
        for line in process.stdout:
            row = rows.append(line)
            print(f"planner-scenarios: {row['scenario']} {row['controller']}-"
                  f"{row['trajectories']} seed {row['seed']}: "
                  f"{'fell' if row['fell'] else 'up'}, {row['metric']:.2f}",
                  file=sys.stderr, flush=True)
    if process.returncode != 0:
        raise ValueError(f"cpbp-scenarios stopped with status {process.returncode}")
