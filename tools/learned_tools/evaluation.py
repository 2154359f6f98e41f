"""Keeps the committed evaluation of the network's controllers in step with the model.

The experiment and the scenario tool resume by skipping rows they already hold, so rows
of `learned` and `guided` ridden with an earlier model would stand in for the new one.
`make train` runs this before it rides them: when models/policy-street_350.safetensors (the reference bike's) is not the
model named in docs/learned/evaluated-model.txt, their rows move to a superseded folder
beside each table (as every other change of the riders does, docs/experiment/superseded)
and the new model is recorded, so a resumed evaluation keeps what it rode with it."""

from __future__ import annotations

import argparse
import csv
import hashlib
import os
import shutil
import sys
from pathlib import Path

NETWORK_CONTROLLERS = {"learned", "guided"}
# (table, the file beside it that names its rows' platforms, if any)
TABLES = ((Path("docs/experiment/results.csv"), Path("docs/experiment/platforms.json")),
          (Path("docs/scenarios/scenarios.csv"), None))
RECORD = Path("docs/learned/evaluated-model.txt")


def model_identity(model: Path) -> str:
    """The first 12 hex digits of the model file's SHA-256."""
    return hashlib.sha256(model.read_bytes()).hexdigest()[:12]


def move_rows(table: Path, platforms: Path | None, folder: Path) -> int:
    """Moves the network's rows of `table` into `folder`/<same name>; returns how many."""
    if not table.exists():
        return 0
    with table.open(newline="") as f:
        reader = csv.DictReader(f)
        header = reader.fieldnames or []
        rows = list(reader)
    stale = [r for r in rows if r["controller"] in NETWORK_CONTROLLERS]
    if not stale:
        return 0
    folder.mkdir(parents=True, exist_ok=True)
    moved = folder / table.name
    new_file = not moved.exists()
    with moved.open("a", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=header, lineterminator="\n")
        if new_file:
            writer.writeheader()
        writer.writerows(stale)
    if platforms is not None and platforms.exists():
        shutil.copyfile(platforms, folder / platforms.name)
    # The kept rows replace the table in one rename: a kill leaves one whole table.
    partial = table.with_suffix(".csv.partial")
    with partial.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=header, lineterminator="\n")
        writer.writeheader()
        writer.writerows(r for r in rows if r["controller"] not in NETWORK_CONTROLLERS)
    os.replace(partial, table)
    return len(stale)


def supersede(root: Path, model: Path) -> str:
    """Supersedes rows ridden with another model; returns what it did, in a sentence."""
    now = model_identity(model)
    record = root / RECORD
    before = record.read_text().strip() if record.exists() else "unrecorded"
    if before == now:
        return f"the evaluation's rows of learned and guided were ridden with model {now}"
    counts = [move_rows(root / table, platforms and root / platforms,
                        root / table.parent / "superseded" / f"model-{before}")
              for table, platforms in TABLES]
    record.parent.mkdir(parents=True, exist_ok=True)
    record.write_text(now + "\n")
    return (f"model {now} replaces {before}: {counts[0]} experiment rows and {counts[1]} "
            f"scenario rows of learned and guided moved to superseded/model-{before}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", type=Path, default=Path("models/policy-street_350.safetensors"))
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parents[2])
    args = parser.parse_args()
    print(supersede(args.root, args.model if args.model.is_absolute()
                    else args.root / args.model))
    return 0


if __name__ == "__main__":
    sys.exit(main())
