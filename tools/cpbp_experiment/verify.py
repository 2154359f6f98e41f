"""`tools/experiment verify`: re-rides chosen rows of a results file and says which repeat
exactly (same outcome, time, distance and steps, as the file spells them)."""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path

from .configs import parse_attempts
from .results import Attempt, ResultsError, ResultsFile
from .progress import Progress
from .runner import Block, Platform, plan_blocks, run_blocks


@dataclass
class Verdict:
    """The chosen rows, and those whose re-ride differs (saved row, re-ride)."""

    checked: list[Attempt]
    differing: list[tuple[Attempt, Attempt]]

    @property
    def exact(self) -> int:
        return len(self.checked) - len(self.differing)

    def lines(self, limit: int = 20) -> list[str]:
        out = [f"verify: {self.exact} of {len(self.checked)} rows re-ride exactly"]
        for saved, again in self.differing[:limit]:
            out.append(f"  {saved.config.label} attempt {saved.attempt}: saved "
                       f"{'/'.join(saved.outcome_fields())}, re-ridden "
                       f"{'/'.join(again.outcome_fields())}")
        if len(self.differing) > limit:
            out.append(f"  … and {len(self.differing) - limit} more")
        return out


def parse_rows(text: str) -> set[int]:
    """Line numbers of the results file (the header is line 1): `2-11,40`."""
    return set(parse_attempts(text, low=2))


def choose(attempts: list[Attempt], rows: set[int] | None, wanted_attempts: set[int] | None,
           configs) -> list[Attempt]:
    """The rows to check: by line number, else by attempt number within `configs`
    (None: every configuration in the file)."""
    if rows is not None:
        lines = {line: a for line, a in enumerate(attempts, start=2)}
        missing = sorted(rows - lines.keys())
        if missing:
            raise ResultsError(f"the results file has no rows at lines {missing[:5]} (it "
                               f"has lines 2–{len(attempts) + 1})")
        return [lines[line] for line in sorted(rows)]
    return [a for a in attempts
            if (wanted_attempts is None or a.attempt in wanted_attempts)
            and (configs is None or a.config in configs)]


def verify(chosen: list[Attempt], base_seed: int, jobs: int, threads: int, log: Path,
           platform: Platform) -> Verdict:
    """Re-rides `chosen` with fresh workers into a scratch file and compares."""
    by_config: dict = {}
    for attempt in chosen:
        by_config.setdefault(attempt.config, set()).add(attempt.attempt)
    blocks: list[Block] = []
    for config, numbers in by_config.items():
        every = range(max(numbers) + 1)
        blocks += plan_blocks([config], len(every), {(config, n) for n in every
                                                     if n not in numbers})
    with tempfile.TemporaryDirectory(prefix="verify-") as scratch:
        again = ResultsFile(Path(scratch) / "results.csv")
        progress = Progress(total=len(chosen), jobs=jobs, done_before=0)
        run_blocks(blocks, again, progress, base_seed, jobs, threads, log, platform)
        ridden = {a.key: a for a in again.load()}
    differing = [(a, ridden[a.key]) for a in chosen
                 if ridden[a.key].outcome_fields() != a.outcome_fields()]
    return Verdict(chosen, differing)
