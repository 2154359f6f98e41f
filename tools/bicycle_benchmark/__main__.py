"""`tools/bicycle-benchmark`: coasts the benchmark bicycle under several physics settings
and prints how each compares with the paper's linear model (docs/physics.md)."""

from __future__ import annotations

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the headless backend)

from .coast import Physics, build  # noqa: E402
from .compare import Comparison, compare  # noqa: E402

# The game's step first (classic physics model, then exact), then what converges to the
# benchmark, then candidates for cheaper rollouts.
EXPLICIT = "explicit"
SETTINGS = [Physics(), Physics("direct", gyroscopic=EXPLICIT), Physics(dt=1 / 1000),
            Physics(dt=1 / 240), Physics(gyroscopic=EXPLICIT), Physics("direct"),
            Physics("direct", dt=1 / 60, gyroscopic=EXPLICIT),
            Physics("direct", dt=1 / 30, gyroscopic=EXPLICIT), Physics("direct", dt=1 / 30)]


def percent(found: float | None, expected: float) -> str:
    if found is None:
        return "none"
    return f"{found:.2f} ({100 * (found / expected - 1):+.0f} %)"


def summary_table(comparisons: list[Comparison]) -> str:
    oracle = comparisons[0].oracle
    weave, capsize = oracle.weave_speed(), oracle.capsize_speed()
    frequency = oracle.modes(weave).weave.imag
    lines = ["| physics | weave speed (m/s) | capsize speed (m/s) | weave frequency at "
             f"{weave:.2f} m/s (rad/s) | worst fit RMS |",
             "|---|---|---|---|---|",
             f"| benchmark (linear model) | {weave:.2f} | {capsize:.2f} | {frequency:.2f} | – |"]
    for c in comparisons:
        stable = [r for r in c.rows if r.speed > 3.0]
        lines.append(f"| {c.physics.label} | {percent(c.weave_speed(), weave)} | "
                     f"{percent(c.capsize_speed(), capsize)} | "
                     f"{percent(c.weave_frequency_at(weave), frequency)} | "
                     f"{max(r.ridden.rms for r in stable):.0e} |")
    return "\n".join(lines)


def chart(comparisons: list[Comparison], path: Path) -> None:
    figure, (rates, frequencies) = plt.subplots(1, 2, figsize=(11, 4.2))
    first = comparisons[0]
    speeds = [r.speed for r in first.rows]
    rates.plot(speeds, [r.expected.weave.real for r in first.rows], "k-", lw=2.5,
               label="benchmark weave")
    rates.plot(speeds, [r.expected.capsize for r in first.rows], "k--", lw=2.5,
               label="benchmark capsize")
    frequencies.plot(speeds, [r.expected.weave.imag for r in first.rows], "k-", lw=2.5,
                     label="benchmark")
    for c in comparisons:
        v = [r.speed for r in c.rows]
        line, = rates.plot(v, [r.ridden.weave.real for r in c.rows], "-", lw=1.2,
                           label=f"{c.physics.label} weave")
        # Below its weave speed the bicycle falls within a second or two and the capsize
        # rate fitted beside the weave means little.
        weave = c.weave_speed() or 0.0
        above = [r for r in c.rows if r.speed > weave]
        rates.plot([r.speed for r in above], [r.ridden.capsize for r in above], "--", lw=1.2,
                   color=line.get_color())
        frequencies.plot(v, [r.ridden.weave.imag for r in c.rows], "-", lw=1.2,
                         color=line.get_color(), label=c.physics.label)
    rates.axhline(0, color="grey", lw=0.6)
    rates.set(xlabel="speed (m/s)", ylabel="real part of eigenvalue (1/s)", ylim=(-4, 3),
              title="growth (> 0) or decay of weave (—) and capsize (- -)")
    frequencies.set(xlabel="speed (m/s)", ylabel="weave frequency (rad/s)",
                    title="weave frequency")
    rates.legend(fontsize=6.5, loc="lower left")
    frequencies.legend(fontsize=6.5)
    figure.tight_layout()
    figure.savefig(path, dpi=110)


def main() -> None:
    parser = argparse.ArgumentParser(prog="tools/bicycle-benchmark", description=__doc__)
    parser.add_argument("--chart", type=Path, help="write the eigenvalue chart here (PNG)")
    args = parser.parse_args()
    build()
    comparisons = [compare(physics) for physics in SETTINGS]
    print(summary_table(comparisons))
    if args.chart:
        chart(comparisons, args.chart)
        print(f"\nchart: {args.chart}")


if __name__ == "__main__":
    main()
