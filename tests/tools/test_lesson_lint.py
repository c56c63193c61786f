#!/usr/bin/env python3
"""lesson_lint.py's own tests: what it flags and what it leaves alone, and its exit code on a small tree."""

import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import lesson_lint  # noqa: E402

FLAGGED = {
    "measured on 2 December 2026": "a date",
    "run 2026-12-02 at night": "a date",
    "from 11:28 to 11:34 UTC": "a clock time",
    "at 0520 UTC": "a clock time",
    "load average 1.2 at the start": "a load average",
    "at a load of 7 to 10": "a load average",
    "one thread on core 0": "a per-core figure",
    "on cores 0 and 1": "a per-core figure",
    "figures quoted in issue 18": "a citation a reader cannot open",
    "the course's source text closes with": "a citation a reader cannot open",
}
CLEAN = [
    "Chapter 05 turned the rendering equation into a recursion.",
    "they move with the machine's load.",
    "a 2-core machine, 16 cores of a GPU",
    "the core idea of the chapter",
    "May the error fall like 1/√N",
]


def main() -> int:
    failures = []
    for text, what in FLAGGED.items():
        found = [w for _, w, _ in lesson_lint.lesson_flags(text)]
        if what not in found:
            failures.append(f"not flagged as {what}: {text!r} (found {found})")
    for text in CLEAN:
        found = lesson_lint.lesson_flags(text)
        if found:
            failures.append(f"flagged but clean: {text!r} ({found})")
    with tempfile.TemporaryDirectory() as root:
        lesson = Path(root) / "chapters" / "01_x" / "README.md"
        lesson.parent.mkdir(parents=True)
        lesson.write_text("word " * lesson_lint.MAX_WORDS, encoding="utf-8")
        if lesson_lint.main(["lesson_lint", root]) != 0:
            failures.append("a lesson of exactly the budget fails")
        lesson.write_text("word " * (lesson_lint.MAX_WORDS + 1), encoding="utf-8")
        if lesson_lint.main(["lesson_lint", root]) != 1:
            failures.append("a lesson over the budget passes")
    for failure in failures:
        print("FAIL:", failure)
    print("OK" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
