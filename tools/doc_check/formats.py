"""How the docs write numbers, one way everywhere."""

from __future__ import annotations

SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def count(n: int) -> str:
    """A count with a space between thousands, as the docs write them: 10 000."""
    return f"{n:,}".replace(",", " ")


def format_p(p: float) -> str:
    """A p-value to two significant figures: 0.12, 0.0049, 1; below 0.001 as 9.5·10⁻⁷."""
    if p >= 0.001:
        return f"{p:.2g}"
    mantissa, exponent = f"{p:.1e}".split("e")
    return f"{mantissa}·10{str(int(exponent)).translate(SUPERSCRIPT)}"


def percent_range(low: float, high: float) -> str:
    """An interval of rates in percent, a bound of exactly 100 % written as 100: 98.1–100 %."""
    def bound(x: float) -> str:
        return "100" if x >= 1.0 else "0" if x <= 0.0 else f"{100 * x:.1f}"
    return f"{bound(low)}–{bound(high)} %"
