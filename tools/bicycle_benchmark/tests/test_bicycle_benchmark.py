"""The benchmark bicycle (a `make test` step): the fit recovers known modes, and the
bicycle built from the game's bodies, hinges and knife-edge tyres is the paper's bicycle
when ODE steps it finely, and at the game's own 1/120 s step in the exact physics model
(direct solver, explicit wheel gyroscopics). The classic model's departure is measured by
`tools/bicycle-benchmark` and recorded in docs/physics.md."""

import unittest

import numpy as np

from bicycle_benchmark.coast import Physics, build, coast
from bicycle_benchmark.compare import compare
from bicycle_benchmark.modes import Modes, crossing, fit
from bicycle_benchmark.oracle import Oracle

# ±10 %: the tolerance for the self-stable band and the weave frequency.
TOLERANCE = 0.10


class FitTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        build()
        parameters, _ = coast([5.0], Physics(duration=0.1))
        cls.oracle = Oracle(parameters)

    def test_the_oracle_is_the_papers_bicycle(self):
        # The paper's Table 2 speeds, as the oracle computes them from our parameters.
        self.assertAlmostEqual(self.oracle.weave_speed(), 4.29, delta=0.01)
        self.assertAlmostEqual(self.oracle.capsize_speed(), 6.02, delta=0.01)

    def test_the_fit_recovers_the_linear_models_modes_from_its_own_motion(self):
        time = np.arange(1, 1201) / 120.0
        for speed in (3.0, 5.0, 8.0):
            expected = self.oracle.modes(speed)
            roll, steer = self.oracle.simulate(time, speed, roll_rate=0.05)
            # Cut where the coaster stops recording: the linear model holds near upright.
            upright = np.cumprod(np.abs(roll) <= 0.2).astype(bool)
            # Started away from the answer, so the test shows the fit finds it.
            start = Modes(expected.weave * 1.2, expected.capsize - 0.3, expected.castor * 0.8,
                          0.0)
            found = fit(time[upright], roll[upright], steer[upright], start)
            with self.subTest(speed=speed):
                self.assertAlmostEqual(found.weave.real, expected.weave.real, delta=0.01)
                self.assertAlmostEqual(found.weave.imag, expected.weave.imag, delta=0.01)
                self.assertLess(found.rms, 1e-3)
                # Below the weave speed the bicycle falls in the weave before the capsize
                # mode shows (compare.Comparison.capsize_speed looks above it only).
                if speed > self.oracle.weave_speed():
                    self.assertAlmostEqual(found.capsize, expected.capsize, delta=0.01)

    def test_a_crossing_is_interpolated_in_the_direction_asked(self):
        speeds = [1.0, 2.0, 3.0, 4.0]
        self.assertAlmostEqual(crossing(speeds, [1.0, 0.5, -0.5, -1.0], rising=False), 2.5)
        self.assertIsNone(crossing(speeds, [1.0, 0.5, -0.5, -1.0], rising=True))
        self.assertAlmostEqual(crossing(speeds, [-2.0, 2.0, 1.0, 1.0], rising=True), 1.5)


class FinelySteppedBicycleTest(unittest.TestCase):
    """At 1 ms ODE's error is small, so what remains is the model: geometry, masses,
    inertias, tyres and contacts."""

    PHYSICS = Physics(dt=1 / 1000)

    @classmethod
    def setUpClass(cls):
        build()
        cls.comparison = compare(cls.PHYSICS)
        cls.oracle = cls.comparison.oracle

    def assertWithin(self, found, expected, what):
        self.assertIsNotNone(found, f"no {what} found")
        self.assertLessEqual(abs(found / expected - 1), TOLERANCE,
                             f"{what}: {found:.2f} against the benchmark's {expected:.2f}")

    def test_it_is_self_stable_between_the_benchmarks_weave_and_capsize_speeds(self):
        self.assertWithin(self.comparison.weave_speed(), self.oracle.weave_speed(),
                          "weave speed")
        self.assertWithin(self.comparison.capsize_speed(), self.oracle.capsize_speed(),
                          "capsize speed")
        middle = [r for r in self.comparison.rows if 4.6 < r.speed < 5.4]
        self.assertTrue(middle and all(r.ridden.self_stable for r in middle))

    def test_its_weave_has_the_benchmarks_frequency_near_the_weave_speed(self):
        speed = self.oracle.weave_speed()
        self.assertWithin(self.comparison.weave_frequency_at(speed),
                          self.oracle.modes(speed).weave.imag, "weave frequency")

    def test_it_falls_over_below_the_weave_speed_and_keeps_its_speed_while_coasting(self):
        slow = [r for r in self.comparison.rows if r.speed < 3.0]
        self.assertTrue(slow and all(r.ridden.weave.real > 0.5 for r in slow))
        _, (coasted,) = coast([5.0], self.PHYSICS)
        self.assertLess(abs(coasted.forward_speed[-1] - 5.0), 0.05)


class ExactModelBicycleTest(FinelySteppedBicycleTest):
    """The exact physics model at the game's step: the direct solver and explicit wheel
    gyroscopics keep the bicycle within the tolerance where the classic model's QuickStep
    with ODE's implicit gyroscopic term is not (capsize -19 %, weave frequency -24 %)."""

    PHYSICS = Physics("direct", dt=1 / 120, gyroscopic="explicit")


if __name__ == "__main__":
    unittest.main()
