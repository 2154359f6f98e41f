"""The experiment's statistics, from statsmodels: Wilson intervals for success rates, the
exact McNemar test for paired attempts and Holm's correction across the paired tests.
The functions keep the project's argument checks and names; statsmodels does the maths."""

from __future__ import annotations

import math

from statsmodels.stats.contingency_tables import mcnemar
from statsmodels.stats.multitest import multipletests
from statsmodels.stats.proportion import proportion_confint

# The family-wise error rate the paired comparisons are held to.
ALPHA = 0.05


def wilson_interval(successes: int, trials: int, alpha: float = ALPHA) -> tuple[float, float]:
    """The Wilson score interval for a binomial proportion (Wilson 1927).

    Unlike the textbook normal ("Wald") interval it stays inside [0, 1] and keeps close
    to its nominal coverage near 0 % and 100 %, where these controllers often are.
    """
    if trials <= 0:
        raise ValueError("an interval needs at least one trial")
    if not 0 <= successes <= trials:
        raise ValueError(f"{successes} successes out of {trials} trials")
    low, high = proportion_confint(successes, trials, alpha=alpha, method="wilson")
    # At 0 and 100 % the bound through p is exact in theory; rounding may miss it.
    p = successes / trials
    return max(0.0, min(p, float(low))), min(1.0, max(p, float(high)))


def mean(values: list[float]) -> float:
    return sum(values) / len(values) if values else math.nan


def mcnemar_exact(only_first: int, only_second: int) -> float:
    """Two-sided exact McNemar test for paired successes: the chance of a split at least
    this uneven between the discordant pairs (one succeeded, the other not) if both
    succeed equally often. Every controller meets the same bumps at attempt i, so the
    attempts pair up and this is sharper than comparing two intervals."""
    if only_first < 0 or only_second < 0:
        raise ValueError("pair counts cannot be negative")
    if only_first + only_second == 0:
        return 1.0
    # Only the discordant cells enter the exact test; the concordant ones are set to 0.
    table = [[0, only_first], [only_second, 0]]
    return min(1.0, float(mcnemar(table, exact=True).pvalue))


def holm(p_values: list[float], alpha: float = ALPHA) -> tuple[list[bool], list[float]]:
    """Holm's step-down correction (Holm 1979) of a family of tests: which reject at a
    family-wise error rate of `alpha`, and the adjusted p-values."""
    if not p_values:
        return [], []
    if any(not 0.0 <= p <= 1.0 for p in p_values):
        raise ValueError(f"p-values must lie within 0 and 1: {p_values}")
    reject, adjusted, _, _ = multipletests(p_values, alpha=alpha, method="holm")
    return [bool(r) for r in reject], [float(p) for p in adjusted]
