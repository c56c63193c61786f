#!/usr/bin/env python3
"""The course map's generator and check (tests/tools/exercise_tool/course_map.py) on small trees: the direct
needs from transitive tags, the map's cells read from README.md, and a wrong cell or count named by line."""

import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ folders in the repository
sys.path.insert(0, str(Path(__file__).resolve().parent))
from exercise_tool import course_map  # noqa: E402
from exercise_tool.marks import Exercise, find_exercises  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
README = """# Course

## Course map

| chapter | needs first | hours |
|---|---|---:|
| 01 first | C++, vectors | 2 |
| 02 second | 01 | 3 |
| 03 third | {third} | 4 |

## Later

| 01 another table | not the map | 1 |

Instructors: every exercise ({count}, one per idea).
"""


def tree(folder: Path, tags: dict[str, str], third: str, count: int) -> Path:
    """A repository of three chapters' test files, each holding `tags`, and a README whose map says `third`."""
    (folder / "tests").mkdir()
    for name, text in tags.items():
        (folder / "tests" / name).write_text(f'TEST_CASE("x", "{text}") {{}}\n', encoding="utf-8")
    (folder / "README.md").write_text(README.format(third=third, count=count), encoding="utf-8")
    return folder


def exercises(n: int) -> list[Exercise]:
    return [Exercise(f"ch01.e{i}", Path("a.cpp"), 0, 1) for i in range(n)]


TAGS = {"01_first_test.cpp": "[ex:ch01.a]",
        "02_second_test.cpp": "[ex:ch01.a][ex:ch02.b]",
        "03_third_test.cpp": "[ex:ch01.a][ex:ch02.b][ex:ch03.c]"}


class Needs(unittest.TestCase):
    def test_a_chapter_needs_first_only_what_no_other_need_implies(self):
        needed = {"01": set(), "02": {"01"}, "03": {"01", "02"}, "04": {"01"}, "05": {"01", "02", "04"}}
        self.assertEqual(course_map.needs_first(needed),
                         {"01": [], "02": ["01"], "03": ["02"], "04": ["01"], "05": ["02", "04"]})
        self.assertEqual(course_map.needs_first_cell([]), "C++, vectors")
        self.assertEqual(course_map.needs_first_cell(["02", "04"]), "02, 04")

    def test_the_course_chapter_10_needs_07_and_there_are_60_exercises(self):
        direct = course_map.needs_first(course_map.chapters_needed(ROOT))
        self.assertEqual(direct["10"], ["07"])
        self.assertEqual(direct["01"], [])
        self.assertEqual(len(find_exercises(ROOT)), 60)

    def test_the_map_cells_come_from_the_course_map_table_only(self):
        cells = course_map.map_cells(README.format(third="02", count=3))
        self.assertEqual(cells, {"01": (7, "C++, vectors"), "02": (8, "01"), "03": (9, "02")})


class Check(unittest.TestCase):
    def test_a_map_that_agrees_with_the_tags_passes(self):
        with tempfile.TemporaryDirectory() as folder:
            root = tree(Path(folder), TAGS, third="02", count=3)
            self.assertEqual(course_map.map_problems(root, exercises(3), ["README.md"]), [])

    def test_a_wrong_cell_is_named_by_its_line_with_what_the_tags_say(self):
        with tempfile.TemporaryDirectory() as folder:
            root = tree(Path(folder), TAGS, third="01, 02", count=3)
            problems = course_map.map_problems(root, exercises(3), ["README.md"])
        self.assertEqual(problems, ['README.md:9: chapter 03 needs first "02" by its tests\' exercise tags, '
                                    'the map says "01, 02"'])

    def test_a_wrong_exercise_count_is_named_by_its_line(self):
        with tempfile.TemporaryDirectory() as folder:
            root = tree(Path(folder), TAGS, third="02", count=54)
            problems = course_map.map_problems(root, exercises(55), ["README.md", "missing.md"])
        self.assertEqual(problems, ["README.md:15: says 54 exercises; 55 are marked"])

    def test_a_chapter_without_a_row_fails(self):
        with tempfile.TemporaryDirectory() as folder:
            tags = dict(TAGS, **{"04_fourth_test.cpp": "[ex:ch03.c]"})
            root = tree(Path(folder), tags, third="02", count=3)
            problems = course_map.map_problems(root, exercises(3), ["README.md"])
        self.assertEqual(problems, ["README.md: the course map has no row for chapter 04 (needs first: 03)"])


if __name__ == "__main__":
    unittest.main()
