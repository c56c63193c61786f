#!/usr/bin/env python3
"""The report's checks (tests/tools/report.sh calls it; only the Python 3 standard library is used):

  * "the lesson says / measured": a lesson marks a figure the report re-measures with an HTML comment right
    before the number, invisible on the rendered page:

        at 256 samples they are <!--report:ch01.stratified_gain_256 ±30%-->3.8× more accurate

    `ch01.stratified_gain_256` names one of the measurements in MEASURES below (how the report computes it
    from its CSV files or a program's output), `±30%` is the tolerance (relative with %, else absolute: `±0.005`), and the number
    right after the comment is what the lesson says. The report reads the number from the lesson, so when the
    lesson changes the report follows.
  * time to an error, never extrapolated: time_to_reach interpolates a measured (seconds, error) curve in
    log–log between the two points around the target; below its last error the page says "not reached in the
    measured range", above its first, that the first point is already below it.
  * a reference too noisy for the error it measures: its own RMSE (from its two halves, or from its samples)
    must be under a third of the error measured against it (then it adds at most 5% to that error:
    √(1 + 1/9) = 1.054), else the row is flagged.

  report_checks.py lesson-table SOURCE_DIR OUT_DIR CHAPTER    the Markdown table of chapter CHAPTER's markers
  report_checks.py csv FILE.csv                               a CSV as a Markdown table, numbers rounded
  report_checks.py console FILE.txt [REFERENCE_SPP]           a program's console output as tables and text
  report_checks.py ch06-efficiency CSV REFERENCE.pfm          chapter 06's efficiency table with the noise flag
  report_checks.py ch07-depth CSV REFERENCE_SPP               chapter 07's depth table with the noise flag
  report_checks.py ch08-time CSV REFERENCE.pfm                chapter 08's time to the same RMSE, interpolated
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
BEFORE_FIRST = "not in the measured range (its first point, {:.3g} s, is already below)"

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


def console_cell(out: Path, file: str, row: str, column: str) -> float:
    """The number in `column` of the row labelled `row` of a table in a program's console output out/file."""
    header: list[str] = []
    for line in console_to_markdown((out / file).read_text(encoding="utf-8")).splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")] if line.startswith("|") else []
        if cells and not header:
            header = cells
        elif not cells:
            header = []
        elif cells[0] == row and column in header:
            return float(cells[header.index(column)])
    raise LookupError(f"{file}: no row {row!r} with a column {column!r}")


def slope(out: Path, file: str, strategy: str) -> float:
    """Least-squares slope of log RMSE against log spp of one strategy in chapter 06's convergence CSV."""
    rows = [r for r in read_csv(out / file) if r["strategy"] == strategy]
    xs = [math.log(float(r["spp"])) for r in rows]
    ys = [math.log(float(r["rmse"])) for r in rows]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


# Each measurement: what it is (a column of the page) and how to compute it from the CSV files and the programs'
# console output in OUT_DIR.
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
                                          light_sampling="hit")),
    "ch05.depth8_bias": ("bias of depth 8 (lights: hit)",
                         lambda o: cell(o, "ch05_termination.csv", "bias", rule="depth", max_depth="8",
                                        light_sampling="hit")),
    "ch06.uniform_slope": ("slope of log RMSE against log spp, uniform",
                           lambda o: slope(o, "ch06_convergence.csv", "uniform")),
    "ch07.schlick_max_error": ("largest error of Schlick's R, entering",
                               lambda o: console_cell(o, "ch07_fresnel.txt", "1.5", "max error")),
    "ch07.depth1_bias": ("mean error (bias) at max depth 1",
                         lambda o: cell(o, "ch07_depth.csv", "mean_error", max_depth="1")),
    "ch08.bounce_fraction": ("fraction of connected light paths contributing through a bounce",
                             lambda o: console_cell(o, "ch08_forward.txt", "connect, bounces only", "fraction")),
    "ch08.camera_rays_per_path": ("camera rays (splats) per connected light path",
                                  lambda o: console_cell(o, "ch08_forward.txt", "connect (pinhole)",
                                                         "camera rays/path")),
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


