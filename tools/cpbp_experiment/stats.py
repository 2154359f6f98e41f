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


def mcnemar_exact(only_first: int, only_second: int) -> float:
    """Two-sided exact McNemar test for paired successes: the chance of a split at least
    this uneven between the discordant pairs (one succeeded, the other not) if both
    succeed equally often. Every controller meets the same bumps at attempt i, so the
    attempts pair up and this is sharper than comparing two intervals."""
    if only_first < 0 or only_second < 0:
        raise ValueError("pair counts cannot be negative")
    discordant = only_first + only_second
    if discordant == 0:
        return 1.0
    tail = sum(math.comb(discordant, k) for k in range(min(only_first, only_second) + 1))
    return min(1.0, 2.0 * tail / 2.0**discordant)
