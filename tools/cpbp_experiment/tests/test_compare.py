import contextlib
import io
import tempfile
import unittest
from pathlib import Path

from cpbp_experiment import cli
from cpbp_experiment.compare import compare, held_at
from cpbp_experiment.configs import Config, Controller
from cpbp_experiment.results import Attempt, ResultsFile

OPTIMIZER = Config(25, Controller("optimizer", 15, "exact"))
COMBINED = Config(20, Controller("combined", 5, "exact"))
ARCADE = Config(20, Controller("arcade"))


def rides(config: Config, outcomes: str, first: int = 0) -> list[Attempt]:
    """One attempt per letter, from attempt `first`: g reached the goal, f fell."""
    return [Attempt(config, first + i, 1000 + first + i, "goal" if o == "g" else "fell",
                    7.0, 36.0, 210, 12.0, 3000.0)
            for i, o in enumerate(outcomes)]


class CompareTest(unittest.TestCase):
    def test_pairs_by_attempt_and_counts_the_discordant_pairs(self):
        before = rides(OPTIMIZER, "gffgg") + rides(COMBINED, "ggg")
        after = rides(OPTIMIZER, "ggfgf") + rides(COMBINED, "ggf")
        comparison = compare(before, after)
        optimizer, combined = comparison.pairings
        self.assertEqual(optimizer.config, OPTIMIZER)
        self.assertEqual((optimizer.pairs, optimizer.goals_before, optimizer.goals_after,
                          optimizer.only_after, optimizer.only_before), (5, 3, 3, 1, 1))
        self.assertEqual((combined.only_after, combined.only_before), (0, 1))
        self.assertEqual((comparison.only_after, comparison.only_before), (1, 2))
        self.assertAlmostEqual(comparison.p, 1.0)
        self.assertFalse(comparison.worse)

    def test_only_attempts_and_configurations_both_rode_are_paired(self):
        before = rides(OPTIMIZER, "ffff") + rides(ARCADE, "gg")
        after = rides(OPTIMIZER, "gg", first=2) + rides(COMBINED, "g")
        comparison = compare(before, after)
        self.assertEqual([p.config for p in comparison.pairings], [OPTIMIZER])
        self.assertEqual(comparison.pairings[0].pairs, 2)
        self.assertEqual(compare(before, after, chosen={COMBINED}).pairings, [])

    def test_a_clear_loss_is_worse_and_a_clear_gain_is_not(self):
        # Six discordant pairs all one way: exact two-sided p = 2 / 2^6 = 0.031.
        good, bad = rides(COMBINED, "g" * 6), rides(COMBINED, "f" * 6)
        self.assertTrue(compare(good, bad).worse)
        self.assertAlmostEqual(compare(good, bad).p, 0.03125)
        self.assertFalse(compare(bad, good).worse)
        self.assertIn("**worse after the change**", compare(good, bad).table())
        self.assertIn("| combined-5:exact @ 20 km/h | 6 | 6 | 0 | 0 | 6 | **0.031** | 1.00 |",
                      compare(good, bad).table())

    def test_the_planning_ratio_is_over_the_paired_attempts(self):
        before = rides(COMBINED, "gggg")
        after = [Attempt(a.config, a.attempt, a.seed, a.outcome, 7.0, 36.0, 210,
                         6.0 if a.attempt < 2 else 9.0, 3000.0)
                 for a in rides(COMBINED, "ggg", first=1)]
        # Attempts 1-3 pair: after plans 6, 9, 9 ms against 12 before: 8 / 12.
        pairing = compare(before, after).pairings[0]
        self.assertEqual(pairing.planning_ratio, "0.67")
        self.assertEqual(compare(rides(ARCADE, "g"), rides(ARCADE, "g"))
                         .pairings[0].planning_ratio, "1.00")

    def test_fewer_trajectories_pair_with_the_five_when_asked(self):
        four = Config(20, Controller("combined", 4, "exact"))
        after = rides(four, "ggf") + rides(ARCADE, "g")
        self.assertEqual(compare(rides(COMBINED, "ggg"), after).pairings, [])
        held = compare(rides(COMBINED, "ggg") + rides(ARCADE, "g"), held_at(after, 5))
        self.assertEqual([p.config for p in held.pairings], [ARCADE, COMBINED])
        self.assertEqual((held.pairings[1].only_after, held.pairings[1].only_before), (0, 1))
        with tempfile.TemporaryDirectory() as directory:
            before_dir, after_dir = Path(directory, "before"), Path(directory, "after")
            for folder, attempts in ((before_dir, rides(COMBINED, "ggg")), (after_dir, after)):
                folder.mkdir()
                results = ResultsFile(folder / "results.csv")
                for attempt in attempts:
                    results.append(attempt)
            printed = io.StringIO()
            with contextlib.redirect_stdout(printed):
                self.assertEqual(cli.main(["compare", "--out", str(after_dir), "--before",
                                           str(before_dir), "--before-count", "5"]), 0)
            self.assertIn("against N = 5 before", printed.getvalue())
            self.assertIn("| combined-5:exact @ 20 km/h | 3 | 3 | 2 | 0 | 1 |",
                          printed.getvalue())

    def test_the_command_exits_1_when_worse_and_says_what_is_missing(self):
        with tempfile.TemporaryDirectory() as directory:
            before_dir, after_dir = Path(directory, "before"), Path(directory, "after")
            for folder, outcomes in ((before_dir, "g" * 6), (after_dir, "f" * 6)):
                folder.mkdir()
                results = ResultsFile(folder / "results.csv")
                for attempt in rides(COMBINED, outcomes):
                    results.append(attempt)
            printed = io.StringIO()
            with contextlib.redirect_stdout(printed):
                worse = cli.main(["compare", "--out", str(after_dir), "--before",
                                  str(before_dir)])
                better = cli.main(["compare", "--out", str(before_dir), "--before",
                                   str(after_dir)])
            self.assertEqual((worse, better), (1, 0))
            self.assertIn("0 won only after the change, 6 only before", printed.getvalue())
            with contextlib.redirect_stdout(io.StringIO()):
                # Speeds alone filter by speed, whatever the controllers.
                self.assertEqual(cli.main(["compare", "--out", str(after_dir), "--before",
                                           str(before_dir), "--speeds", "20"]), 1)
            with contextlib.redirect_stderr(io.StringIO()) as errors:
                self.assertEqual(cli.main(["compare", "--out", str(after_dir)]), 1)
                self.assertEqual(cli.main(["compare", "--out", str(after_dir), "--before",
                                           str(Path(directory, "nowhere"))]), 1)
            self.assertIn("compare needs --before DIR", errors.getvalue())
            self.assertIn("does not exist", errors.getvalue())


if __name__ == "__main__":
    unittest.main()
