#!/usr/bin/env python3
"""The report's checks on small inputs (ctest -L tools): the lesson markers, time to an error without
extrapolation, the noisy-reference rule, and a reference's own RMSE from its two halves."""

import math
import struct
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import report_checks as rc  # noqa: E402


class LessonMarkers(unittest.TestCase):
    def test_figures_are_read_from_the_text(self):
        text = ("they are <!--report:ch01.stratified_gain_256 ±30%-->3.8× more accurate\n"
                "no marker 0.5 here\n"
                "bias <!--report:ch07.depth1_bias ±0.005-->−0.0416 and <!--report:ch02.moller_leaks ±0-->1 453 rays,"
                " a fraction of <!-- report:ch04.independent_256 ±10% --> 1.5·10⁻⁴")
        figures = rc.lesson_figures(text, "lesson.md")
        self.assertEqual([f.key for f in figures],
                         ["ch01.stratified_gain_256", "ch07.depth1_bias", "ch02.moller_leaks", "ch04.independent_256"])
        self.assertEqual([f.value for f in figures[:3]], [3.8, -0.0416, 1453.0])
        self.assertAlmostEqual(figures[3].value, 1.5e-4, places=12)
        self.assertEqual([f.line for f in figures], [1, 3, 3, 3])
        self.assertEqual((figures[0].tolerance, figures[0].relative), (0.3, True))
        self.assertEqual((figures[1].tolerance, figures[1].relative), (0.005, False))
        self.assertEqual(figures[0].text, "3.8")

    def test_tolerance(self):
        relative = rc.lesson_figures("<!--report:k ±10%-->2.0")[0]
        self.assertTrue(rc.agrees(relative, 2.2))
        self.assertTrue(rc.agrees(relative, 1.8))
        self.assertFalse(rc.agrees(relative, 2.21))
        absolute = rc.lesson_figures("<!--report:k ±0.01-->−0.04")[0]
        self.assertTrue(rc.agrees(absolute, -0.049))
        self.assertFalse(rc.agrees(absolute, -0.0511))
        exact = rc.lesson_figures("<!--report:k ±0-->453")[0]
        self.assertTrue(rc.agrees(exact, 453))
        self.assertFalse(rc.agrees(exact, 454))

    def test_every_marker_in_the_lessons_names_a_measurement(self):
        source = Path(__file__).resolve().parents[2]
        lessons = sorted(source.glob("chapters/*/README.md"))
        figures = [f for p in lessons for f in rc.lesson_figures(p.read_text(encoding="utf-8"), str(p))]
        self.assertGreater(len(figures), 0)
        for f in figures:
            self.assertIn(f.key, rc.MEASURES, f"{f.file}:{f.line}")


class TimeToReach(unittest.TestCase):
    curve = [(1.0, 0.1), (4.0, 0.05), (16.0, 0.025)]

    def test_interpolates_in_log_log(self):
        self.assertAlmostEqual(rc.time_to_reach(self.curve, 0.05), 4.0)
        # Half way in log error between 0.1 and 0.05 is half way in log time between 1 and 4: 2.
        self.assertAlmostEqual(rc.time_to_reach(self.curve, 0.1 / math.sqrt(2)), 2.0)
        self.assertAlmostEqual(rc.time_to_reach(self.curve, 0.1), 1.0)

    def test_never_extrapolates(self):
        self.assertIsNone(rc.time_to_reach(self.curve, 0.2))    # above the first point: before it
        self.assertIsNone(rc.time_to_reach(self.curve, 0.02))   # below the last point
        self.assertIsNone(rc.time_to_reach([], 0.05))

    def test_first_crossing_of_a_noisy_curve(self):
        noisy = [(1.0, 0.1), (2.0, 0.04), (4.0, 0.06), (8.0, 0.03)]
        self.assertAlmostEqual(rc.time_to_reach(noisy, 0.04), 2.0)


class NoisyReference(unittest.TestCase):
    def test_a_third_of_the_measured_error(self):
        self.assertFalse(rc.reference_too_noisy(0.0099, 0.03))
        self.assertTrue(rc.reference_too_noisy(0.0101, 0.03))
        self.assertTrue(rc.reference_too_noisy(0.02, 0.01))

    def test_from_samples(self):
        # A 16-spp render with RMSE 0.08 against a 1024-spp reference: the reference's noise is 0.08 / 8.
        self.assertAlmostEqual(rc.rmse_from_samples(0.08, 16, 1024), 0.01)

    def test_from_two_halves(self):
        def write(path, values):
            path.write_bytes(b"PF\n2 1\n-1.0\n" + struct.pack("<6f", *values))
        with tempfile.TemporaryDirectory() as d:
            a, b = [1, 2, 3, 4, 5, 6], [1, 2, 3, 4, 5, 10]   # differ in one of six samples, by 4
            mean = [(x + y) / 2 for x, y in zip(a, b)]
            write(Path(d) / "ref.pfm", mean)
            write(Path(d) / "ref_half.pfm", a)
            # mean((A − B)²) / 4 = (16 / 6) / 4
            self.assertAlmostEqual(rc.rmse_of_halves(Path(d) / "ref.pfm", Path(d) / "ref_half.pfm"),
                                   math.sqrt(16 / 6 / 4), places=6)


class ConsoleTables(unittest.TestCase):
    def test_a_printf_table_becomes_named_rounded_columns(self):
        text = ("Title line, 3 runs\n"
                "  denoiser       rel. MSE  plain spp  time s\n"
                "  none         3.0126e-01        16    0.500\n"
                "  atrous       1.8334e-02       267*   5.852\n"
                "  chapter 07: median 0.12534 s\n")
        self.assertEqual(rc.console_to_markdown(text),
                         "Title line, 3 runs\n\n"
                         "| denoiser | rel. MSE | plain spp | time s |\n"
                         "|---|---:|---:|---:|\n"
                         "| none | 0.3013 | 16 | 0.5 |\n"
                         f"| atrous | 0.01833 | {rc.NOT_REACHED} | — |\n\n"
                         "| item | measured |\n|---|---|\n| chapter 07 | median 0.1253 s |\n")

    def test_rounding(self):
        self.assertEqual([rc.rounded_number(t) for t in ["0.123456", "+1.5e-05", "1024", "58.64%", "x"]],
                         ["0.1235", "+1.5e-05", "1024", "58.64%", "x"])


if __name__ == "__main__":
    unittest.main()
