"""Runs the native `cpbp-bicycle` coaster and reads what it recorded."""

from __future__ import annotations

import json
import subprocess
from dataclasses import dataclass
from pathlib import Path

import numpy as np

PROJECT_ROOT = Path(__file__).resolve().parents[2]
BINARY = PROJECT_ROOT / "native" / "target" / "release" / "cpbp-bicycle"


@dataclass
class Coast:
    """One coast from upright after a roll kick, in the paper's signs."""

    speed: float
    time: np.ndarray
    roll: np.ndarray
    steer: np.ndarray
    forward_speed: np.ndarray

    @property
    def mean_speed(self) -> float:
        """The speed the motion belongs to: contacts bleed some off as it coasts."""
        return float(np.mean(self.forward_speed))


@dataclass(frozen=True)
class Physics:
    """How the coaster steps: the game's own settings unless told otherwise."""

    solver: str = "quickstep"
    dt: float = 1.0 / 120.0
    duration: float = 10.0
    # How the wheels' gyroscopic torque is computed: ODE's implicit term (the classic
    # physics model) or explicitly (the exact model).
    gyroscopic: str = "implicit"

    @property
    def label(self) -> str:
        wheels = ", explicit gyro" if self.gyroscopic == "explicit" else ""
        return f"{self.solver} at 1/{round(1.0 / self.dt)} s{wheels}"

    def arguments(self) -> list[str]:
        return ["--solver", self.solver, "--dt", repr(self.dt), "--duration",
                repr(self.duration), "--gyroscopic", self.gyroscopic]


def build() -> None:
    """Builds the coaster (a no-op when it is up to date)."""
    subprocess.run([str(PROJECT_ROOT / "tools" / "cargo"), "build", "--release", "--quiet",
                    "-p", "cpbp-core", "--bin", "cpbp-bicycle"], check=True)


def coast(speeds: list[float], physics: Physics) -> tuple[dict[str, float], list[Coast]]:
    """The bicycle's parameters (named as `bicycleparameters` names them) and one coast
    per speed."""
    done = subprocess.run([str(BINARY), "--speeds", ",".join(map(repr, speeds)),
                           *physics.arguments()], capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise RuntimeError(f"cpbp-bicycle failed: {done.stderr.strip()}")
    lines = [json.loads(line) for line in done.stdout.splitlines()]
    parameters = lines[0]["parameters"]
    coasts = [Coast(line["speed"], *(np.array(line[key]) for key in
                                     ("time", "roll", "steer", "forward_speed")))
              for line in lines[1:]]
    return parameters, coasts
