"""python -m sound_check RIDE.wav RIDE.csv [--spectrogram OUT.png --title TEXT]: fails
unless the recorded engine sounds at the firing frequency its layout gives at the logged
crank speed (so its pitch rises with speed in every gear), the game's synthesiser fires as
that layout says, it is heard while riding, and pausing the game is exactly silent. With
--spectrogram, draws the recording's spectrogram with that firing frequency over it."""

import sys

import numpy as np

from . import analysis

# At least this share of windows within TOLERANCE of the logged firing frequency.
SHARE, TOLERANCE = 0.9, 0.05


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    options = dict(zip(argv[2::2], argv[3::2]))
    if len(argv) < 2 or len(argv) % 2 or not set(options) <= {"--spectrogram", "--title"}:
        print(__doc__, file=sys.stderr)
        return 2
    rec = analysis.load(argv[0], argv[1])
    lag, windows = analysis.best_lag(rec)
    close = [w for w in windows if w.error < TOLERANCE]
    print(f"sound: {rec.rate} Hz, {len(rec.samples) / rec.rate:.1f} s; "
          f"sound {lag} frames behind the log")
    for w in windows[::3]:
        print(f"  frame {w.first_frame:4d}  {w.speed * 3.6:5.1f} km/h  gear {w.gear}  "
              f"firing {w.expected:6.1f} Hz  heard {w.heard:6.1f} Hz")
    failures = []
    riding = [r for r in rec.frames if not r["paused"]]
    off = max(abs(r["firing_frequency"] / analysis.layout_frequency(r) - 1.0) for r in riding)
    if off > 0.01:
        failures.append(f"the game's synthesiser fires {off:.0%} off its layout "
                        f"({riding[0]['cylinders']:.0f} cylinders, {riding[0]['strokes']:.0f} strokes)")
    if len(windows) < 10 or len(close) < SHARE * len(windows):
        failures.append(f"only {len(close)} of {len(windows)} windows sound within "
                        f"{TOLERANCE:.0%} of the firing frequency")
    pairs, higher = analysis.rises_with_speed(windows)
    print(f"  {higher} of {pairs} pairs of windows in one gear sound higher at the higher speed")
    if pairs < 10 or higher < SHARE * pairs:
        failures.append(f"the pitch rises with speed in only {higher} of {pairs} pairs")
    loudness = analysis.riding_rms(rec)
    print(f"  riding: RMS {loudness:.3f}")
    if loudness < 0.02:
        failures.append(f"riding is nearly silent (RMS {loudness:.4f})")
    tail = analysis.paused_tail(rec)
    print(f"  paused: {len(tail)} samples, loudest {np.abs(tail).max() if len(tail) else 0:.6f}")
    if len(tail) < rec.rate // 2 or np.any(tail != 0.0):
        failures.append("pausing the game is not exactly silent")
    if "--spectrogram" in options:
        from .spectrogram import draw
        draw(rec, lag, options["--spectrogram"], options.get("--title", ""))
    for failure in failures:
        print(f"sound check: {failure}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
