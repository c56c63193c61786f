#!/usr/bin/env python3
"""lesson_lint.py's own tests: what it flags and what it leaves alone, what counts as measurement, and its exit
code on a small tree."""

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


# Blocks and the measurement words each holds (0: not measurement).
MEASUREMENT = {
    "The render takes 4.66 s on two threads.": 8,
    "Light sampling is 63× more efficient here.": 7,
    "It loses 5.1 % of the light.": 7,
    "- roulette's mean is within 0.3% of the reference": 9,
    "```\nrender 1.10 s, denoise 0.02 s\n```": 8,
    "| spp | RMSE |\n|---|---|\n| 1 | 0.249 |\n| 4 | 0.125 |": 16,
    "A 200×200 image, 16 samples per pixel.": 0,
    "The test fails below the 1 % level.": 0,
    "A chi-square test of 20 000 samples.": 0,
    "| code | what |\n|---|---|\n| `a.cpp` | the sampler |": 0,
    "```\nch07_bsdf_refraction --spp 16 --out glass.png\n```": 0,
}


def main() -> int:
    failures = []
    for text, words in MEASUREMENT.items():
        found = lesson_lint.measurement_words(text)
        if found != words:
            failures.append(f"measurement words of {text!r}: {found}, expected {words}")
    # Blocks are counted apart: a measured paragraph does not make its neighbours measurement.
    two = "Plain words of teaching here.\n\nIt ran in 3 s."
    if lesson_lint.measurement_words(two) != 5:
        failures.append(f"a blank line does not separate blocks: {lesson_lint.measurement_words(two)} words")
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
        readme = Path(root) / "README.md"

        def expect(path: Path, text: str, status: int, failure: str) -> None:
            path.write_text(text, encoding="utf-8")
            if lesson_lint.main(["lesson_lint", root]) != status:
                failures.append(failure)

        expect(lesson, "word " * lesson_lint.MAX_WORDS, 0, "a lesson of exactly the budget fails")
        expect(lesson, "word " * (lesson_lint.MAX_WORDS + 1), 1, "a lesson over the budget passes")
        # 85 words of teaching and 15 of measurement: exactly the share allowed; one more measured word fails.
        teaching = "word " * 85
        expect(lesson, teaching + "\n\nrender " + "took " * 12 + "2.5 s\n", 0,
               "a lesson of exactly 15 % measurement fails")
        expect(lesson, teaching + "\n\nrender " + "took " * 13 + "2.5 s\n", 1,
               "a lesson over 15 % measurement passes")
        lesson.write_text(teaching, encoding="utf-8")
        expect(readme, "word " * lesson_lint.MAX_README_WORDS, 0, "a top README of exactly its budget fails")
        expect(readme, "word " * (lesson_lint.MAX_README_WORDS + 1), 1, "a top README over its budget passes")
    for failure in failures:
        print("FAIL:", failure)
    print("OK" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
