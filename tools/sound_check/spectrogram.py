"""A recording's spectrogram with the firing frequency its engine's layout gives at the
logged crank speed drawn over it: a picture of how a bike sounds, for docs/sound/."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import analysis  # noqa: E402

# The band drawn (Hz): the engines' firing frequencies and a few of their harmonics.
TOP = 1500.0


def draw(rec: analysis.Recording, lag: int, path: str, title: str) -> None:
    riding = [i for i, r in enumerate(rec.frames) if not r["paused"]]
    sound = rec.frame_samples(0, riding[-1] + 1)
    figure, axes = plt.subplots(figsize=(9, 3.6), dpi=100)
    axes.specgram(sound, NFFT=4096, Fs=rec.rate, noverlap=3072, cmap="magma", vmin=-130)
    seconds = (np.array(riding) + lag) / analysis.FRAME_RATE
    firing = [analysis.layout_frequency(rec.frames[i]) for i in riding]
    axes.plot(seconds, firing, color="cyan", linewidth=1.0, linestyle=(0, (4, 4)),
              label="firing frequency of the layout at the logged rpm")
    axes.set_ylim(0, TOP)
    axes.set_xlabel("time (s)")
    axes.set_ylabel("frequency (Hz)")
    axes.set_title(title, fontsize=10)
    axes.legend(loc="upper right", fontsize=8)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)
