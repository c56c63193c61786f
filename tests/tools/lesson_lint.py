#!/usr/bin/env python3
"""Lessons that teach, not logs: each lesson's word count, and what a lesson should not hold.

  lesson_lint.py [REPOSITORY_ROOT]

Prints each lesson (chapters/*/README.md) with its word count (words as `wc -w` counts them), then one
line per flag: FILE:LINE: what was found. The top README.md is held to MAX_README_WORDS (its first screen is
for students; the detail lives in common/README.md). A lesson is flagged for
  * more than MAX_WORDS words;
  * a date or a clock time (a measurement's date belongs in the chapter's benchmark/README.md);
  * a load average, or a figure tied to one core ("core 0", "on core 1"): a lab notebook's detail;
  * a citation a reader of the repository cannot open ("issue 18", "the course's source text");
  * measurement above MAX_MEASUREMENT_SHARE of its words (the runs belong in the chapter's benchmark/README.md;
    a lesson keeps one table per claim, with its command).

Measurement, plainly: the words (as `wc -w` counts them) of
  * tables of figures: a Markdown table at least half of whose body cells begin with a number;
  * blocks outside tables that quote a measured figure. A block is a paragraph, a list item or a fenced block
    (blocks are separated by blank lines; each list item is one). A measured figure is a number with a unit of
    time (ns, µs, ms, s, min), a rate (/s), a size (KiB, MiB, GiB, KB, MB, GB), a speed-up or ratio (3.2×,
    not a size such as 200×200) or a percentage (not a chosen level, "the 1 % level"). Counts are not
    figures by themselves (a test's 20 000 samples is not a measurement).
The share is measurement words over all the lesson's words; each lesson's line gives it.
Exits 1 if anything is flagged, 0 otherwise. Only the Python 3 standard library is used.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

MAX_WORDS = 5000
MAX_README_WORDS = 3000

MONTH = r"(?:January|February|March|April|May|June|July|August|September|October|November|December)"
FLAGS = [
    ("a date", re.compile(r"\b\d{4}-\d{2}-\d{2}\b|\b\d{1,2} " + MONTH + r"\b|\b" + MONTH + r" \d{1,2}\b")),
    ("a clock time", re.compile(r"\b\d{1,2}:?\d{2} ?UTC\b|\bUTC\b")),
    ("a load average", re.compile(r"\bload(?: average)?(?: of)? ~?\d", re.IGNORECASE)),
    ("a per-core figure", re.compile(r"\bcores? #?\d", re.IGNORECASE)),
    ("a citation a reader cannot open", re.compile(r"\b(?:issue|PR|pull request) #?\d+|\bsource text\b",
                                                   re.IGNORECASE)),
]


MAX_MEASUREMENT_SHARE = 0.15

UNIT = r"(?:ns|µs|ms|s|min|KiB|MiB|GiB|KB|MB|GB)"
MEASURED_FIGURE = re.compile(
    r"(?<![\w.])\d+(?:\.\d+)?(?:e[-−]?\d+)?\s?(?:" + UNIT + r"(?![\w²³])|[\w/]*/s\b)"  # a time, size or rate
    r"|(?<![\d×])\d+(?:\.\d+)?\s?×(?!\s?\d)"  # a speed-up or ratio, not 200×200
    r"|(?<![\w.])\d+(?:\.\d+)?\s?%(?! level)"  # a percentage, not a chosen level
)
NUMBER_CELL = re.compile(r"^[~≈<>±+\-−]?\s*\d")


def blocks(text: str) -> list[list[str]]:
    """The lesson's blocks: paragraphs, list items, tables and fenced blocks, each a list of lines."""
    found: list[list[str]] = []
    block: list[str] = []
    fenced = False
    for line in text.splitlines():
        if line.startswith("```"):
            block.append(line)
            if fenced:
                found.append(block)
                block = []
            fenced = not fenced
            continue
        if fenced:
            block.append(line)
        elif not line.strip():
            if block:
                found.append(block)
            block = []
        else:
            starts_item = re.match(r"\s*(?:[-*]|\d+\.) ", line) is not None
            table_changes = bool(block) and line.startswith("|") != block[-1].startswith("|")
            if block and (starts_item or table_changes):
                found.append(block)
                block = []
            block.append(line)
    if block:
        found.append(block)
    return found


def is_table_of_figures(block: list[str]) -> bool:
    if not block[0].startswith("|") or len(block) < 3:
        return False
    cells = [cell.strip(" *`") for row in block[2:] for cell in row.strip().strip("|").split("|")]
    cells = [cell for cell in cells if cell]
    return bool(cells) and 2 * sum(1 for cell in cells if NUMBER_CELL.match(cell)) >= len(cells)


def measurement_words(text: str) -> int:
    """The words of a lesson's tables of figures and of its blocks that quote a measured figure."""
    total = 0
    for block in blocks(text):
        joined = "\n".join(block)
        table = block[0].startswith("|")
        if (table and is_table_of_figures(block)) or (not table and MEASURED_FIGURE.search(joined)):
            total += len(joined.split())
    return total


def lesson_flags(text: str) -> list[tuple[int, str, str]]:
    """(line, what, the matched text) for everything flagged in a lesson's text."""
    found = []
    for number, line in enumerate(text.splitlines(), start=1):
        for what, pattern in FLAGS:
            for m in pattern.finditer(line):
                found.append((number, what, m.group(0)))
    return found


def main(argv: list[str]) -> int:
    root = Path(argv[1]) if len(argv) > 1 else Path(__file__).resolve().parents[2]
    lessons = sorted(root.glob("chapters/*/README.md"))
    if not lessons:
        print(f"lesson_lint: no lessons under {root}/chapters", file=sys.stderr)
        return 2
    failed = False
    for lesson in lessons:
        text = lesson.read_text(encoding="utf-8")
        words = len(text.split())
        name = lesson.relative_to(root)
        over = words > MAX_WORDS
        share = measurement_words(text) / words if words else 0.0
        measured_over = share > MAX_MEASUREMENT_SHARE
        print(f"{words:7d} words  {share:5.1%} measurement  {name}" +
              (f"  (over the budget of {MAX_WORDS} words)" if over else "") +
              (f"  (measurement over {MAX_MEASUREMENT_SHARE:.0%}: move runs to benchmark/README.md)"
               if measured_over else ""))
        for line, what, match in lesson_flags(text):
            print(f"  {name}:{line}: {what}: \"{match}\"")
            failed = True
        failed = failed or over or measured_over
    readme = root / "README.md"
    if readme.is_file():
        words = len(readme.read_text(encoding="utf-8").split())
        print(f"{words:7d} words  README.md" +
              (f"  (over the budget of {MAX_README_WORDS} words)" if words > MAX_README_WORDS else ""))
        failed = failed or words > MAX_README_WORDS
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
