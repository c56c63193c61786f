#!/usr/bin/env python3
"""Each interface lives in the chapter that teaches it (tests/tools/chapter_ownership.py ROOT).

An earlier chapter may hold the step a later chapter calls, never the later chapter's idea: no source or lesson
of a chapter before the owner below names one of the owner's interfaces. Prints one line per use found
(file:line: name, which chapter NN teaches) and exits 1; prints nothing and exits 0 when there is none.
"""
import pathlib
import re
import sys

# The interface (a whole identifier) and the chapter that teaches it.
OWNERS = {
    "PhaseFunction": 9, "PhaseSample": 9, "FreeFlight": 9, "pdf_ratio": 9, "pick_channel": 9,
    "sample_free_flight": 9, "ScatteringMedium": 9, "index_matched": 9,  # media, spectral MIS
    "Transport": 7, "kImportance": 7, "radiance_scale": 7,  # refraction's radiance scale, per transport
}
WORD = re.compile(r"\b(" + "|".join(OWNERS) + r")\b")


def check(root):
    problems = []
    for folder in sorted((root / "chapters").glob("[0-9][0-9]_*")):
        chapter = int(folder.name[:2])
        for path in sorted([*folder.glob("*.[ch]pp"), folder / "README.md"]):
            if not path.exists():
                continue
            for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
                for name in WORD.findall(line):
                    # In a lesson only code names count: `Transport` in prose is the English word.
                    if path.suffix == ".md" and f"`{name}" not in line and f"{name}`" not in line and \
                            f"::{name}" not in line:
                        continue
                    if chapter < OWNERS[name]:
                        problems.append(f"{path.relative_to(root)}:{number}: {name}, which chapter "
                                        f"{OWNERS[name]:02d} teaches")
    return problems


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
    problems = check(root)
    for line in problems:
        print(line)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
