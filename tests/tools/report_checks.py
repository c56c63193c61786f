#!/usr/bin/env python3
"""The report's checks (tests/tools/report.sh calls it; only the Python 3 standard library is used):

  * "the lesson says / measured": a lesson marks a figure the report re-measures with an HTML comment right
    before the number, invisible on the rendered page:

        at 256 samples they are <!--report:ch01.stratified_gain_256 ±30%-->3.8× more accurate

    `ch01.stratified_gain_256` names one of the measurements in MEASURES below (how the report computes it
    from its CSV files), `±30%` is the tolerance (relative with %, else absolute: `±0.005`), and the number
    right after the comment is what the lesson says. The report reads the number from the lesson, so when the
    lesson changes the report follows.
  * time to an error, never extrapolated: time_to_reach interpolates a measured (seconds, error) curve in
    log–log between the two points around the target and says "not reached in the measured range" outside it.
  * a reference too noisy for the error it measures: its own RMSE (from its two halves, or from its samples)
    must be under a third of the error measured against it (then it adds at most 5% to that error:
    √(1 + 1/9) = 1.054), else the row is flagged.

  report_checks.py lesson-table SOURCE_DIR OUT_DIR CHAPTER    the Markdown table of chapter CHAPTER's markers
  report_checks.py ch06-reference OUT_DIR CSV                 the reference-noise table of chapter 06's study
  report_checks.py ch07-depth OUT_DIR CSV REFERENCE_SPP       chapter 07's depth table with the noise flag
  report_checks.py ch08-time OUT_DIR CSV                      chapter 08's time to the same RMSE, interpolated
"""

from __future__ import annotations

import csv
import math
import re
import struct
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Optional

# A reference whose own RMSE is above the measured RMSE divided by this is too noisy for it.
NOISY_REFERENCE_RATIO = 3
NOT_REACHED = "not reached in the measured range"

# ------------------------------------------------------------------------------------------ lesson markers

MARKER = re.compile(r"<!--\s*report:(?P<key>[\w.]+)\s+±(?P<tolerance>[0-9.]+)(?P<percent>%?)\s*-->"
                    r"\s*(?P<number>[−+-]?(?:[0-9]{1,3}(?:[ ,\u202f][0-9]{3})+|[0-9]+)(?:\.[0-9]+)?(?:[eE][−+-]?[0-9]+|·10[⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)?)")
SUPERSCRIPT = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


@dataclass
class LessonFigure:
    key: str
    value: float
    tolerance: float
    relative: bool  # tolerance is a fraction of the lesson's value
    text: str       # the number as the lesson writes it
    file: str
    line: int


def parse_number(text: str) -> float:
    """A number as a lesson writes it: U+2212 minus, thin spaces or commas between thousands, 1.5·10⁻⁴."""
    text = text.strip().replace("−", "-").replace(",", "").replace(" ", "").replace("\u202f", "")
    if "·10" in text:
        mantissa, exponent = text.split("·10")
        return float(mantissa) * 10.0 ** int(exponent.translate(SUPERSCRIPT))
    return float(text)


def lesson_figures(markdown: str, file: str = "") -> list[LessonFigure]:
    """Every marked figure of a lesson, in order."""
    figures = []
    for number, line in enumerate(markdown.splitlines(), start=1):
        for m in MARKER.finditer(line):
            tolerance = float(m["tolerance"])
            relative = m["percent"] == "%"
            figures.append(LessonFigure(m["key"], parse_number(m["number"]), tolerance / 100 if relative else tolerance,
                                        relative, m["number"].strip(), file, number))
    return figures


def agrees(figure: LessonFigure, measured: float) -> bool:
    """Within the figure's tolerance of the lesson's value."""
    allowed = figure.tolerance * abs(figure.value) if figure.relative else figure.tolerance
    return abs(measured - figure.value) <= allowed + 1e-12


# ---------------------------------------------------------------------------- time to an error, interpolated

