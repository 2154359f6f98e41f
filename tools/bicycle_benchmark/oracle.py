"""The paper's linear model, as the `bicycleparameters` package computes it."""

from __future__ import annotations

import numpy as np
from bicycleparameters.models import Meijaard2007Model
from bicycleparameters.parameter_sets import Meijaard2007ParameterSet
from scipy.optimize import brentq

from .modes import Modes


class Oracle:
    """Eigenvalues of the benchmark's linearised equations for given parameters."""

    def __init__(self, parameters: dict[str, float]):
        # The model wants a speed in its parameter set; every call below overrides it.
        self.model = Meijaard2007Model(Meijaard2007ParameterSet(dict(parameters, v=1.0), True))

    def modes(self, speed: float) -> Modes:
        """Weave (the oscillating pair), capsize and castor at `speed`; only meaningful
        where the weave oscillates (above about 0.7 m/s for the benchmark)."""
        values, _ = self.model.calc_eigen(v=speed)
        weave = values[np.argmax(values.imag)]
        real = np.sort(values[np.abs(values.imag) < 1e-9].real)
        if weave.imag <= 0 or len(real) != 2:
            raise ValueError(f"the weave does not oscillate at {speed} m/s: {values}")
        return Modes(complex(weave), float(real[1]), float(real[0]), 0.0)

    def weave_speed(self) -> float:
        """Where the weave turns stable (the paper: about 4.29 m/s)."""
        return brentq(lambda v: self.modes(v).weave.real, 2.0, 6.0)

    def capsize_speed(self) -> float:
        """Where the capsize turns unstable (the paper: about 6.02 m/s)."""
        return brentq(lambda v: self.modes(v).capsize, 5.0, 10.0)

    def simulate(self, times: np.ndarray, speed: float,
                 roll_rate: float) -> tuple[np.ndarray, np.ndarray]:
        """Roll and steer of the linear model after a roll kick (for checking the fit)."""
        states, _ = self.model.simulate(times, [0.0, 0.0, roll_rate, 0.0], v=speed)
        return states[:, 0], states[:, 1]
