import tempfile
import unittest
from pathlib import Path

from planner_scenarios import report
from planner_scenarios.rows import FIELDS, ScenarioRows, parse
from planner_scenarios.stats import paired_difference, t_interval


def line(scenario, controller, n, seed, fell, metric):
    return f"{scenario},{controller},{n},{seed},exact,{'true' if fell else 'false'},{metric},9.5"


class StatsTest(unittest.TestCase):
    def test_the_t_interval_of_a_known_sample(self):
        # Mean 2, sd 1, n 3: half-width t(0.975, 2) · 1/√3 = 4.3027 · 0.57735 = 2.4841.
        interval = t_interval([1.0, 2.0, 3.0])
        self.assertAlmostEqual(interval.mean, 2.0)
        self.assertAlmostEqual(interval.high - interval.mean, 2.4841, places=4)

    def test_a_paired_difference_uses_only_the_shared_seeds(self):
        difference = paired_difference({0: 5.0, 1: 7.0, 2: 9.0}, {0: 4.0, 1: 5.0, 3: 1.0})
        self.assertEqual(difference.n, 2)
        self.assertAlmostEqual(difference.mean, 1.5)

    def test_too_few_values_say_so(self):
        self.assertEqual(t_interval([]).text(), "–")
        self.assertEqual(t_interval([3.0]).text(), "3.0 (n = 1)")


class RowsTest(unittest.TestCase):
    def test_rows_append_and_read_back_and_a_cut_line_is_dropped(self):
        with tempfile.TemporaryDirectory() as tmp:
            rows = ScenarioRows(Path(tmp) / "scenarios.csv")
            rows.append(line("turn", "mppi", 5, 0, False, 4.5))
            rows.append(line("turn", "mppi", 5, 1, True, 30.0))
            with rows.path.open("a") as file:
                file.write("turn,mppi,5,2,ex")  # killed mid-write
            loaded = rows.load()
            self.assertEqual([r["seed"] for r in loaded], [0, 1])
            self.assertTrue(loaded[1]["fell"])
            self.assertTrue(rows.path.read_text().endswith("\n"))

    def test_malformed_rows_and_foreign_files_are_errors(self):
        with self.assertRaisesRegex(ValueError, "fell is true or false"):
            parse("turn,mppi,5,0,exact,maybe,1.0,2.0")
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "scenarios.csv"
            path.write_text("speed_kmh,controller\n")
            with self.assertRaisesRegex(ValueError, "not a scenarios file"):
                ScenarioRows(path).load()
        self.assertEqual(FIELDS[0], "scenario")