def time_to_reach(points: list[tuple[float, float]], target: float) -> Optional[float]:
    """The time at which a curve of (seconds, error) points, in the order measured, first reaches `target`:
    linear in log error against log time between the two measured points around it. None when the target is
    outside the measured errors (above the first point's error or below every point's): that would need an
    extrapolation."""
    if not points or target <= 0:
        return None
    t0, e0 = points[0]
    if target > e0:
        return None
    if target == e0:
        return t0
    for (ta, ea), (tb, eb) in zip(points, points[1:]):
        if eb <= target <= ea and eb < ea:
            f = (math.log(ea) - math.log(target)) / (math.log(ea) - math.log(eb))
            return math.exp(math.log(ta) + f * (math.log(tb) - math.log(ta)))
    return None


# ---------------------------------------------------------------------------------------- noisy references

def reference_too_noisy(reference_rmse: float, measured_rmse: float) -> bool:
    """True when the reference's own RMSE is not well below (a third of) the RMSE measured against it."""
    return reference_rmse > measured_rmse / NOISY_REFERENCE_RATIO


def rmse_from_samples(measured_rmse: float, spp: int, reference_spp: int) -> float:
    """A reference's own RMSE estimated from a noise-dominated render of `spp` samples whose RMSE against it
    is `measured_rmse`: noise falls like 1/√spp, so the reference's is measured_rmse · √(spp / reference_spp)
    (an upper bound: the measured RMSE includes the reference's noise and any bias)."""
    return measured_rmse * math.sqrt(spp / reference_spp)


def read_pfm(path: Path) -> tuple[int, int, list[float]]:
    """Width, height and the float samples of a PFM (colour "PF" or grey "Pf")."""
    data = path.read_bytes()
    fields: list[bytes] = []
    at = 0
    while len(fields) < 4:  # magic, width, height, scale: whitespace-separated
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[at:end])
        at = end
    at += 1  # the single whitespace character after the scale
    magic, width, height, scale = fields[0], int(fields[1]), int(fields[2]), float(fields[3])
    channels = 3 if magic == b"PF" else 1
    count = width * height * channels
    values = struct.unpack(("<" if scale < 0 else ">") + f"{count}f", data[at:at + 4 * count])
    return width, height, list(values)


def rmse_of_halves(reference: Path, half: Path) -> float:
    """The own RMSE of a reference that is the mean of two independent renders A and B, from it and A: since
    B = 2 ref − A, (A − B)² / 4 = (A − ref)², and the reference's MSE is mean((A − B)²) / 4 = mean((A − ref)²)."""
    _, _, r = read_pfm(reference)
    _, _, a = read_pfm(half)
    if len(r) != len(a):
        raise ValueError(f"{reference} and {half} differ in size")
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, r)) / len(r))


# ---------------------------------------------------------------------------------- what the report measures

def read_csv(path: Path) -> list[dict[str, str]]:
    with path.open(newline="") as f:
        return list(csv.DictReader(f))


def cell(out: Path, file: str, column: str, **where: str) -> float:
    """The number in `column` of the one row of out/file whose columns equal `where`."""
    rows = [r for r in read_csv(out / file) if all(r[k] == v for k, v in where.items())]
    if len(rows) != 1:
        raise LookupError(f"{file}: {len(rows)} rows match {where}")
    return float(rows[0][column])


def slope(out: Path, file: str, strategy: str) -> float:
    """Least-squares slope of log RMSE against log spp of one strategy in chapter 06's convergence CSV."""
    rows = [r for r in read_csv(out / file) if r["strategy"] == strategy]
    xs = [math.log(float(r["spp"])) for r in rows]
    ys = [math.log(float(r["rmse"])) for r in rows]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


