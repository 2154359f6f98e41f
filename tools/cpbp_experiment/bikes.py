"""The bike an experiment rides (`--bike`, `--model`): what the workers are told to load
and what its rows and report call it."""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

from .results import REFERENCE_BIKE


@dataclass(frozen=True)
class Bike:
    """The bike a run rides: its name (the file's), the res:// path a worker loads (empty
    for the reference bike, the workers' own) and the learned controllers' network when
    it is not the bike's own (`--model`: how far another bike's network carries)."""

    name: str
    resource: str = ""
    model: str = ""

    @staticmethod
    def reference() -> "Bike":
        return Bike(REFERENCE_BIKE)

    @staticmethod
    def of_file(root: Path, path: str | None, model: str | None = None) -> "Bike":
        """The bike in file `path` (None: the reference), its network the one in file
        `model` (None: its own); both must lie in the project at `root`, where the
        workers load them from as res:// paths. Raises ValueError saying what is wrong."""
        bike = Bike(Path(path).stem, _resource(root, "--bike", path, "bike file")) if path \
            else Bike.reference()
        if model:
            bike = replace(bike, model=_resource(root, "--model", model, "model file"))
        return bike

    @property
    def label(self) -> str:
        """What rows and reports call it: the name, with "+" and the network's bike when
        the network is another's (pit_bike+street_390)."""
        if not self.model:
            return self.name
        return f"{self.name}+{Path(self.model).stem.removeprefix(MODEL_PREFIX)}"

    def arguments(self) -> list[str]:
        """A worker's arguments for riding it."""
        return ([f"--bike={self.resource}"] if self.resource else []) + \
            ([f"--model={self.model}"] if self.model else [])


# Model files are named policy-<bike>.safetensors (models/).
MODEL_PREFIX = "policy-"


def _resource(root: Path, option: str, path: str, what: str) -> str:
    file = Path(path).resolve()
    if not file.is_file():
        raise ValueError(f"{option} {path}: no such {what}")
    if not file.is_relative_to(root):
        raise ValueError(f"{option} {path}: the file must lie in the project "
                         f"({root}), where the workers load it from")
    return "res://" + file.relative_to(root).as_posix()
