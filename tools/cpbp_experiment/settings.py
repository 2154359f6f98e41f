"""The settings schema (cpbp_core::settings) as the native tests write it into
settings.json and hold it equal: every setting's name, label, unit, default, range, owner
and whether players see it (and start from another default). The tools take ranges and defaults from here, never from a
copy of their own."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

SCHEMA_FILE = Path(__file__).with_name("settings.json")
_KIND_NAMES = {"bool": "a switch", "int": "a whole number", "float": "a number", "text": "a name"}


@dataclass(frozen=True)
class Setting:
    name: str
    label: str
    description: str
    unit: str
    type: str
    default: bool | int | float | str
    owner: str
    player: bool
    menu: str
    range: tuple[float, float, float] | None = None
    offered: tuple[float, ...] = ()
    choices: tuple[str, ...] = ()
    # What a player's game starts with where it differs from `default` (the tools' own).
    player_default: bool | int | float | str | None = None

    def check(self, value: bool | int | float | str) -> None:
        """Raises ValueError unless `value` is one this setting may hold."""
        kinds = {"bool": (bool,), "int": (int,), "float": (int, float), "text": (str,)}
        if isinstance(value, bool) != (self.type == "bool") or not isinstance(
            value, kinds[self.type]
        ):
            raise ValueError(f"{self.name} takes {_KIND_NAMES[self.type]}, not {value!r}")
        if self.range and not self.range[0] <= value <= self.range[1]:
            raise ValueError(
                f"{self.name} must be within {self.range[0]:g}–{self.range[1]:g}"
                f" {self.unit}".rstrip() + f", not {value}"
            )
        if self.choices and value not in self.choices:
            raise ValueError(f"{self.name} is one of {', '.join(self.choices)}, not {value!r}")


def load(path: Path = SCHEMA_FILE) -> dict[str, Setting]:
    """Every setting in the schema file at `path`, by name."""
    entries = json.loads(path.read_text("utf-8"))["settings"]
    settings = {}
    for entry in entries:
        entry = dict(entry)
        if "range" in entry:
            entry["range"] = tuple(entry["range"])
        entry["offered"] = tuple(entry.get("offered", ()))
        entry["choices"] = tuple(entry.get("choices", ()))
        settings[entry["name"]] = Setting(**entry)
    return settings


SETTINGS = load()
AUTO_TRAJECTORIES = tuple(
    int(n) for n in json.loads(SCHEMA_FILE.read_text("utf-8"))["auto_trajectories"]
)