class MeasuresTest(unittest.TestCase):
    def test_a_row_reports_its_measures_and_an_earlier_row_none(self):
        row = parse(line("brake60", "arcade", 0, 3, False, 0.91)
                    + ",distance_m=15.5;rear_lift_mm=0.3")
        self.assertEqual(row["extra"], {"distance_m": 15.5, "rear_lift_mm": 0.3})
        self.assertEqual(parse(line("turn", "mppi", 5, 0, False, 4.5))["extra"], {})
        with self.assertRaisesRegex(ValueError, "name=number"):
            parse(line("brake60", "arcade", 0, 3, False, 0.91) + ",distance_m=far")

    def test_a_file_with_the_earlier_columns_still_reads_and_takes_new_rows(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "scenarios.csv"
            path.write_text(",".join(FIELDS[:-1]) + "\n"
                            + line("turn", "mppi", 5, 0, False, 4.5) + "\n")
            rows = ScenarioRows(path)
            rows.append(line("brake90", "combined", 5, 0, False, 0.92) + ",peak_g=0.97")
            loaded = rows.load()
            self.assertEqual([r["extra"] for r in loaded], [{}, {"peak_g": 0.97}])

    def test_the_brakes_table_gives_means_and_the_worst_ride(self):
        rows = [parse(line("brake60", "arcade", 0, s, False, 0.91)
                      + f",distance_m={d};rear_lift_mm={lift};rear_on_road={on}")
                for s, (d, lift, on) in enumerate([(15.0, 0.2, 1.0), (16.0, 0.8, 0.9)])]
        table = report.measures_table(rows, "brake60")
        self.assertIn("| arcade | 0 | 15.50 (16.00) |", table)
        self.assertIn("0.50 (0.80)", table)
        self.assertIn("0.95 (0.90)", table, "the least the rear touched is the worst")
        self.assertEqual(report.measures_table(rows, "turn"), "")

    def test_a_bend_gives_the_lean_and_radii_with_their_range(self):
        rows = [parse(line("bend45-h22", "arcade", 0, s, False, 0.1)
                      + f",lean_deg={lean};radius_m={r};radius_eq43_m=24.5")
                for s, (lean, r) in enumerate([(44.0, 28.0), (46.0, 29.0)])]
        rows.append(parse(line("bend45-h22", "optimizer", 10, 0, True, 9.0)
                          + ",lean_deg=70;radius_m=5;radius_eq43_m=3"))
        table = report.measures_table(rows, "bend45-h22")
        self.assertIn("mean (least to most)", table)
        self.assertIn("| arcade | 0 | 45.00 (44.00 to 46.00) | 28.50 (28.00 to 29.00) | "
                      "24.50 (24.50 to 24.50) |", table)
        self.assertNotIn("optimizer", table, "a ride that fell measures nothing")
        camber = [parse(line("camber8-left", "combined", 5, 0, False, 6.3)
                        + ",stood_downhill_deg=2.9;on_a_foot=1")]
        self.assertIn("| combined | 5 | 2.90 (2.90 to 2.90) | 1.00 (1.00 to 1.00) |",
                      report.measures_table(camber, "camber8-left"))


class ReportTest(unittest.TestCase):
    def test_the_table_pairs_each_planner_with_combined_at_its_n(self):
        rows = [parse(line("push", "combined", 5, s, False, m))
                for s, m in enumerate([4.0, 6.0, 5.0])]
        rows += [parse(line("push", "sampling", 5, s, s == 2, m))
                 for s, m in enumerate([10.0, 12.0, 80.0])]
        table = report.scenario_table(rows, "push")
        self.assertIn("| combined | 5 | 3 | 0 | 5.00 (2.52 to 7.48) | – | 9.5 ms |", table)
        # Seeds 0 and 1 both stayed up: differences 6 and 6, so the interval is a point.
        self.assertIn("| sampling | 5 | 3 | 1 | 11.00 (-1.71 to 23.71) | 6.00 (6.00 to 6.00) |",
                      table)

    def test_a_low_side_is_counted_over_the_rides_that_fell(self):
        rows = [parse(line("lowside-wet", "arcade", 0, s, True, m))
                for s, m in enumerate([1.0, 1.0, 0.0])]
        table = report.scenario_table(rows, "lowside-wet")
        self.assertIn("| arcade | 0 | 3 | 3 | 0.67 (", table)
        self.assertIn(", every ride |", table)

    def test_the_report_and_chart_are_written(self):
        rows = [parse(line(sc, c, n, s, False, 1.0 + s + n))
                for sc in ("turn", "walk") for c in ("combined", "mppi") for n in (5, 10)
                for s in range(3)]
        with tempfile.TemporaryDirectory() as tmp:
            report.write_report(rows, Path(tmp))
            text = (Path(tmp) / "scenarios.md").read_text()
            self.assertIn("24 rides, exact physics", text)
            self.assertIn("speed held at walking pace", text)
            self.assertGreater((Path(tmp) / "scenarios.png").stat().st_size, 10_000)



class BrakeCurveTest(unittest.TestCase):
    def test_a_steady_one_g_stop_sums_to_its_distance(self):
        from planner_scenarios.brake_curve import G, summary
        # 10 m/s braked at 1 g in steps of 0.1 s: 1.0194 s, 5.097 m; the rows' times are
        # rounded to the millisecond as the example prints them.
        dt, v, rows = 0.1, 10.0, []
        for step in range(1, 12):
            nxt = max(v - G * dt, 0.0)
            rows.append({"t": f"{step * dt:.3f}", "speed_kmh": f"{nxt * 3.6:.2f}",
                         "decel_g": f"{(v - nxt) / dt / G:.3f}", "pitch_deg": "-2.0",
                         "rear_lift_mm": "0.1", "fell": "false"})
            v = nxt
            if v == 0.0:
                break
        s = summary(rows)
        self.assertAlmostEqual(s["from_kmh"], 36.0, places=1)
        self.assertAlmostEqual(s["distance_m"], 5.1, delta=0.2)
        self.assertAlmostEqual(s["mean_g"], 1.0, delta=0.05)
        self.assertEqual(s["nose_down_deg"], 2.0)
        self.assertFalse(s["fell"])


class CompareTest(unittest.TestCase):
    def test_both_bikes_side_by_side_over_the_seeds_both_rode(self):
        from planner_scenarios.compare import side_by_side
        first = [parse(line("stop40", "arcade", 0, s, False, m))
                 for s, m in enumerate([10.0, 11.0, 12.0])]
        second = [parse(line("stop40", "arcade", 0, s, s == 1, m))
                  for s, m in enumerate([7.0, 70.0, 8.0, 9.0])]
        second += [parse(line("turn", "arcade", 0, 0, False, 1.0))]
        table = side_by_side(first, second, ("street_350", "street_390"))
        self.assertIn("| arcade | 0 | 3 | 0 | 1 |", table, "seed 3 is on one side only")
        self.assertIn("−3.50", table.replace("-", "−"), "paired over seeds 0 and 2: 7−10, 8−12")
        self.assertNotIn("15° turn", table, "a scenario on one side only is left out")

    def test_a_real_difference_is_flagged_after_holm_and_noise_is_not(self):
        from planner_scenarios.compare import pairings, side_by_side
        noise = [0.3, -0.2, 0.1, -0.4, 0.25, -0.05, 0.15, -0.1, 0.2, -0.3]
        first = [parse(line("slalom", "combined", 5, s, False, 2.0 + d))
                 for s, d in enumerate(noise)]
        first += [parse(line("walk", "combined", 5, s, False, 8.0 + d))
                  for s, d in enumerate(noise)]
        # The slalom's error doubles on every seed; the walk's moves by noise alone.
        second = [parse(line("slalom", "combined", 5, s, False, 4.0 + d * 0.9))
                  for s, d in enumerate(noise)]
        second += [parse(line("walk", "combined", 5, s, False, 8.0 + noise[::-1][s]))
                   for s in range(len(noise))]
        slalom, walk = pairings(first, second)
        self.assertLess(slalom.metric_p, 1e-6)
        self.assertGreater(walk.metric_p, 0.5)
        self.assertEqual((slalom.falls_p, walk.falls_p), (1.0, 1.0), "nobody fell")
        self.assertAlmostEqual(slalom.planning_ratio, 1.0)
        table = side_by_side(first, second, ("1.2 s", "0.6 s"))
        self.assertIn("1 of 4 paired tests", table)
        self.assertIn("planning 0.6 s / 1.2 s", table)

    def test_falls_pair_by_seed_and_a_constant_shift_still_counts(self):
        from planner_scenarios.compare import pairings
        first = [parse(line("push", "guided", 5, s, False, 10.0)) for s in range(12)]
        second = [parse(line("push", "guided", 5, s, s < 10, 11.0)) for s in range(12)]
        (push,) = pairings(first, second)
        self.assertEqual(push.falls, (0, 10))
        self.assertLess(push.falls_p, 0.01, "10 discordant pairs all one way")
        self.assertEqual(push.metric_p, 0.0, "the two seeds up differ by 1 each")
        same = pairings(first, first)[0]
        self.assertEqual((same.falls_p, same.metric_p), (1.0, 1.0))


class SettingsTest(unittest.TestCase):
    """A folder's rows are ridden with one set of planner settings (`--set`)."""

    def _settings(self, out, *assignments, command="run"):
        import argparse

        from planner_scenarios.cli import _settings
        args = argparse.Namespace(command=command, set=list(assignments))
        return _settings(args, out, ScenarioRows(out / "scenarios.csv"))

    def test_a_folder_keeps_its_settings_and_refuses_rows_of_others(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            self.assertEqual(self._settings(out, "horizon=0.6"), {"horizon": "0.6"})
            self.assertIn("0.6", (out / "settings.json").read_text())
            self.assertEqual(self._settings(out, "horizon=0.6"), {"horizon": "0.6"}, "resumes")
            self.assertEqual(self._settings(out, command="report"), {"horizon": "0.6"})
            with self.assertRaisesRegex(ValueError, "its own --out"):
                self._settings(out, "horizon=0.4")
            with self.assertRaisesRegex(ValueError, "its own --out"):
                self._settings(out)
            with self.assertRaisesRegex(ValueError, "NAME=VALUE"):
                self._settings(Path(tmp) / "x", "horizon")

    def test_rows_at_the_defaults_take_no_settings_after_them(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp)
            ScenarioRows(out / "scenarios.csv").append(line("turn", "arcade", 0, 0, False, 1))
            self.assertEqual(self._settings(out), {})
            with self.assertRaisesRegex(ValueError, "the defaults"):
                self._settings(out, "horizon=0.6")

    def test_the_report_names_the_settings(self):
        rows = [parse(line("turn", "combined", 5, s, False, 1.0)) for s in range(3)]
        with tempfile.TemporaryDirectory() as tmp:
            report.write_report(rows, Path(tmp), settings={"horizon": "0.6"})
            self.assertIn("planned with horizon = 0.6", (Path(tmp) / "scenarios.md").read_text())


if __name__ == "__main__":
    unittest.main()
