"""The results file: one CSV row per finished attempt, appended and synced as each
attempt ends, so a kill loses at most the attempts in progress, and read back on a rerun
so the run resumes where it stopped."""

from __future__ import annotations

import csv
import io
import os
from dataclasses import dataclass
from pathlib import Path

from .configs import PLANNERS, Config, Controller
from .fingerprint import UNRECORDED

# The columns of a results file made before the platform was recorded with every row.
LEGACY_FIELDS = (
    "speed_kmh",
    "controller",
    "trajectories",
    "attempt",
    "seed",
    "outcome",
    "time_s",
    "distance_m",
    "steps",
    "planning_ms",
    "wall_ms",
)
# `planner_seed` is the planner's seed for the attempt, `late_plans` the steps driven
# without that step's plan (0 for a row that repeats exactly), `platform` the identity of
# the fingerprint in platforms.json it was made on.
PLATFORM_FIELDS = LEGACY_FIELDS + ("planner_seed", "late_plans", "platform")
# `physics` is the physics model the row was ridden in (earlier files: all classic).
PHYSICS_FIELDS = PLATFORM_FIELDS + ("physics",)
# `bike` is the name of the bike file ridden, with "+" and another bike's name when the
# learned controllers rode that bike's network, and "@" and the planner settings asked
# when they were not the defaults (earlier files: all the reference bike's).
FIELDS = PHYSICS_FIELDS + ("bike",)
OUTDATED_LAYOUTS = (LEGACY_FIELDS, PLATFORM_FIELDS, PHYSICS_FIELDS)
# The thesis's bike, which a run rides unless given another (scenes/bike/bikes/).
REFERENCE_BIKE = "street_350"
OUTCOMES = ("goal", "fell", "timeout")


class ResultsError(Exception):
    """The results file cannot be used as it is (the message says why and what to do)."""


@dataclass(frozen=True)
class Attempt:
    config: Config
    attempt: int
    seed: int
    outcome: str
    time_s: float
    distance_m: float
    steps: int
    planning_ms: float
    wall_ms: float
    # Not recorded (None, UNRECORDED) in rows of legacy files.
    planner_seed: int | None = None
    late_plans: int | None = None
    platform: str = UNRECORDED
    bike: str = REFERENCE_BIKE

    @property
    def key(self) -> tuple[Config, int]:
        return (self.config, self.attempt)

    def row(self) -> list[str]:
        c = self.config
        return [
            str(c.speed_kmh),
            c.controller.kind,
            str(c.controller.trajectories),
            str(self.attempt),
            str(self.seed),
            self.outcome,
            f"{self.time_s:.4f}",
            f"{self.distance_m:.3f}",
            str(self.steps),
            f"{self.planning_ms:.3f}",
            f"{self.wall_ms:.1f}",
            "" if self.planner_seed is None else str(self.planner_seed),
            "" if self.late_plans is None else str(self.late_plans),
            self.platform,
            c.controller.physics,
            self.bike,
        ]

    def outcome_fields(self) -> list[str]:
        """What a re-ride must reproduce exactly, as the file spells it."""
        return self.row()[5:9]

    @staticmethod
    def from_row(row: dict[str, str]) -> "Attempt":
        kind = row["controller"]
        label = f"{kind}-{row['trajectories']}" if kind in PLANNERS else kind
        label += f":{row['physics']}" if row.get("physics") else ""
        outcome = row["outcome"]
        if outcome not in OUTCOMES:
            raise ValueError(f"outcome '{outcome}' is not one of {', '.join(OUTCOMES)}")
        return Attempt(
            config=Config(int(row["speed_kmh"]), Controller.parse(label)),
            attempt=int(row["attempt"]),
            seed=int(row["seed"]),
            outcome=outcome,
            time_s=float(row["time_s"]),
            distance_m=float(row["distance_m"]),
            steps=int(row["steps"]),
            planning_ms=float(row["planning_ms"]),
            wall_ms=float(row["wall_ms"]),
            planner_seed=int(row["planner_seed"]) if row.get("planner_seed") else None,
            late_plans=int(row["late_plans"]) if row.get("late_plans") else None,
            platform=row.get("platform") or UNRECORDED,
            bike=row.get("bike") or REFERENCE_BIKE,
        )


