"""The scenario rows on disk: appended a line at a time, read back typed; a line cut
short by a kill is dropped and the file repaired, anything else malformed is an error."""

from __future__ import annotations

import csv
import io
import os
from pathlib import Path

FIELDS = ("scenario", "controller", "trajectories", "seed", "physics", "fell", "metric",
          "planning_ms", "extra")
# Rows written before a ride could report more than its metric have no `extra`.
EARLIER_FIELDS = FIELDS[:-1]


def parse(line: str) -> dict:
    values = next(csv.reader(io.StringIO(line)))
    if len(values) == len(EARLIER_FIELDS):
        values.append("")
    if len(values) != len(FIELDS):
        raise ValueError(f"a scenario row has {len(FIELDS)} fields, not {len(values)}: {line!r}")
    row = dict(zip(FIELDS, values))
    if row["fell"] not in ("true", "false"):
        raise ValueError(f"fell is true or false, not {row['fell']!r}")
    return {**row, "trajectories": int(row["trajectories"]), "seed": int(row["seed"]),
            "fell": row["fell"] == "true", "metric": float(row["metric"]),
            "planning_ms": float(row["planning_ms"]), "extra": _measures(row["extra"])}


def rider_name(row: dict) -> str:
    """The planner and N a row was ridden by, as the tools and docs name it: `combined-5`."""
    return f"{row['controller']}-{row['trajectories']}"


def _measures(text: str) -> dict[str, float]:
    """`name=value;…` as numbers by name ({} for none)."""
    measures = {}
    for item in filter(None, text.split(";")):
        name, _, value = item.partition("=")
        try:
            measures[name] = float(value)
        except ValueError:
            raise ValueError(f"a measure is name=number, not {item!r}") from None
    return measures


class ScenarioRows:
    def __init__(self, path: Path):
        self.path = path

    def load(self) -> list[dict]:
        if not self.path.exists():
            return []
        text = self.path.read_text()
        lines = text.splitlines()
        if not lines:
            return []
        if lines[0].split(",") not in (list(FIELDS), list(EARLIER_FIELDS)):
            raise ValueError(f"{self.path} is not a scenarios file (columns {lines[0]!r})")
        if not text.endswith("\n"):
            # A kill mid-write leaves a partial last line: drop it, keep the rest.
            lines = lines[:-1]
            self.path.write_text("\n".join(lines) + "\n")
        return [parse(line) for line in lines[1:]]

    def append(self, line: str) -> dict:
        """Saves one row the binary printed (checked first) and returns it parsed."""
        row = parse(line.strip())
        new = not self.path.exists()
        with self.path.open("a") as file:
            if new:
                file.write(",".join(FIELDS) + "\n")
            file.write(line.strip() + "\n")
            file.flush()
            os.fsync(file.fileno())
        return row
