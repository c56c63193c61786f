#!/usr/bin/env python3
"""The course's explanatory diagrams, drawn from the maths by matplotlib (Debian: python3-matplotlib).

  make_diagrams.py                 write every diagram into its chapter's images/ folder
  make_diagrams.py --check         regenerate every diagram in a temporary folder and fail (exit 1) if any
                                   differs from the committed SVG or is missing; exit 77 (skipped) when
                                   matplotlib is not installed

One module per chapter (chNN_*.py) draws its figures, course_*.py those of common/README.md; figure_style.py makes the SVG deterministic.
"""

from __future__ import annotations

import argparse
import importlib
import sys
import tempfile
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ in the source tree

HERE = Path(__file__).resolve().parent
CHAPTERS = HERE.parent
SKIPPED = 77


def every_diagram() -> dict[str, bytes]:
    """Each diagram's path under chapters/ and its SVG bytes."""
    from figure_style import svg_bytes
    diagrams = {}
    for module_file in sorted([*HERE.glob("ch[0-9][0-9]_*.py"), *HERE.glob("course_*.py")]):
        module = importlib.import_module(module_file.stem)
        for path, fig in module.figures().items():
            diagrams[path] = svg_bytes(fig)
    return diagrams


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="compare with the committed SVGs, write nothing")
    args = parser.parse_args()
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("make_diagrams: matplotlib is not installed (apt-get install python3-matplotlib): skipped")
        return SKIPPED
    sys.path.insert(0, str(HERE))
    diagrams = every_diagram()
    if not args.check:
        for path, svg in diagrams.items():
            (CHAPTERS / path).write_bytes(svg)
            print(f"wrote chapters/{path}")
        return 0
    stale = []
    with tempfile.TemporaryDirectory() as scratch:
        for path, svg in diagrams.items():
            fresh = Path(scratch) / path.replace("/", "_")
            fresh.write_bytes(svg)
            committed = CHAPTERS / path
            if not committed.is_file() or committed.read_bytes() != fresh.read_bytes():
                stale.append(path)
    for path in stale:
        print(f"make_diagrams: chapters/{path} differs from what chapters/diagrams draws "
              f"(run chapters/diagrams/make_diagrams.py and commit it)")
    print(f"make_diagrams: {len(diagrams) - len(stale)} of {len(diagrams)} diagrams as committed")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
