"""The bike an experiment rides (`--bike`, `--model`) and how its planners plan (`--set`):
what the workers are told to load and set, and what its rows and report call it."""

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
    # Planner settings other than their defaults, each "NAME=VALUE", sorted by name (the
    # workers check them against the schema and refuse what does not fit).
    settings: tuple[str, ...] = ()

    @staticmethod
    def reference() -> "Bike":
        return Bike(REFERENCE_BIKE)

    @staticmethod
    def of_file(root: Path, path: str | None, model: str | None = None,
                settings: list[str] | None = None) -> "Bike":
        """The bike in file `path` (None: the reference), its network the one in file
        `model` (None: its own); both must lie in the project at `root`, where the
        workers load them from as res:// paths; its planners planning with `settings`
        ("NAME=VALUE"). Raises ValueError saying what is wrong."""
        bike = Bike(Path(path).stem, _resource(root, "--bike", path, "bike file")) if path \
            else Bike.reference()
        if model:
            bike = replace(bike, model=_resource(root, "--model", model, "model file"))
        named = {}
        for assignment in settings or []:
            name, equals, value = assignment.partition("=")
            if not (name and equals and value):
                raise ValueError(f"--set takes NAME=VALUE, not {assignment}")
            named[name] = value
        return replace(bike, settings=tuple(f"{n}={named[n]}" for n in sorted(named)))

    @property
    def label(self) -> str:
        """What rows and reports call it: the name, with "+" and the network's bike when
        the network is another's (pit_bike+street_390), and "@" and the planner settings
        when they are not the defaults (street_390@horizon=0.6): rows of other settings
        never join a results file."""
        label = self.name
        if self.model:
            label += f"+{Path(self.model).stem.removeprefix(MODEL_PREFIX)}"
        if self.settings:
            label += "@" + ",".join(self.settings)
        return label

    def arguments(self) -> list[str]:
        """A worker's arguments for riding it."""
        return ([f"--bike={self.resource}"] if self.resource else []) + \
            ([f"--model={self.model}"] if self.model else []) + \
            [f"--set={assignment}" for assignment in self.settings]


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
