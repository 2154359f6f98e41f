"""Experiment configurations: a controller (with its trajectory count, in a physics
model) at a speed."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from .settings import SETTINGS

THESIS_SPEEDS = (10, 15, 20, 25)
THESIS_CONTROLLERS = (
    "arcade",
    "optimizer-5",
    "optimizer-10",
    "optimizer-15",
    "combined-5",
    "combined-10",
    "combined-15",
)
# The controller registry (cpbp_core::ride::ControllerKind::BUILT_IN) as the native tests
# write it into controllers.json and hold it equal: every controller's name, menu label,
# whether players pick it and whether it plans. The worker also refuses a name the
# registry does not know. The trajectory counts the ride takes are the settings schema's.
_NATIVE = json.loads(Path(__file__).with_name("controllers.json").read_text("utf-8"))
REGISTRY = tuple(_NATIVE["controllers"])
MIN_TRAJECTORIES, MAX_TRAJECTORIES = (int(n) for n in SETTINGS["trajectories"].range[:2])
PLANNERS = tuple(entry["name"] for entry in REGISTRY if entry["plans"])
# The controllers players pick that drive by themselves, without trajectories or an N
# (arcade, learned).
DRIVERS = tuple(entry["name"] for entry in REGISTRY if entry["offered"] and not entry["plans"])
# The thesis's planners, C-PBP alone and warm-started; the registry's other planners are
# the baselines they are compared with.
THESIS_PLANNERS = ("optimizer", "combined")
# Planners whose trajectory 1 follows a controller: each against combined at the same N.
FOLLOWING_PLANNERS = ("guided",)
BASELINES = tuple(kind for kind in PLANNERS
                  if kind not in THESIS_PLANNERS + FOLLOWING_PLANNERS)
# The game's physics models (cpbp_core::physics::PhysicsModel); rows without one are
# classic, the model every row was ridden in before the exact model existed.
PHYSICS = ("classic", "exact")
# The evaluation on the game's physics (docs/results.md): every thesis configuration with
# 200 tries and arcade with 500, the baselines and the network's controllers with 100, and
# 5 and 30 km/h beside the thesis's speeds for arcade, combined-5, learned and guided-5.
# (controllers, speeds, tries); a configuration named twice takes the larger count.
GAME_PROTOCOL = (
    ("arcade:exact", (5, 10, 15, 20, 25, 30), 500),
    (",".join(f"{p}-{n}:exact" for p in THESIS_PLANNERS for n in (5, 10, 15)), THESIS_SPEEDS,
     200),
    ("sampling-10:exact,mppi-10:exact,learned:exact,guided-5:exact", THESIS_SPEEDS, 100),
    ("combined-5:exact,learned:exact,guided-5:exact", (5, 30), 100),
)
# Trajectory counts of the planning-time study (Figure 5.2 and beyond).
TIMING_COUNTS = (5, 6, 8, 10, 15, 20, 32, 64, 128)


@dataclass(frozen=True, order=True)
class Controller:
    """`arcade`, or a planner (one of PLANNERS) with its trajectory count N, riding
    in a physics model: `combined-5` is classic, `combined-5:exact` the exact model."""

    kind: str
    trajectories: int = 0
    physics: str = "classic"

    @property
    def plans(self) -> bool:
        """Whether it plans with trajectories (and so has an N and a planning time)."""
        return self.kind in PLANNERS

    @property
    def label(self) -> str:
        name = f"{self.kind}-{self.trajectories}" if self.plans else self.kind
        return name if self.physics == "classic" else f"{name}:{self.physics}"

    def in_physics(self, physics: str) -> "Controller":
        return Controller(self.kind, self.trajectories, physics)

    @staticmethod
    def parse(label: str) -> "Controller":
        name, _, physics = label.strip().partition(":")
        physics = physics or "classic"
        if physics not in PHYSICS:
            raise ValueError(f"unknown physics '{physics}' in '{label}': use "
                             f"{' or '.join(PHYSICS)}")
        kind, _, count = name.partition("-")
        if kind in DRIVERS and not count:
            return Controller(kind, 0, physics)
        if kind in PLANNERS and count.isdigit() and (
                MIN_TRAJECTORIES <= int(count) <= MAX_TRAJECTORIES):
            return Controller(kind, int(count), physics)
        planners = ", ".join(f"{p}-N" for p in PLANNERS)
        raise ValueError(
            f"unknown controller '{label}': use {' or '.join(DRIVERS)} or {planners} "
            f"(N in {MIN_TRAJECTORIES}–{MAX_TRAJECTORIES}), "
            "with :exact for the exact physics"
        )


@dataclass(frozen=True, order=True)
class Config:
    speed_kmh: int
    controller: Controller

    @property
    def label(self) -> str:
        return f"{self.controller.label} @ {self.speed_kmh} km/h"


def protocol_tries(at_least: int = 0) -> dict["Config", int]:
    """The game protocol's configurations and their tries, each raised to `at_least`."""
    tries: dict[Config, int] = {}
    for controllers, speeds, count in GAME_PROTOCOL:
        for controller in parse_controllers(controllers):
            for speed in speeds:
                config = Config(speed, controller)
                tries[config] = max(tries.get(config, 0), count, at_least)
    return tries


def parse_speeds(text: str) -> list[int]:
    return _whole_numbers(text, 1, 90, "speeds are whole km/h")


def parse_controllers(text: str) -> list[Controller]:
    return sorted({Controller.parse(item) for item in text.split(",")}, key=display_order)


def display_order(controller: Controller) -> tuple[int, int, int]:
    """The thesis's order: arcade, then the optimizer, then combined (then the baselines),
    each by N, each physics model beside the classic one."""
    return ((DRIVERS + PLANNERS).index(controller.kind), controller.trajectories,
            PHYSICS.index(controller.physics))


def parse_counts(text: str) -> list[int]:
    return _whole_numbers(text, MIN_TRAJECTORIES, MAX_TRAJECTORIES,
                          "trajectory counts are whole numbers")


def _whole_numbers(text: str, low: int, high: int, what: str) -> list[int]:
    """A comma-separated list of whole numbers within low–high, sorted, each once."""
    numbers = set()
    for item in text.split(","):
        if not item.strip().isdigit() or not low <= int(item) <= high:
            raise ValueError(f"{what} within {low}–{high}, not '{item}'")
        numbers.add(int(item))
    return sorted(numbers)


def parse_attempts(text: str, low: int = 0) -> list[int]:
    """Whole numbers and ranges, comma-separated: `0-19,25` (at least `low`)."""
    numbers = set()
    for item in text.split(","):
        first, _, last = item.strip().partition("-")
        if not first.isdigit() or not (last or first).isdigit():
            raise ValueError(f"expected numbers or ranges like 0-19, not '{item}'")
        start, end = int(first), int(last or first)
        if start < low or end < start or end - start > 1_000_000:
            raise ValueError(f"'{item}' is not a range from {low} up")
        numbers.update(range(start, end + 1))
    return sorted(numbers)
