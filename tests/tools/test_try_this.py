#!/usr/bin/env python3
"""Tests of try_this.py: which figures agree with a run's output, and how a lesson's items become runs."""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

sys.dont_write_bytecode = True
from try_this import check_figure, try_this_items, with_flags  # noqa: E402

OUTPUT = """  rays: camera 1440000, shadow 3923763, reflection 50543, refraction 505605, indirect 4925482 (total 10845393)
  image mean 0.350671, all pixels finite: yes
sphere  light     0.140496  0.140494 8.038e-03    902.2 1.907e-03 4.667e-04 1.262e-04 3.546e-06
"""

LESSON = """# A lesson

## Try this

From the repository root (`B=build/release/chapters`), about 10 s each:

1. `$B/07_x/ch07_x --spp 16 --out glass.png`. It counts `refraction 505605` rays; the same with `--spp 4`:
   `image mean 0.35067`.
2. The same with `--spp 8 --out
   b.png`: `image mean 0.3507`.

## Files
"""


def main() -> int:
    failures = []

    def expect(condition: bool, what: str) -> None:
        if not condition:
            failures.append(what)

    expect(check_figure("refraction 505605", OUTPUT) is None, "a count printed as shown agrees")
    expect(check_figure("refraction 325140", OUTPUT) is not None, "a stale count (chapter 07's 325 140) is caught")
    expect(check_figure("refraction 505600", OUTPUT) is not None, "a count agrees only exactly")
    expect(check_figure("image mean 0.35067", OUTPUT) is None, "a mean agrees to the digits shown (0.350671)")
    expect(check_figure("image mean 0.351", OUTPUT) is None, "a mean rounded to 3 digits agrees")
    expect(check_figure("image mean 0.3508", OUTPUT) is not None, "a mean off in its last digit shown is caught")
    expect(check_figure("rays: camera 1440000, shadow 3923763, ...", OUTPUT) is None, "... stands for the rest")
    expect(check_figure("sphere light ... 1.262e-04", OUTPUT) is None, "a gap, then a number further on")
    expect(check_figure("sphere light ... 1.5e-4", OUTPUT) is not None, "a number nowhere on the line is caught")
    expect(check_figure("image median 0.35067", OUTPUT) is not None, "other words are caught")
    expect(with_flags("$B/a --spp 16 --out x.png", "--spp 4") == "$B/a --spp 4 --out x.png", "a flag's value changes")
    expect(with_flags("$B/a --spp 16", "--tracer paths") == "$B/a --spp 16 --tracer paths", "a new flag is added")
    with tempfile.TemporaryDirectory() as folder:
        lesson = Path(folder) / "README.md"
        lesson.write_text(LESSON, encoding="utf-8")
        items = try_this_items(lesson)
        expect(len(items) == 2 and all(item.slow for item in items), "two items, slow by the block's 'about 10 s each'")
        runs = [(command, [figure for _, figure in figures]) for item in items for command, figures in item.runs]
        expect(runs == [("$B/07_x/ch07_x --spp 16 --out glass.png", ["refraction 505605"]),
                        ("$B/07_x/ch07_x --spp 4 --out glass.png", ["image mean 0.35067"]),
                        ("$B/07_x/ch07_x --spp 8 --out b.png", ["image mean 0.3507"])], f"the runs: {runs}")
        expect([line for item in items for _, figures in item.runs for line, _ in figures] == [7, 8, 10],
               "each figure's line in the lesson")
    for failure in failures:
        print(f"FAILED: {failure}")
    print(f"try_this.py: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
