#!/usr/bin/env python3
"""Lessons that teach, not logs: each lesson's word count, and what a lesson should not hold.

  lesson_lint.py [REPOSITORY_ROOT]

Prints each lesson (chapters/*/README.md) with its word count (words as `wc -w` counts them), then one
line per flag: FILE:LINE: what was found. A lesson is flagged for
  * more than MAX_WORDS words;
  * a date or a clock time (a measurement's date belongs in the chapter's benchmark/README.md);
  * a load average, or a figure tied to one core ("core 0", "on core 1"): a lab notebook's detail;
  * a citation a reader of the repository cannot open ("issue 18", "the course's source text").
Exits 1 if anything is flagged, 0 otherwise. Only the Python 3 standard library is used.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

MAX_WORDS = 5000

MONTH = r"(?:January|February|March|April|May|June|July|August|September|October|November|December)"
FLAGS = [
    ("a date", re.compile(r"\b\d{4}-\d{2}-\d{2}\b|\b\d{1,2} " + MONTH + r"\b|\b" + MONTH + r" \d{1,2}\b")),
    ("a clock time", re.compile(r"\b\d{1,2}:?\d{2} ?UTC\b|\bUTC\b")),
    ("a load average", re.compile(r"\bload(?: average)?(?: of)? ~?\d", re.IGNORECASE)),
    ("a per-core figure", re.compile(r"\bcores? #?\d", re.IGNORECASE)),
    ("a citation a reader cannot open", re.compile(r"\b(?:issue|PR|pull request) #?\d+|\bsource text\b",
                                                   re.IGNORECASE)),
]


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
        print(f"{words:7d} words  {name}" + (f"  (over the budget of {MAX_WORDS})" if over else ""))
        for line, what, match in lesson_flags(text):
            print(f"  {name}:{line}: {what}: \"{match}\"")
            failed = True
        failed = failed or over
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
