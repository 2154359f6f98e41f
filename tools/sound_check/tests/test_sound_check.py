"""The sound check itself: it hears a pulse train's pitch, finds the sound's delay behind
the log, works the firing frequency out of the crank speed and the layout, and fails a
recording whose pitch does not follow the engine or whose pause is not silent."""

import csv
import tempfile
import unittest
import wave
from pathlib import Path

import numpy as np

from sound_check import analysis
from sound_check.__main__ import main

RATE = 48_000
PER_FRAME = RATE // analysis.FRAME_RATE


def pulses(frequencies: np.ndarray) -> np.ndarray:
    """A decaying pulse every period, the period following `frequencies` sample by sample."""
    phase = np.cumsum(frequencies / RATE)
    within = phase % 1.0
    return np.exp(-4.0 * within) * 0.5 - 0.15


def write(folder: Path, sound: np.ndarray, rows: list[dict]) -> tuple[str, str]:
    wav_path, csv_path = folder / "ride.wav", folder / "ride.csv"
    with wave.open(str(wav_path), "wb") as wav:
        wav.setnchannels(2)
        wav.setsampwidth(2)
        wav.setframerate(RATE)
        pcm = (np.clip(sound, -1, 1) * 32767).astype(np.int16)
        wav.writeframes(np.repeat(pcm, 2).tobytes())
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return str(wav_path), str(csv_path)


def ride(frames: int = 400, paused_from: int = 340, lag: int = 4, wrong: bool = False,
         cylinders: int = 1, strokes: int = 4, heard_as: float = 1.0):
    """A ride accelerating through two gears on an engine of `cylinders` and `strokes`, its
    log, and its sound `lag` frames late (at `heard_as` times the firing frequency)."""
    rows, per_sample = [], []
    for frame in range(frames):
        speed = min(frame / 30.0, 9.0)
        gear = 1 if speed < 5.0 else 2
        firing = (15.0 + speed * (9.0 if gear == 1 else 5.0)) * cylinders * 4 / strokes
        rpm = firing * 60.0 * strokes / (2.0 * cylinders)
        rows.append({"frame": frame, "mix_rate": RATE, "paused": int(frame >= paused_from),
                     "speed": speed, "rpm": rpm, "gear": gear, "firing_frequency": firing,
                     "cylinders": cylinders, "strokes": strokes})
        per_sample.append(np.full(PER_FRAME, 40.0 if wrong else firing * heard_as))
    frequencies = np.concatenate([np.full(lag * PER_FRAME, 15.0)] + per_sample)[:frames * PER_FRAME]
    sound = pulses(frequencies)
    sound[(paused_from + 8) * PER_FRAME:] = 0.0
    return sound, rows


class SoundCheckTest(unittest.TestCase):
    def test_the_pitch_of_a_pulse_train(self):
        for frequency in (14.0, 33.0, 61.0, 90.0, 180.0, 330.0):
            heard = analysis.pitch(pulses(np.full(RATE // 4, frequency)), RATE)
            self.assertAlmostEqual(heard / frequency, 1.0, delta=0.02)

    def test_a_faithful_recording_passes_and_its_delay_is_found(self):
        with tempfile.TemporaryDirectory() as folder:
            paths = write(Path(folder), *ride(lag=4))
            self.assertEqual(main(list(paths)), 0)
            self.assertEqual(analysis.best_lag(analysis.load(*paths))[0], 4)

    def test_each_layout_passes_heard_at_its_own_firing_frequency(self):
        for cylinders, strokes in ((1, 2), (4, 4)):
            with tempfile.TemporaryDirectory() as folder:
                paths = write(Path(folder), *ride(cylinders=cylinders, strokes=strokes))
                self.assertEqual(main(list(paths)), 0, f"{cylinders} cylinders, {strokes}")

    def test_an_engine_firing_as_another_layout_fails(self):
        # The log says an inline four, the sound fires as a single would at that rpm.
        with tempfile.TemporaryDirectory() as folder:
            sound, rows = ride(cylinders=4, strokes=4, heard_as=0.25)
            self.assertEqual(main(list(write(Path(folder), sound, rows))), 1)
        # The synthesiser's own figure disagrees with the layout.
        sound, rows = ride()
        for row in rows:
            row["firing_frequency"] *= 2
        with tempfile.TemporaryDirectory() as folder:
            self.assertEqual(main(list(write(Path(folder), sound, rows))), 1)

    def test_the_spectrogram_is_drawn(self):
        with tempfile.TemporaryDirectory() as folder:
            paths = write(Path(folder), *ride())
            picture = Path(folder) / "ride.png"
            self.assertEqual(main([*paths, "--spectrogram", str(picture), "--title", "t"]), 0)
            self.assertGreater(picture.stat().st_size, 10_000)

    def test_a_pitch_that_ignores_the_engine_fails(self):
        with tempfile.TemporaryDirectory() as folder:
            self.assertEqual(main(list(write(Path(folder), *ride(wrong=True)))), 1)

    def test_a_pause_that_is_not_silent_fails(self):
        sound, rows = ride()
        sound[-PER_FRAME:] = 1e-4
        with tempfile.TemporaryDirectory() as folder:
            self.assertEqual(main(list(write(Path(folder), sound, rows))), 1)


if __name__ == "__main__":
    unittest.main()
