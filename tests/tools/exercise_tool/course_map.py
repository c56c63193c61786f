"""The course map's "needs first" column, written from the tests' exercise tags, and the map checked against it.

A chapter's tests (tests/NN_*_test.cpp) carry a tag [ex:chMM.name] for every exercise they reach, so the
chapters whose exercises they need are the MMs of those tags other than NN. The column names only the
chapters needed directly: those not already needed by another chapter of the list (chapter 09 needs 01 to
08, and 08 needs 01 to 07, so 09 needs first 08). A chapter that needs none needs "C++, vectors".
"""

from __future__ import annotations

import re
from pathlib import Path

from .marks import TAG_PREFIX, Exercise

NOTHING_BEFORE = "C++, vectors"
TEST_FILE_RE = re.compile(r"^(\d\d)_\w+_test\.cpp$")
TAG_CHAPTER_RE = re.compile(r"\[" + re.escape(TAG_PREFIX) + r"ch(\d\d)\.")
MAP_HEADING = "## Course map"
MAP_ROW_RE = re.compile(r"^\|\s*(\d\d) [^|]*\|([^|]*)\|")
COUNT_RE = re.compile(r"\bevery exercise \((\d+)|\b(\d+) exercises\b")


def chapters_needed(root: Path) -> dict[str, set[str]]:
    """Chapter number → the chapters whose exercises its tests are tagged with (itself left out)."""
    needed = {}
    for test_file in sorted((root / "tests").glob("[0-9][0-9]_*_test.cpp")):
        chapter = TEST_FILE_RE.match(test_file.name).group(1)
        tagged = set(TAG_CHAPTER_RE.findall(test_file.read_text(encoding="utf-8")))
        needed[chapter] = tagged - {chapter}
    return needed


def needs_first(needed: dict[str, set[str]]) -> dict[str, list[str]]:
    """Each chapter's direct needs: the chapters it needs that no other chapter it needs needs, at any depth."""
    def closure(chapter: str, seen: frozenset = frozenset()) -> set[str]:
        found = set()
        for other in needed.get(chapter, set()) - seen:
            found |= {other} | closure(other, seen | {chapter})
        return found

    return {chapter: sorted(d for d in needs if not any(d in closure(e) for e in needs - {d}))
            for chapter, needs in needed.items()}


def needs_first_cell(direct: list[str]) -> str:
    return ", ".join(direct) if direct else NOTHING_BEFORE


def map_cells(readme: str) -> dict[str, tuple[int, str]]:
    """The course map's rows in the README: chapter number → (line, its "needs first" cell)."""
    cells = {}
    in_map = False
    for number, line in enumerate(readme.splitlines(), start=1):
        if line.startswith("## "):
            in_map = line.strip() == MAP_HEADING
        m = MAP_ROW_RE.match(line) if in_map else None
        if m:
            cells[m.group(1)] = (number, m.group(2).strip())
    return cells


def exercise_counts(text: str) -> list[tuple[int, int]]:
    """(line, N) for each "every exercise (N" or "N exercises" a document states."""
    found = []
    for number, line in enumerate(text.splitlines(), start=1):
        for m in COUNT_RE.finditer(line):
            found.append((number, int(m.group(1) or m.group(2))))
    return found


def map_problems(root: Path, exercises: list[Exercise], documents: list[str]) -> list[str]:
    """Where README.md's course map disagrees with the tags, or a document states another exercise count."""
    readme = "README.md"
    direct = needs_first(chapters_needed(root))
    cells = map_cells((root / readme).read_text(encoding="utf-8"))
    problems = []
    if not cells:
        problems.append(f"{readme}: no course map (a table under \"{MAP_HEADING}\")")
    for chapter in sorted(set(direct) | set(cells)):
        want = needs_first_cell(direct.get(chapter, []))
        if chapter not in cells:
            if cells:
                problems.append(f"{readme}: the course map has no row for chapter {chapter} (needs first: {want})")
            continue
        line, cell = cells[chapter]
        if chapter not in direct:
            problems.append(f"{readme}:{line}: chapter {chapter} has no tests (tests/{chapter}_*_test.cpp)")
        elif cell != want:
            problems.append(f"{readme}:{line}: chapter {chapter} needs first \"{want}\" by its tests' exercise tags, "
                            f"the map says \"{cell}\"")
    for document in documents:
        path = root / document
        for line, count in exercise_counts(path.read_text(encoding="utf-8")) if path.is_file() else []:
            if count != len(exercises):
                problems.append(f"{document}:{line}: says {count} exercises; {len(exercises)} are marked")
    return problems
