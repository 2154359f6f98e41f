"""Figures the docs quote from the project's own files: the Rust version the workspace
needs (native/Cargo.toml) and the preflight's limits (tools/preflight.sh)."""

from __future__ import annotations

import re
from pathlib import Path

from . import challenge_figures
from .markers import Figure, FigureError


def _assignment(path: Path, pattern: str, what: str) -> str:
    match = re.search(pattern, path.read_text(encoding="utf-8"), re.M)
    if not match:
        raise FigureError(f"{path} sets no {what}")
    return match.group(1)


def figures(root: Path) -> dict[str, Figure]:
    return {
        # "1.94": the workspace's rust-version.
        "rust-version": Figure(lambda: _assignment(
            root / "native/Cargo.toml", r'^rust-version *= *"([\d.]+)"', "rust-version"),
            r"[\d.]+"),
        # A constant of the preflight, as `PYTHON_MIN` or `DISK_MIN_GB`.
        "preflight": Figure(lambda name: _assignment(
            root / "tools/preflight.sh", rf"^{re.escape(name)}=([\w.]+)$", name), r"[\w.]+"),
        # "0.25 m": the score a lesson or challenge needs for a medal, as `medal ride_off gold`.
        "medal": Figure(lambda key, medal: challenge_figures.threshold(root, key, medal),
                        r"[\d.]+ ?(?:s|m|°|km/h)"),
    }