# ------------------------------------------------------------------ the programs' output as tables and text

NUMERIC = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?[%*]?$")
WORD_CELLS = {"on", "off", "yes", "no", "-", "–"}


def rounded_number(text: str) -> str:
    """A number to four significant digits (whole numbers as they are, a leading + and a trailing % or * kept);
    other text as it is."""
    if not NUMERIC.match(text) or re.match(r"^[+-]?\d+[%*]?$", text):
        return text
    suffix = text[-1] if text[-1] in "%*" else ""
    value = float(text.rstrip("%*"))
    out = f"{value:.4g}"
    if text.startswith("+") and value >= 0:
        out = "+" + out
    return out + suffix


def rounded_text(line: str) -> str:
    """Every number of a sentence to four significant digits."""
    return re.sub(r"(?<![\w.])[+-]?\d+\.\d+(?:[eE][+-]?\d+)?(?![\w.])", lambda m: rounded_number(m.group()), line)


def split_row(line: str) -> Optional[tuple[str, list[tuple[str, int]]]]:
    """A table row of a program's output: a label (words, maybe none) then values (numbers, on/off), each
    value with the column where it ends; None for any other line (a sentence, a "name: value" line)."""
    tokens = [(m.group(), m.start(), m.end()) for m in re.finditer(r"\S+", line)]
    first_value = len(tokens)
    while first_value > 0 and (NUMERIC.match(tokens[first_value - 1][0])
                               or tokens[first_value - 1][0].lower() in WORD_CELLS):
        first_value -= 1
    values = tokens[first_value:]
    label = line[:values[0][1]].strip() if values else ""
    if not values or not any(NUMERIC.match(v) for v, _, _ in values) or label.endswith(":"):
        return None
    if not label and len(values) < 2:
        return None
    return label, [(v, e - 1 if v.endswith("*") else e) for v, _, e in values]  # a * overflows its column


def label_columns(label: str, columns: int = 0) -> list[str]:
    """A row's label as its columns: pieces two or more spaces apart (at most `columns`, when given)."""
    parts = re.split(r"\s{2,}", label.strip(), maxsplit=columns - 1 if columns else 0)
    return parts + [""] * (columns - len(parts)) if columns else parts


def split_header(header: str, row: tuple[str, list[tuple[str, int]]]) -> Optional[list[str]]:
    """A header line over a row cut at the row's value columns' ends (printf right-aligns them); when the row
    has a label (one column, or several two or more spaces apart: "1.5000   entering"), the first piece holds
    their names and the first value's, two or more spaces apart. None when a name comes out empty."""
    label, values = row
    cells, start = [], 0
    for _, end in values:
        while 0 < end < len(header) and not header[end - 1].isspace() and not header[end].isspace():
            end += 1  # a name wider than its column's numbers, or a left-aligned value: cut after the word
        cells.append(header[start:end].strip())
        start = end
    if header[start:].strip():
        return None
    if label:
        columns = len(label_columns(label))
        parts = re.split(r"\s{2,}", cells[0], maxsplit=columns)
        if len(parts) != columns + 1:
            return None
        cells = parts + cells[1:]
    return cells if all(cells) else None


