"""Before and after a change: the same configurations in two results files, paired by
attempt (attempt i meets the same bumps in both), with the exact McNemar test per
configuration and a sign test over every discordant pair. This is how a physics or
controller change is held against the results committed before it (docs/experiment.md,
"Comparing with earlier results")."""

from __future__ import annotations

from dataclasses import dataclass, replace

from .configs import Config, display_order
from .results import Attempt
from .stats import mcnemar_exact

# A change is called worse when the pairs it lost outnumber the ones it won this clearly.
SIGNIFICANCE = 0.05


@dataclass(frozen=True)
class Pairing:
    """One configuration ridden before and after, on the attempts both rode."""

    config: Config
    pairs: int
    goals_before: int
    goals_after: int
    only_after: int
    only_before: int
    # Mean planning time per control step over the paired attempts (0 for arcade):
    # timed as each row was ridden, so a loaded machine's figure, not a cost ratio.
    planning_before: float = 0.0
    planning_after: float = 0.0

    @property
    def p(self) -> float:
        return mcnemar_exact(self.only_after, self.only_before)

    @property
    def planning_ratio(self) -> str:
        if self.planning_before <= 0.0:
            return "–"
        return f"{self.planning_after / self.planning_before:.2f}"


@dataclass(frozen=True)
class Comparison:
    pairings: list[Pairing]

    @property
    def only_after(self) -> int:
        return sum(p.only_after for p in self.pairings)

    @property
    def only_before(self) -> int:
        return sum(p.only_before for p in self.pairings)

    @property
    def p(self) -> float:
        """Sign test over every discordant pair of every configuration: under no effect
        each is as likely won by either side."""
        return mcnemar_exact(self.only_after, self.only_before)

    @property
    def worse(self) -> bool:
        return self.only_before > self.only_after and self.p < SIGNIFICANCE

    def table(self) -> str:
        lines = [
            "| configuration | pairs | goals before | goals after | only after | only before "
            "| McNemar p | planning after ÷ before |",
            "|---|---|---|---|---|---|---|---|",
        ]
        for p in self.pairings:
            lines.append(
                f"| {p.config.label} | {p.pairs} | {p.goals_before} | {p.goals_after} | "
                f"{p.only_after} | {p.only_before} | {_p(p.p)} | {p.planning_ratio} |"
            )
        lines += [
            "",
            f"Over all {sum(p.pairs for p in self.pairings)} pairs: {self.only_after} won only "
            f"after the change, {self.only_before} only before (sign test p = {_p(self.p)})"
            + ("; **worse after the change**." if self.worse else "."),
        ]
        return "\n".join(lines)


def compare(before: list[Attempt], after: list[Attempt],
            chosen: set[Config] | None = None) -> Comparison:
    """Pairs every configuration found in both (or those `chosen`), attempt by attempt."""
    goal_before = {(a.config, a.attempt): a.outcome == "goal" for a in before}
    goal_after = {(a.config, a.attempt): a.outcome == "goal" for a in after}
    planned_before = {(a.config, a.attempt): a.planning_ms for a in before}
    planned_after = {(a.config, a.attempt): a.planning_ms for a in after}
    configs = {c for (c, _) in goal_before} & {c for (c, _) in goal_after}
    if chosen is not None:
        configs &= chosen
    pairings = []
    for config in sorted(configs, key=lambda c: (display_order(c.controller), c.speed_kmh)):
        shared = sorted({i for (c, i) in goal_before if c == config}
                        & {i for (c, i) in goal_after if c == config})
        was = [goal_before[(config, i)] for i in shared]
        now = [goal_after[(config, i)] for i in shared]
        pairings.append(Pairing(
            config=config,
            pairs=len(shared),
            goals_before=sum(was),
            goals_after=sum(now),
            only_after=sum(n and not w for w, n in zip(was, now)),
            only_before=sum(w and not n for w, n in zip(was, now)),
            planning_before=_mean([planned_before[(config, i)] for i in shared]),
            planning_after=_mean([planned_after[(config, i)] for i in shared]),
        ))
    return Comparison(pairings)


def held_at(attempts: list[Attempt], trajectories: int) -> list[Attempt]:
    """The planners' attempts as if ridden with `trajectories`, so that they pair with
    rows made at that N (fewer trajectories held against the protocol's five); arcade's
    and learned's stay as they are."""
    return [replace(a, config=replace(a.config, controller=replace(
                a.config.controller, trajectories=trajectories)))
            if a.config.controller.plans else a for a in attempts]


def _mean(values: list[float]) -> float:
    return sum(values) / len(values) if values else 0.0


def _p(p: float) -> str:
    return f"**{p:.2g}**" if p < SIGNIFICANCE else f"{p:.2g}"