# Each measurement: what it is (a column of the page) and how to compute it from the CSV files in OUT_DIR.
MEASURES: dict[str, tuple[str, Callable[[Path], float]]] = {
    "ch01.uniform_256": ("edge RMSE, uniform jitter, 256 spp",
                         lambda o: cell(o, "ch01_antialiasing.csv", "edge_rmse", sampler="uniform", spp="256")),
    "ch01.stratified_gain_256": ("uniform over stratified edge RMSE at 256 spp",
                                 lambda o: cell(o, "ch01_antialiasing.csv", "edge_rmse", sampler="uniform", spp="256")
                                 / cell(o, "ch01_antialiasing.csv", "edge_rmse", sampler="stratified", spp="256")),
    "ch02.moller_leaks": ("leak probe rays escaping Möller–Trumbore",
                          lambda o: cell(o, "ch02_triangle_tests.csv", "leak_probe_escaped", method="bvh",
                                         triangle_test="moller")),
    "ch02.watertight_leaks": ("leak probe rays escaping the watertight test",
                              lambda o: cell(o, "ch02_triangle_tests.csv", "leak_probe_escaped", method="bvh",
                                             triangle_test="watertight")),
    "ch04.independent_256": ("RMSE, 256 independent light samples",
                             lambda o: cell(o, "ch04_shadow_samples.csv", "rmse", sampler="independent",
                                            shadow_samples="256")),
    "ch04.stratified_gain_256": ("independent over stratified RMSE at 256 samples",
                                 lambda o: cell(o, "ch04_shadow_samples.csv", "rmse", sampler="independent",
                                                shadow_samples="256")
                                 / cell(o, "ch04_shadow_samples.csv", "rmse", sampler="stratified",
                                        shadow_samples="256")),
    "ch05.roulette_rays": ("rays per path, Russian roulette (lights: hit)",
                           lambda o: cell(o, "ch05_termination.csv", "rays_per_path", rule="roulette",
                                          lights="hit")),
    "ch05.depth8_bias": ("bias of depth 8 (lights: hit)",
                         lambda o: cell(o, "ch05_termination.csv", "bias", rule="depth", value="8", lights="hit")),
    "ch06.uniform_slope": ("slope of log RMSE against log spp, uniform",
                           lambda o: slope(o, "ch06_convergence.csv", "uniform")),
    "ch07.schlick_max_error": ("largest |R_Schlick − R|, entering",
                               lambda o: max(abs(float(r["schlick_entering"]) - float(r["exact_entering"]))
                                             for r in read_csv(o / "ch07_fresnel.csv"))),
    "ch07.depth1_bias": ("mean error (bias) at max depth 1",
                         lambda o: cell(o, "ch07_depth.csv", "mean_error", max_depth="1")),
}


def measured(key: str, out: Path) -> Optional[float]:
    try:
        return MEASURES[key][1](out)
    except (OSError, LookupError, ValueError, ZeroDivisionError):
        return None


def figure_text(value: float) -> str:
    """Four significant digits, U+2212 for minus."""
    return f"{value:.4g}".replace("-", "−")


def lesson_table(source: Path, out: Path, chapter: str) -> str:
    """The Markdown table of a chapter's marked figures against the report's measurements."""
    lessons = sorted(source.glob(f"chapters/{chapter}_*/README.md"))
    figures = [f for lesson in lessons
               for f in lesson_figures(lesson.read_text(encoding="utf-8"), str(lesson.relative_to(source)))]
    if not figures:
        return ""
    rows = ["| figure | lesson (line) | the lesson says | measured | tolerance | agrees |", "|---|---|---:|---:|---:|---|"]
    for f in figures:
        if f.key not in MEASURES:
            raise SystemExit(f"{f.file}:{f.line}: report:{f.key}: no such measurement in report_checks.py")
        value = measured(f.key, out)
        tolerance = f"±{f.tolerance * 100:g}%" if f.relative else f"±{f.tolerance:g}"
        verdict = "not measured" if value is None else "yes" if agrees(f, value) else "**no**"
        rows.append(f"| {MEASURES[f.key][0]} | {Path(f.file).parent.name} ({f.line}) | {f.text} | "
                    f"{'—' if value is None else figure_text(value)} | {tolerance} | {verdict} |")
    return "\n".join(rows) + "\n"


# -------------------------------------------------------------------------------------- the studies' tables

def noise_note(reference_rmse: float, how: str, flagged: int) -> str:
    sentence = f"The reference's own RMSE is about {reference_rmse:.2g} ({how})."
    if flagged:
        return (sentence + f" **The reference is too noisy for {flagged} of these errors** (marked ⚠: its own"
                f" RMSE is over a third of theirs); render it with more samples to measure them.")
    return sentence + " Every error here is at least three times the reference's own: it can measure them."


