import unittest

from cpbp_experiment.stats import holm, mcnemar_exact, wilson_interval


class WilsonIntervalTest(unittest.TestCase):
    def test_matches_newcombes_published_values(self):
        # Newcombe (1998), "Two-sided confidence intervals for the single proportion",
        # Statistics in Medicine 17, Table I, method 3 (score interval without continuity
        # correction), to four decimals.
        known = {
            (81, 263): (0.2553, 0.3662),
            (15, 148): (0.0624, 0.1605),
            (0, 20): (0.0000, 0.1611),
            (1, 29): (0.0061, 0.1718),
            (29, 29): (0.8830, 1.0000),
        }
        for (successes, trials), (low, high) in known.items():
            with self.subTest(successes=successes, trials=trials):
                got_low, got_high = wilson_interval(successes, trials)
                self.assertAlmostEqual(got_low, low, places=4)
                self.assertAlmostEqual(got_high, high, places=4)

    def test_stays_within_zero_and_one_and_holds_the_estimate(self):
        for trials in (1, 7, 200, 500):
            for successes in range(0, trials + 1, max(1, trials // 10)):
                low, high = wilson_interval(successes, trials)
                self.assertTrue(0.0 <= low <= successes / trials <= high <= 1.0)

    def test_narrows_with_more_trials(self):
        widths = [wilson_interval(n // 2, n) for n in (20, 200, 2000)]
        spans = [high - low for low, high in widths]
        self.assertGreater(spans[0], spans[1])
        self.assertGreater(spans[1], spans[2])

    def test_refuses_impossible_counts(self):
        for successes, trials in ((1, 0), (-1, 5), (6, 5)):
            with self.subTest(successes=successes, trials=trials):
                with self.assertRaises(ValueError):
                    wilson_interval(successes, trials)


class McNemarTest(unittest.TestCase):
    def test_matches_the_binomial_tail(self):
        # 1 against 6 discordant pairs: P(X ≤ 1 | n = 7, ½) = 8/128, two-sided 0.125.
        self.assertAlmostEqual(mcnemar_exact(1, 6), 0.125)
        self.assertAlmostEqual(mcnemar_exact(6, 1), 0.125)
        # 0 against 10: 2 · 2⁻¹⁰.
        self.assertAlmostEqual(mcnemar_exact(0, 10), 2 / 1024)
        # Agresti, Categorical Data Analysis (2002), §10.1.4: 86 against 150 discordant
        # pairs gives an exact two-sided P of about 3.8e-5 (z = 4.17 asymptotically).
        self.assertLess(mcnemar_exact(86, 150), 5e-5)
        self.assertGreater(mcnemar_exact(86, 150), 2e-5)

    def test_an_even_split_or_no_discordant_pair_shows_nothing(self):
        self.assertEqual(mcnemar_exact(0, 0), 1.0)
        self.assertEqual(mcnemar_exact(5, 5), 1.0)


class HolmTest(unittest.TestCase):
    def test_the_worked_example(self):
        # Four hypotheses with p = 0.01, 0.04, 0.03, 0.005 at α = 0.05 (the worked example
        # of Holm's method in its Wikipedia article): sorted, 0.005 ≤ 0.05/4 and 0.01 ≤
        # 0.05/3 reject, 0.03 > 0.05/2 stops, so H1 and H4 are rejected and H2, H3 not.
        reject, adjusted = holm([0.01, 0.04, 0.03, 0.005])
        self.assertEqual(reject, [True, False, False, True])
        # Adjusted: 4·0.005, 3·0.01, then max(2·0.03, earlier) and max(1·0.04, 0.06).
        for got, want in zip(adjusted, [0.03, 0.06, 0.06, 0.02]):
            self.assertAlmostEqual(got, want)

    def test_one_test_is_left_alone_and_nothing_is_nothing(self):
        self.assertEqual(holm([0.04]), ([True], [0.04]))
        self.assertEqual(holm([]), ([], []))

    def test_refuses_impossible_p_values(self):
        with self.assertRaises(ValueError):
            holm([0.5, 1.5])


if __name__ == "__main__":
    unittest.main()
