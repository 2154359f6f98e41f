"""Means and paired differences with Student-t 95 % intervals."""

from __future__ import annotations

import math
from dataclasses import dataclass

from scipy import stats


@dataclass(frozen=True)
class Interval:
    mean: float
    low: float
    high: float
    n: int

    def text(self, digits: int = 1) -> str:
        if self.n == 0:
            return "–"
        if self.n == 1:
            return f"{self.mean:.{digits}f} (n = 1)"
        return f"{self.mean:.{digits}f} ({self.low:.{digits}f} to {self.high:.{digits}f})"


def t_interval(values: list[float], level: float = 0.95) -> Interval:
    """The mean of `values` with its two-sided Student-t interval (nan bounds for n < 2)."""
    n = len(values)
    if n == 0:
        return Interval(math.nan, math.nan, math.nan, 0)
    mean = sum(values) / n
    if n < 2:
        return Interval(mean, math.nan, math.nan, 1)
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))
    half = stats.t.ppf(0.5 + level / 2, n - 1) * sd / math.sqrt(n)
    return Interval(mean, mean - half, mean + half, n)


def paired_difference(first: dict[int, float], second: dict[int, float]) -> Interval:
    """Mean of first − second over the seeds both have, with its t interval: each seed is
    the same ride for both, so the difference removes what the seed alone decides."""
    shared = sorted(first.keys() & second.keys())
    return t_interval([first[s] - second[s] for s in shared])