def ch06_reference(out: Path, csv_file: Path) -> str:
    """Chapter 06's reference noise against the smallest error of each strategy."""
    references = sorted((out / "references").glob("ch06_reference_*spp.pfm"))
    rows = read_csv(csv_file)
    if not references or not rows:
        return ""
    reference = references[0]
    own = rmse_of_halves(reference, reference.with_name(reference.stem + "_half.pfm"))
    table = ["| strategy | largest spp | RMSE there | reference noise ok |", "|---|---:|---:|---|"]
    flagged = 0
    for strategy in dict.fromkeys(r["strategy"] for r in rows):
        last = [r for r in rows if r["strategy"] == strategy][-1]
        rmse = float(last["rmse"])
        noisy = reference_too_noisy(own, rmse)
        flagged += noisy
        table.append(f"| {strategy} | {last['spp']} | {rmse:.3g} | {'⚠ no' if noisy else 'yes'} |")
    return noise_note(own, f"from its two halves, {reference.name}", flagged) + "\n\n" + "\n".join(table) + "\n"


def ch07_depth(out: Path, csv_file: Path, reference_spp: int) -> str:
    rows = read_csv(csv_file)
    if not rows:
        return ""
    deepest = max(rows, key=lambda r: int(r["max_depth"]))
    own = rmse_from_samples(float(deepest["rmse"]), int(deepest["spp"]), reference_spp)
    table = ["| max depth | RMSE | relative MSE | mean error (bias) | time (s) | rays | reference noise ok |",
             "|---:|---:|---:|---:|---:|---:|---|"]
    flagged = 0
    for r in rows:
        noisy = reference_too_noisy(own, float(r["rmse"]))
        flagged += noisy
        table.append(f"| {r['max_depth']} | {float(r['rmse']):.3g} | {float(r['relative_mse']):.3g} | "
                     f"{figure_text(float(r['mean_error']))} | {float(r['seconds']):.3g} | {int(r['rays']):,} | "
                     f"{'⚠ no' if noisy else 'yes'} |")
    how = (f"estimated from its {reference_spp} spp and the {deepest['spp']}-spp render at depth "
           f"{deepest['max_depth']}: RMSE · √({deepest['spp']}/{reference_spp})")
    return "\n".join(table) + "\n\n" + noise_note(own, how, flagged) + "\n"


def ch08_time(out: Path, csv_file: Path) -> str:
    """Chapter 08's time to the same RMSE: the light tracer's curve, interpolated only."""
    rows = read_csv(csv_file)
    forward = [(float(r["seconds"]), float(r["rmse"])) for r in rows if r["tracer"].startswith("forward")]
    reverse = [r for r in rows if r["tracer"].startswith("reverse")]
    references = sorted((out / "references").glob("ch06_reference_*spp.pfm"))
    own = (rmse_of_halves(references[0], references[0].with_name(references[0].stem + "_half.pfm"))
           if references else None)
    table = ["| tracer | spp | RMSE | time (s) | light tracer to the same RMSE (s) | forward / reverse | "
             "reference noise ok |", "|---|---:|---:|---:|---:|---:|---|"]
    flagged = 0
    for r in rows:
        rmse, seconds = float(r["rmse"]), float(r["seconds"])
        noisy = own is not None and reference_too_noisy(own, rmse)
        flagged += noisy
        same, ratio = "", ""
        if r in reverse:
            t = time_to_reach(forward, rmse)
            same = NOT_REACHED if t is None else f"{t:.3g}"
            ratio = "" if t is None else f"{t / seconds:.2g}"
        table.append(f"| {r['tracer']} | {r['spp']} | {rmse:.3g} | {seconds:.3g} | {same} | {ratio} | "
                     f"{'—' if own is None else '⚠ no' if noisy else 'yes'} |")
    text = "\n".join(table) + "\n"
    if own is not None:
        text += "\n" + noise_note(own, f"from its two halves, {references[0].name}", flagged) + "\n"
    return text


def main(argv: list[str]) -> int:
    if len(argv) == 4 and argv[0] == "lesson-table":
        sys.stdout.write(lesson_table(Path(argv[1]), Path(argv[2]), argv[3]))
    elif len(argv) == 3 and argv[0] == "ch06-reference":
        sys.stdout.write(ch06_reference(Path(argv[1]), Path(argv[2])))
    elif len(argv) == 4 and argv[0] == "ch07-depth":
        sys.stdout.write(ch07_depth(Path(argv[1]), Path(argv[2]), int(argv[3])))
    elif len(argv) == 3 and argv[0] == "ch08-time":
        sys.stdout.write(ch08_time(Path(argv[1]), Path(argv[2])))
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
