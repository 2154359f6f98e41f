"""Confidence intervals for success rates."""

from __future__ import annotations

import math

# The 97.5 % quantile of the standard normal distribution: a two-sided 95 % interval.
Z_95 = 1.959963984540054


def wilson_interval(successes: int, trials: int, z: float = Z_95) -> tuple[float, float]:
    """The Wilson score interval for a binomial proportion (Wilson 1927).

    Unlike the textbook normal ("Wald") interval it stays inside [0, 1] and keeps close
    to its nominal coverage near 0 % and 100 %, where these controllers often are.
    """
    if trials <= 0:
        raise ValueError("an interval needs at least one trial")
    if not 0 <= successes <= trials:
        raise ValueError(f"{successes} successes out of {trials} trials")
    p = successes / trials
    z2 = z * z
    centre = (p + z2 / (2 * trials)) / (1 + z2 / trials)
    half = z / (1 + z2 / trials) * math.sqrt(p * (1 - p) / trials + z2 / (4 * trials * trials))
    # At 0 and 100 % the bound through p is exact in theory; rounding may miss it.
    return max(0.0, min(p, centre - half)), min(1.0, max(p, centre + half))


def mean(values: list[float]) -> float:
    return sum(values) / len(values) if values else math.nan
