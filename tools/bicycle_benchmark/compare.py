"""The benchmark bicycle coasted at many speeds and compared with the oracle."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .coast import Physics, coast
from .modes import Modes, crossing, fit
from .oracle import Oracle

# Where the benchmark's weave oscillates clearly (at 1 m/s its frequency is 0.8 rad/s and
# the bicycle falls within a second) up to where the capsize grows slowly.
SPEEDS = [round(1.5 + 0.25 * i, 2) for i in range(35)]


@dataclass
class Row:
    speed: float
    ridden: Modes
    expected: Modes


@dataclass
class Comparison:
    physics: Physics
    rows: list[Row]
    oracle: Oracle

    def weave_speed(self) -> float | None:
        return crossing([r.speed for r in self.rows], [r.ridden.weave.real for r in self.rows],
                        rising=False)

    def capsize_speed(self) -> float | None:
        """Searched above the weave speed only: below it the bicycle falls over in the
        weave within a second or two, and a slow exponential fitted beside it means
        little."""
        weave = self.weave_speed()
        above = [r for r in self.rows if weave is not None and r.speed > weave]
        return crossing([r.speed for r in above], [r.ridden.capsize for r in above],
                        rising=True)

    def weave_frequency_at(self, speed: float) -> float:
        """The ridden weave's frequency (rad/s) at `speed`, interpolated."""
        return float(np.interp(speed, [r.speed for r in self.rows],
                               [r.ridden.weave.imag for r in self.rows]))


def compare(physics: Physics, speeds: list[float] = SPEEDS) -> Comparison:
    parameters, coasts = coast(speeds, physics)
    oracle = Oracle(parameters)
    rows = []
    for ridden in coasts:
        speed = ridden.mean_speed
        expected = oracle.modes(speed)
        rows.append(Row(speed, fit(ridden.time, ridden.roll, ridden.steer, expected),
                        expected))
    return Comparison(physics, rows, oracle)
