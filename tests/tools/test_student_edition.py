#!/usr/bin/env python3
"""The student edition compiles every file without an exercise exactly as the course does, so ccache reuses
the course's objects: a student's first build compiles only the files with exercises.

  test_student_edition.py REPOSITORY_ROOT BUILD_DIR

Writes the student edition in a scratch folder, configures it as BUILD_DIR (the course's build) is configured
(its build type and options, its build folder as deep below the edition), and compares the two builds'
compile commands file by file, the edition's folder read as the repository's: equal for every file (a warning in
a student's code stays a warning through pragmas around the exercise, not through flags). Needs cmake; only the Python 3 standard library is used.
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from pathlib import Path

sys.dont_write_bytecode = True
from exercise_tool.edition import generate  # noqa: E402

CACHE_OPTIONS = ["CMAKE_BUILD_TYPE", "CMAKE_CXX_FLAGS_DEBUG", "CMAKE_CXX_COMPILER", "CMAKE_CXX_FLAGS", "RT_SANITIZE",
                 "RT_FUZZ", "RT_PCH", "RT_DOUBLE", "RT_WARNINGS_AS_ERRORS", "RT_BENCHMARKS_IN_ALL"]


def cache_values(build: Path) -> dict[str, str]:
    values = {}
    for line in (build / "CMakeCache.txt").read_text(encoding="utf-8", errors="replace").splitlines():
        name, _, rest = line.partition(":")
        if name in CACHE_OPTIONS and "=" in rest:
            values[name] = rest.split("=", 1)[1]
    return values


def commands(build: Path, root: Path) -> dict[str, list[str]]:
    """Each compiled file (relative to root) → its compile command's words, with root written as ROOT."""
    entries = json.loads((build / "compile_commands.json").read_text(encoding="utf-8"))
    return {str(Path(e["file"]).relative_to(root)) if Path(e["file"]).is_relative_to(root) else e["file"]:
            e["command"].replace(str(root), "ROOT").split() for e in entries}


def main(argv: list[str]) -> int:
    root, build = Path(argv[0]).resolve(), Path(argv[1]).resolve()
    with tempfile.TemporaryDirectory(prefix="student-edition-flags.") as scratch:
        edition = Path(scratch) / "rt-student"
        exercises = generate(root, edition, [], force=False)
        edition_build = edition / build.relative_to(root)
        options = [f"-D{k}={v}" for k, v in cache_values(build).items() if k != "RT_WARNINGS_AS_ERRORS" or v != "ON"]
        subprocess.run(["cmake", "-S", str(edition), "-B", str(edition_build), *options], check=True,
                       stdout=subprocess.DEVNULL)
        course, student = commands(build, root), commands(edition_build, edition)
    problems = []
    for file, words in sorted(course.items()):
        if file not in student:
            problems.append(f"{file}: compiled by the course, not by the student edition")
        elif sorted(student[file]) != sorted(words):
            added = sorted(set(student[file]) - set(words))
            lost = sorted(set(words) - set(student[file]))
            problems.append(f"{file}: the student edition compiles it with {added or 'nothing'} more and "
                            f"{lost or 'nothing'} less than the course")
    for problem in problems:
        print(problem)
    print(f"{len(course)} files compiled by the course; {len(problems)} compiled otherwise by the student edition "
          f"({len(exercises)} exercises stubbed)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