def markdown_table(header: list[str], rows: list[list[str]]) -> list[str]:
    align = ["---:" if all(NUMERIC.match(r[i]) or r[i] in ("", "—", NOT_REACHED) for r in rows) else "---"
             for i in range(len(header))]
    return (["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
            + ["| " + " | ".join(rounded_number(c) for c in r) + " |" for r in rows])


def reference_noise_from_tables(tables: list[tuple[list[str], list[list[str]]]],
                                reference_spp: int) -> tuple[Optional[float], Optional[float]]:
    """A reference's own RMSE and relative MSE estimated from every row of the tables that has an spp, as the
    smallest of RMSE · √(spp / reference spp) and relative MSE · spp / reference spp (noise falls like 1/√spp
    in RMSE, 1/spp in MSE; each row gives an upper bound, bias and the reference's noise included)."""
    rmse, relative = [], []
    for header, rows in tables:
        if "spp" not in header:
            continue
        for r in rows:
            cells = dict(zip(header, r))
            try:
                spp = float(cells["spp"])
                if "RMSE" in cells:
                    rmse.append(float(cells["RMSE"]) * math.sqrt(spp / reference_spp))
                if "rel. MSE" in cells:
                    relative.append(float(cells["rel. MSE"]) * spp / reference_spp)
            except ValueError:
                continue
    return (min(rmse) if rmse else None), (min(relative) if relative else None)


def console_to_markdown(text: str, reference_spp: Optional[int] = None) -> str:
    """A program's console output as Markdown: each table it prints (a header line over rows of an optional
    label and numbers right-aligned in columns, as printf's %10s over %10.4f prints them) as a table with named
    columns and rounded numbers; indented "name: value" lines as a two-column table; any other line as a
    sentence, its numbers rounded. A value marked * (extrapolated, chapter 10's equal-error spp past its last
    render) is shown as "not reached in the measured range", and the row's values that follow from it as —.
    With `reference_spp` (the samples of the reference the errors are measured against), each table with an
    RMSE or a relative MSE gets a column saying whether the reference is good enough for it, and a sentence
    after the last table says how noisy the reference is (reference_noise_from_tables)."""
    lines = [line.rstrip() for line in text.splitlines()]
    out: list[str | tuple[list[str], list[list[str]]]] = []
    i = 0
    while i < len(lines):
        line = lines[i]
        if not line.strip():
            out.append("")
            i += 1
            continue
        first = split_row(lines[i + 1]) if i + 1 < len(lines) and split_row(line) is None else None
        parsed = []
        j = i + 1
        while first and j < len(lines):
            row = split_row(lines[j])
            if row is None or bool(row[0]) != bool(first[0]):
                break
            parsed.append(row)
            j += 1
        # The columns end where at least half of the rows have a value end (printf right-aligns them). A row may leave a column empty; a number that ends elsewhere, before the
        # columns, is part of its row's label ("lens radius 16").
        counts: dict[int, int] = {}
        for _, values in parsed:
            for _, end in values:
                counts[end] = counts.get(end, 0) + 1
        ends = sorted(e for e, n in counts.items() if 2 * n >= len(parsed))
        column_of = lambda end: next((k for k, e in enumerate(ends) if e == end), None)  # noqa: E731
        header = split_header(line, (first[0], [("", e) for e in ends])) if parsed and ends else None
        label_count = len(label_columns(first[0])) if first and first[0] else 0
        if header:
            rows = []
            for label, values in parsed:
                by_column = ["" for _ in ends]
                for value, end in values:
                    column = column_of(end)
                    if column is None and not any(by_column):
                        label = (label + " " + value).strip()
                    elif column is not None:
                        by_column[column] = value
                cells = (label_columns(label, label_count) if label_count else []) + by_column
                # A value the program marks * is extrapolated past its measured points: it and what follows
                # from it are not shown.
                starred = next((k for k, c in enumerate(cells) if c.endswith("*")), None)
                if starred is not None:
                    cells = cells[:starred] + [NOT_REACHED] + ["—"] * (len(cells) - starred - 1)
                rows.append(cells)
            out += ["", (header, rows), ""]
            i = j
            continue
        pair = re.compile(r"^\s+[^:(;]+: [^;]+$")  # "  chapter 07: median 0.125 s", no sentence
        if pair.match(line):
            pairs = []
            j = i
            while j < len(lines) and pair.match(lines[j]):
                name, value = lines[j].split(":", 1)
                pairs.append(f"| {name.strip()} | {rounded_text(value.strip())} |")
                j += 1
            out += ["", "| item | measured |", "|---|---|"] + pairs + [""]
            i = j
            continue
        out.append(rounded_text(line.strip()))  # lines of one sentence run on into one paragraph
        i += 1
    tables = [b for b in out if isinstance(b, tuple)]
    own_rmse, own_relative = reference_noise_from_tables(tables, reference_spp) if reference_spp else (None, None)
    flagged = 0
    lines_out: list[str] = []
    for block in out:
        if isinstance(block, str):
            lines_out.append(block)
            continue
        header, rows = block
        own_row = next((r for r in rows if r[0].startswith("reference's own noise")), None)
        if own_row:  # a table that lists the reference's own error per column (chapter 08's regions)
            verdicts = []
            for r in rows:
                pairs = [(float(v), float(o)) for v, o in zip(r[1:], own_row[1:])
                         if NUMERIC.match(v) and NUMERIC.match(o) and "RMSE" in header[r.index(v)]]
                noisy = r is not own_row and any(reference_too_noisy(o, v) for v, o in pairs)
                flagged += noisy
                verdicts.append("" if r is own_row else "⚠ no" if noisy else "yes")
            lines_out += markdown_table(header + ["reference noise ok"], [r + [v] for r, v in zip(rows, verdicts)])
            continue
        column = "RMSE" if "RMSE" in header and own_rmse else "rel. MSE" if "rel. MSE" in header and own_relative else None
        if column:
            k = header.index(column)
            verdicts = []
            for r in rows:
                try:
                    value = float(r[k])
                except ValueError:
                    verdicts.append("—")
                    continue
                # RMSE against RMSE; a relative MSE's square root against the reference's.
                noisy = (reference_too_noisy(own_rmse, value) if column == "RMSE"
                         else reference_too_noisy(math.sqrt(own_relative), math.sqrt(value)))
                flagged += noisy
                verdicts.append("⚠ no" if noisy else "yes")
            header, rows = header + ["reference noise ok"], [r + [v] for r, v in zip(rows, verdicts)]
        lines_out += markdown_table(header, rows)
    if flagged and not (own_rmse or own_relative):
        lines_out += ["", f"**The reference is too noisy for {flagged} of these rows** (marked ⚠: its own RMSE is "
                      "over a third of theirs in a column); render it with more samples to measure them."]
    if own_rmse or own_relative:
        own = (f"RMSE about {own_rmse:.2g}" if own_rmse else "") + (" and " if own_rmse and own_relative else "") + \
              (f"relative MSE about {own_relative:.2g}" if own_relative else "")
        how = f"estimated from its {reference_spp} spp and the renders above: noise falls like 1/√spp"
        lines_out += ["", (f"The reference's own {own} ({how})." + (
            f" **The reference is too noisy for {flagged} of these errors** (marked ⚠: its own error is over a "
            "third of theirs, in RMSE or in the square root of the relative MSE); render it with more samples to "
            "measure them." if flagged else
            " Every error here is at least three times the reference's own: it can measure them."))]
    return re.sub(r"\n{3,}", "\n\n", "\n".join(lines_out)).strip() + "\n"


def csv_to_markdown(csv_file: Path) -> str:
    """A CSV as a Markdown table: its header's names with spaces for underscores, numbers rounded."""
    with csv_file.open(newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return ""
    return "\n".join(markdown_table([h.replace("_", " ") for h in rows[0]], rows[1:])) + "\n"


# -------------------------------------------------------------------------------------- the studies' tables

def noise_note(reference_rmse: float, how: str, flagged: int) -> str:
    sentence = f"The reference's own RMSE is about {reference_rmse:.2g} ({how})."
    if flagged:
        return (sentence + f" **The reference is too noisy for {flagged} of these errors** (marked ⚠: its own"
                f" RMSE is over a third of theirs); render it with more samples to measure them.")
    return sentence + " Every error here is at least three times the reference's own: it can measure them."


def ch06_efficiency(csv_file: Path, reference: Path) -> str:
    """Chapter 06's strategies at their largest spp: the slope of log RMSE against log spp, the error, the
    processor time, the efficiency 1 / (MSE × time) against uniform's, and whether the reference (the mean of
    two halves, `reference` and its _half.pfm) is good enough for that error."""
    rows = read_csv(csv_file)
    if not rows:
        return ""
    own = rmse_of_halves(reference, reference.with_name(reference.stem + "_half.pfm"))
    table = ["| strategy | slope of log RMSE | spp | RMSE | MSE − reference's | processor s | efficiency 1/(MSE·s) |"
             " × uniform | reference noise ok |", "|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    flagged = 0
    last = {r["strategy"]: r for r in rows}  # each strategy's largest spp: its last row
    uniform = last.get("uniform")
    base = 1 / (float(uniform["mse"]) * float(uniform["cpu_seconds"])) if uniform and float(uniform["mse"]) > 0 else 0
    for strategy, r in last.items():
        rmse, mse, cpu = float(r["rmse"]), float(r["mse"]), float(r["cpu_seconds"])
        noisy = reference_too_noisy(own, rmse)
        flagged += noisy
        efficiency = 1 / (mse * cpu) if mse > 0 and cpu > 0 else 0
        table.append(f"| {strategy} | {figure_text(slope(csv_file.parent, csv_file.name, strategy))} | {r['spp']} | {rmse:.3g} | "
                     f"{mse:.3g} | {cpu:.3g} | {efficiency:.4g} | "
                     f"{f'{efficiency / base:.3g}' if base > 0 and efficiency > 0 else '—'} | "
                     f"{'⚠ no' if noisy else 'yes'} |")
    return ("\n".join(table) + "\n\n" + noise_note(own, f"from its two halves, {reference.name}", flagged) + "\n")


def ch07_depth(csv_file: Path, reference_spp: int) -> str:
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


def ch08_time(csv_file: Path, reference: Optional[Path]) -> str:
    """Chapter 08's time to the same RMSE: the light tracer's curve, interpolated only; and whether chapter
    06's reference (`reference`, the mean of two halves) is good enough for each error."""
    rows = read_csv(csv_file)
    forward = [(float(r["seconds"]), float(r["rmse"])) for r in rows if r["tracer"].startswith("forward")]
    reverse = [r for r in rows if r["tracer"].startswith("reverse")]
    own = rmse_of_halves(reference, reference.with_name(reference.stem + "_half.pfm")) if reference else None
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
            if t is not None:
                same = f"{t:.3g}"
            elif forward and rmse > forward[0][1]:  # reached before the first point: when, it does not say
                same = BEFORE_FIRST.format(forward[0][0])
            else:
                same = NOT_REACHED
            ratio = "" if t is None else f"{t / seconds:.2g}"
        table.append(f"| {r['tracer']} | {r['spp']} | {rmse:.3g} | {seconds:.3g} | {same} | {ratio} | "
                     f"{'—' if own is None else '⚠ no' if noisy else 'yes'} |")
    text = "\n".join(table) + "\n"
    if own is not None:
        text += "\n" + noise_note(own, f"from its two halves, {reference.name}", flagged) + "\n"
    return text


def main(argv: list[str]) -> int:
    command, arguments = (argv[0], argv[1:]) if argv else ("", [])
    if command == "lesson-table" and len(arguments) == 3:
        sys.stdout.write(lesson_table(Path(arguments[0]), Path(arguments[1]), arguments[2]))
    elif command == "console" and len(arguments) in (1, 2):
        sys.stdout.write(console_to_markdown(Path(arguments[0]).read_text(encoding="utf-8"),
                                             int(arguments[1]) if len(arguments) == 2 else None))
    elif command == "csv" and len(arguments) == 1:
        sys.stdout.write(csv_to_markdown(Path(arguments[0])))
    elif command == "ch06-efficiency" and len(arguments) == 2:
        sys.stdout.write(ch06_efficiency(Path(arguments[0]), Path(arguments[1])))
    elif command == "ch07-depth" and len(arguments) == 2:
        sys.stdout.write(ch07_depth(Path(arguments[0]), int(arguments[1])))
    elif command == "ch08-time" and len(arguments) == 2:
        reference = Path(arguments[1])
        sys.stdout.write(ch08_time(Path(arguments[0]), reference if reference.is_file() else None))
    else:
        print(__doc__, file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
