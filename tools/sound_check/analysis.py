"""What a recording of the bike says: its pitch window by window, how loud it is, and
whether silence is exactly silent, set against the engine state the game logged each
frame (tests/sound/sound_capture.gd): its crank speed and its layout's cylinders and
strokes, from which the firing frequency is worked out here, not taken from the game."""

import csv
import wave
from dataclasses import dataclass

import numpy as np

FRAME_RATE = 60
# The engines' pitch range (Hz): a four-stroke single idles at 14 firings a second, an
# inline four shifting up at 10 500 rpm fires 350 times.
LOWEST, HIGHEST = 10.0, 400.0


@dataclass
class Recording:
    samples: np.ndarray  # mono, -1..1
    rate: int
    frames: list[dict]  # the log, one row per game frame

    def frame_samples(self, first: int, count: int, lag: int = 0) -> np.ndarray:
        per = self.rate // FRAME_RATE
        start = (first + lag) * per
        return self.samples[start:start + count * per]


def load(wav_path: str, csv_path: str) -> Recording:
    with wave.open(wav_path, "rb") as wav:
        width, channels, rate = wav.getsampwidth(), wav.getnchannels(), wav.getframerate()
        raw = wav.readframes(wav.getnframes())
    kinds = {2: (np.int16, 32768.0), 4: (np.int32, 2147483648.0)}
    if width not in kinds:
        raise ValueError(f"{wav_path}: {8 * width}-bit samples are not read here")
    kind, scale = kinds[width]
    samples = np.frombuffer(raw, dtype=kind).astype(np.float64) / scale
    samples = samples.reshape(-1, channels).mean(axis=1)
    with open(csv_path, newline="", encoding="utf-8") as f:
        frames = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    return Recording(samples, rate, frames)


def layout_frequency(row: dict) -> float:
    """Exhaust pulses per second at the row's crank speed, for its engine's layout: each
    cylinder fires once a turn on a two-stroke, every second turn on a four-stroke."""
    return row["rpm"] / 60.0 * row["cylinders"] * 2.0 / row["strokes"]


def pitch(samples: np.ndarray, rate: int) -> float:
    """Fundamental frequency by autocorrelation: past the first lobe (where the
    correlation first falls below zero, so a slowly decaying pulse's own width is not
    taken for a period), the first peak that comes within 10 % of the best in the
    engines' range, so a period's multiples are not taken for it."""
    x = samples - samples.mean()
    n = len(x)
    spectrum = np.fft.rfft(x, 2 * n)
    correlation = np.fft.irfft(spectrum * np.conj(spectrum))[:n]
    high = min(int(rate / LOWEST), n - 2)
    below = np.flatnonzero(correlation[:high] < 0.0)
    if len(below) == 0:
        return float("nan")
    low = max(int(rate / HIGHEST), int(below[0]))
    window = correlation[low:high]
    best = window.max()
    for i in range(1, len(window) - 1):
        if window[i] >= 0.9 * best and window[i] >= window[i - 1] and window[i] >= window[i + 1]:
            return rate / (low + i)
    return float("nan")


@dataclass
class Window:
    first_frame: int
    speed: float
    gear: int
    expected: float  # the layout's firing frequency (Hz) at the logged rpm, window mean
    heard: float  # the recording's pitch (Hz)

    @property
    def error(self) -> float:
        return abs(self.heard / self.expected - 1.0)


def pitch_windows(rec: Recording, lag: int, length: int = 15, hop: int = 5) -> list[Window]:
    """The recording's pitch in windows of `length` frames where the engine held its
    speed within 10 % in one gear and the game ran, against the log `lag` frames
    earlier."""
    windows = []
    for first in range(0, len(rec.frames) - length - lag, hop):
        rows = rec.frames[first:first + length]
        if any(r["paused"] for r in rows):
            continue
        expected = np.array([layout_frequency(r) for r in rows])
        if expected.max() > 1.1 * expected.min() or len({r["gear"] for r in rows}) > 1:
            continue
        heard = pitch(rec.frame_samples(first, length, lag), rec.rate)
        windows.append(Window(first, float(np.mean([r["speed"] for r in rows])),
                              int(rows[-1]["gear"]), float(expected.mean()), heard))
    return windows


def best_lag(rec: Recording, most: int = 10) -> tuple[int, list[Window]]:
    """The delay (frames) between the log and the sound that fits best: the generator's
    buffer holds a few frames of sound ahead of the mixer."""
    fits = []
    for lag in range(most + 1):
        windows = pitch_windows(rec, lag)
        fits.append((float(np.mean([min(w.error, 0.5) for w in windows])), lag, windows))
    _, lag, windows = min(fits, key=lambda fit: fit[0])
    return lag, windows


def rises_with_speed(windows: list[Window], apart: float = 3.0 / 3.6) -> tuple[int, int]:
    """Pairs of windows in the same gear at speeds at least `apart` m/s apart, and how
    many of them sound higher at the higher speed."""
    pairs = higher = 0
    for i, a in enumerate(windows):
        for b in windows[i + 1:]:
            if a.gear == b.gear and abs(a.speed - b.speed) >= apart:
                pairs += 1
                slow, fast = (a, b) if a.speed < b.speed else (b, a)
                higher += fast.heard > slow.heard
    return pairs, higher


def paused_tail(rec: Recording, settle: int = 12) -> np.ndarray:
    """The sound after the game had been paused `settle` frames (fade and buffer out)."""
    paused = [i for i, r in enumerate(rec.frames) if r["paused"]]
    if len(paused) <= settle:
        return np.zeros(0)
    first = paused[settle]
    return rec.frame_samples(first, paused[-1] - first + 1)


def riding_rms(rec: Recording) -> float:
    riding = [i for i, r in enumerate(rec.frames) if not r["paused"] and r["speed"] > 1.0]
    if not riding:
        return 0.0
    sound = rec.frame_samples(riding[0], riding[-1] - riding[0])
    return float(np.sqrt(np.mean(sound ** 2)))