class ResultsFile:
    def __init__(self, path: Path):
        self.path = path
        # Read in an earlier layout of the columns: rows are added only after `upgrade`.
        self.legacy = False

    def load(self) -> list[Attempt]:
        """Every saved attempt. A last line cut short by a kill is dropped from the file
        (that attempt runs again); anything else unreadable is an error, never skipped."""
        if not self.path.exists():
            return []
        text = self.path.read_text(encoding="utf-8")
        if text and not text.endswith("\n"):
            kept = text[: text.rfind("\n") + 1]
            with open(self.path, "r+", encoding="utf-8") as f:
                f.truncate(len(kept.encode("utf-8")))
            text = kept
        if not text:
            return []
        reader = csv.DictReader(io.StringIO(text))
        self.legacy = tuple(reader.fieldnames or ()) in OUTDATED_LAYOUTS
        if tuple(reader.fieldnames or ()) != FIELDS and not self.legacy:
            raise ResultsError(
                f"{self.path} is not an experiment results file (its columns are "
                f"{reader.fieldnames}); choose another --out"
            )
        attempts = []
        seen = set()
        for line, row in enumerate(reader, start=2):
            try:
                attempt = Attempt.from_row(row)
            except (KeyError, TypeError, ValueError) as error:
                raise ResultsError(f"{self.path}:{line}: unreadable row ({error})") from error
            if attempt.key in seen:
                raise ResultsError(f"{self.path}:{line}: {attempt.config.label} attempt "
                                   f"{attempt.attempt} is in the file twice")
            seen.add(attempt.key)
            attempts.append(attempt)
        return attempts

    def upgrade(self, attempts: list[Attempt]) -> None:
        """Rewrites a file of an earlier layout in today's columns (a row's platform
        unrecorded if it had none, its physics classic, its bike the reference), via a
        temporary file renamed over it, so a kill leaves the old file or the new one."""
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        writer.writerow(FIELDS)
        writer.writerows(a.row() for a in attempts)
        temporary = self.path.with_suffix(".csv.tmp")
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(buffer.getvalue())
            f.flush()
            os.fsync(f.fileno())
        os.replace(temporary, self.path)
        self.legacy = False

    def append(self, attempt: Attempt) -> None:
        """Adds one attempt and syncs it to disk before returning."""
        if self.legacy:
            raise ResultsError(f"{self.path} has the legacy columns: upgrade it first")
        self.path.parent.mkdir(parents=True, exist_ok=True)
        new = not self.path.exists() or self.path.stat().st_size == 0
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        if new:
            writer.writerow(FIELDS)
        writer.writerow(attempt.row())
        with open(self.path, "a", encoding="utf-8") as f:
            f.write(buffer.getvalue())
            f.flush()
            os.fsync(f.fileno())


def check_seed(attempts: list[Attempt], base_seed: int, path: Path) -> None:
    """Attempt i of a run used seed base + i; mixing runs of two seeds would count
    different bumps as the same attempt."""
    for attempt in attempts:
        if attempt.seed - attempt.attempt != base_seed:
            raise ResultsError(
                f"{path} was made with --seed {attempt.seed - attempt.attempt}, not "
                f"{base_seed}: rerun with that seed to resume, or choose another --out"
            )


def check_bike(attempts: list[Attempt], bike: str, path: Path) -> None:
    """One bike per results file: a table pairs attempts by configuration and seed, and
    two bikes' attempts are not the same attempt."""
    others = sorted({a.bike for a in attempts} - {bike})
    if others:
        raise ResultsError(
            f"{path} has rows ridden on {', '.join(others)}, not {bike}: keep each bike's "
            "rows in an --out of their own (rerun with that bike to resume)"
        )
