"""Which learned cost-to-go a folder's rows were ridden with (issue 59).

Rows ridden with `terminal_value` on depend on the bike's network,
models/value-<bike>.safetensors, which `make train` makes again. Both tools resume by
keeping the rows they hold, so a folder records the network's identity beside its rows
(value-model.txt) and refuses to take rows of another: rows of an earlier network are
moved aside (superseded/) and ridden again, never mixed with the new one's."""

from __future__ import annotations

import hashlib
from pathlib import Path
from typing import Mapping

RECORD = "value-model.txt"
# What the planners' bool settings take for on (the workers' schema check refuses the rest).
ON = ("true", "1")


def uses_value(settings: Mapping[str, str]) -> bool:
    """Whether `settings` (NAME -> VALUE, as given to --set) turn the cost-to-go on."""
    return settings.get("terminal_value", "").strip().lower() in ON


def value_model_file(root: Path, bike: str) -> Path:
    """The cost-to-go file the tools load for `bike` (a bike file's name)."""
    return root / "models" / f"value-{bike}.safetensors"


def identity(model: Path) -> str:
    """The first 12 hex digits of the file's SHA-256, or "none" where there is no file
    (the planners then plan the whole horizon and say so)."""
    if not model.is_file():
        return "none"
    return hashlib.sha256(model.read_bytes()).hexdigest()[:12]


def keep_value_record(out: Path, root: Path, bike: str, settings: Mapping[str, str]) -> str:
    """Checks OUT's record of the cost-to-go against `bike`'s network, writing it for a
    folder without one; returns the identity ("" when the settings leave it off). Raises
    ValueError, saying what to do, when OUT's rows were ridden with another network."""
    if not uses_value(settings):
        return ""
    now = identity(value_model_file(root, bike))
    record = out / RECORD
    if record.exists():
        before = record.read_text("utf-8").strip()
        if before != now:
            raise ValueError(
                f"{out}'s rows were ridden with the cost-to-go {before}, and "
                f"models/value-{bike}.safetensors is now {now}: move the folder aside "
                f"(superseded/value-{before}/) and ride it again")
        return now
    out.mkdir(parents=True, exist_ok=True)
    record.write_text(now + "\n", "utf-8")
    return now
