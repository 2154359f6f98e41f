"""The School's lessons and the levels' challenges as the docs quote them: each one's
title, what its score measures and its medals' thresholds, read from the Challenge files
the catalogue lists (scenes/challenges/catalogue.tres), written as the game writes them
(Challenge.format)."""

from __future__ import annotations

import csv
import json
import re
from pathlib import Path

from .markers import FigureError

CATALOGUE = Path("scenes/challenges/catalogue.tres")
MEDALS = ("gold", "silver", "bronze")


def _paths(root: Path, kind: str) -> list[Path]:
    text = (root / CATALOGUE).read_text(encoding="utf-8")
    match = re.search(rf"^{kind} = Array\[String\]\(\[(.*)\]\)$", text, re.M)
    if not match:
        raise FigureError(f"{CATALOGUE} lists no {kind}")
    return [root / p.removeprefix("res://") for p in re.findall(r'"([^"]+)"', match.group(1))]


def _field(text: str, name: str, path: Path) -> str:
    match = re.search(rf"^{name} = (.*)$", text, re.M)
    if not match:
        raise FigureError(f"{path} sets no {name}")
    return match.group(1)


def challenge(path: Path) -> dict:
    """One challenge file's title, score, unit, direction and thresholds."""
    text = path.read_text(encoding="utf-8")
    fields = {name: json.loads(_field(text, name, path)) for name in ("title", "score_name")}
    unit = re.search(r'^unit = (".*")$', text, re.M)
    fields["unit"] = json.loads(unit.group(1)) if unit else "m"
    lower = re.search(r"^lower_is_better = (\w+)$", text, re.M)
    fields["lower_is_better"] = lower is None or lower.group(1) == "true"
    for medal in MEDALS:
        fields[medal] = float(_field(text, medal, path))
    fields["key"] = path.stem
    return fields


def format_score(value: float, unit: str) -> str:
    """As Challenge.format writes a score."""
    if unit == "s":
        return f"{value:.2f} s"
    if unit == "°":
        return f"{value:.1f}°"
    if unit == "km/h":
        return f"{round(value)} km/h"
    return f"{value:.2f} {unit}"


def table(root: Path, kind: str) -> str:
    """| lesson | score | gold | silver | bronze |, one row a lesson (or challenge)."""
    lines = [f"| {kind[:-1]} | score | gold | silver | bronze |", "|---|---|---|---|---|"]
    for number, path in enumerate(_paths(root, kind), start=1):
        c = challenge(path)
        sign = "≤" if c["lower_is_better"] else "≥"
        cells = [f"{sign} {format_score(c[m], c['unit'])}" for m in MEDALS]
        name = f"{number}. {c['title']}" if kind == "lessons" else c["title"]
        lines.append(f"| {name} (`{c['key']}`) | {c['score_name']} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def threshold(root: Path, key: str, medal: str) -> str:
    """The score challenge `key` needs for `medal`, as the game writes it."""
    for kind in ("lessons", "challenges"):
        for path in _paths(root, kind):
            if path.stem == key:
                c = challenge(path)
                return format_score(c[medal], c["unit"])
    raise FigureError(f"the catalogue lists no challenge {key}")


BOT_RIDES = Path("docs/challenges/bot-rides.csv")


def bot_table(root: Path) -> str:
    """| challenge | one column a bike |: the medal the bot's gold ride of each earned on
    each bike (tools/challenge-survey.sh's rows), with its score, or why it missed."""
    with (root / BOT_RIDES).open(encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise FigureError(f"{BOT_RIDES} has no rows")
    bikes = list(dict.fromkeys(r["bike"] for r in rows))
    units = {}
    for kind in ("lessons", "challenges"):
        for path in _paths(root, kind):
            c = challenge(path)
            units[c["key"]] = (c["title"], c["unit"])
    lines = ["| lesson or challenge | " + " | ".join(b.replace("_", " ") for b in bikes) + " |",
             "|---|" + "---|" * len(bikes)]
    for key in dict.fromkeys(r["challenge"] for r in rows):
        if key not in units:
            raise FigureError(f"{BOT_RIDES} rides {key}, which the catalogue does not list")
        title, unit = units[key]
        cells = []
        for bike in bikes:
            row = next((r for r in rows if r["challenge"] == key and r["bike"] == bike), None)
            if row is None:
                cells.append("–")
            elif row["passed"] == "true":
                cells.append(f"{row['medal']} ({format_score(float(row['score']), unit)})")
            else:
                cells.append(f"missed: {row['why']}")
        lines.append(f"| {title} | " + " | ".join(cells) + " |")
    return "\n".join(lines)
