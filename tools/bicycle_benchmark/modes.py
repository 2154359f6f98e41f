"""The modes of a recorded coast: a least-squares fit of the linear model's form."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares


@dataclass(frozen=True)
class Modes:
    """Eigenvalues (1/s) of a coasting bicycle: the weave's oscillating pair (its
    positive-frequency member), the capsize and castor modes, and the fit's RMS error
    relative to each signal's largest value (0 for the oracle)."""

    weave: complex
    capsize: float
    castor: float
    rms: float

    @property
    def self_stable(self) -> bool:
        return self.weave.real < 0 and self.capsize < 0


def _basis(time: np.ndarray, rates: np.ndarray) -> np.ndarray:
    decay, frequency, capsize, castor = rates
    weave = np.exp(decay * time)
    return np.column_stack([weave * np.cos(frequency * time), weave * np.sin(frequency * time),
                            np.exp(capsize * time), np.exp(castor * time), np.ones_like(time)])


def _residuals(rates: np.ndarray, time: np.ndarray, signals: list[np.ndarray]) -> np.ndarray:
    basis = _basis(time, rates)
    out = []
    for signal in signals:
        amplitudes, *_ = np.linalg.lstsq(basis, signal, rcond=None)
        out.append((basis @ amplitudes - signal) / np.abs(signal).max())
    return np.concatenate(out)


def fit(time: np.ndarray, roll: np.ndarray, steer: np.ndarray, start: Modes) -> Modes:
    """Fits roll and steer together as the linear model moves after a kick: a weave
    oscillation, two real exponentials and an offset, sharing the rates. The amplitudes
    are solved exactly for each trial of rates (variable projection), so only four
    numbers are searched, from `start` (in practice the oracle's modes at that speed:
    the fit then tells how far the recorded motion is from them)."""
    guess = [start.weave.real, start.weave.imag, start.capsize, start.castor]
    found = least_squares(_residuals, guess, args=(time, [roll, steer]))
    decay, frequency, first, second = found.x
    capsize, castor = max(first, second), min(first, second)
    return Modes(complex(decay, abs(frequency)), capsize, castor,
                 float(np.sqrt(np.mean(found.fun ** 2))))


def crossing(speeds: list[float], rates: list[float], rising: bool) -> float | None:
    """The first speed where `rates` change sign (rising: − to +), linearly interpolated."""
    for (v0, r0), (v1, r1) in zip(zip(speeds, rates), zip(speeds[1:], rates[1:])):
        if (r0 < 0 <= r1) if rising else (r0 >= 0 > r1):
            return v0 + (v1 - v0) * r0 / (r0 - r1)
    return None
