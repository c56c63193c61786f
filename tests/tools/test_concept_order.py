#!/usr/bin/env python3
"""concept_order.py's own tests: on small lesson trees, a use before the teaching section fails and names the
concept and the lesson; a use after it, or in a later lesson, passes; a missing or silent section fails."""

import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ folders in the repository
sys.path.insert(0, str(Path(__file__).resolve().parent))
import concept_order  # noqa: E402

INVERSION = concept_order.Concept("sampling by inversion", "02_b", "Sampling", (r"\binversion\b", r"\bCDF\b"))


def lessons(texts: dict[str, str]) -> list[concept_order.Lesson]:
    return [concept_order.Lesson(Path("chapters") / name / "README.md", text.splitlines())
            for name, text in sorted(texts.items())]


class Order(unittest.TestCase):
    def test_a_use_in_an_earlier_lesson_fails_naming_the_concept_and_the_lesson(self):
        found = concept_order.problems(lessons({
            "01_a": "# A\n\nDerive the inversion here.\nAnd the CDF.\n",
            "02_b": "# B\n\n## Sampling\n\nThe inversion method.\n",
        }), [INVERSION])
        self.assertEqual(len(found), 1, found)
        self.assertIn("chapters/01_a/README.md:3: uses sampling by inversion", found[0])
        self.assertIn("chapters/02_b/README.md § Sampling, line 3", found[0])
        self.assertIn("1 more use", found[0])

    def test_a_use_above_the_section_of_the_same_lesson_fails(self):
        found = concept_order.problems(lessons({
            "02_b": "# B\n\nThe CDF first.\n\n## Sampling\n\nThe inversion method.\n",
        }), [INVERSION])
        self.assertEqual(len(found), 1, found)
        self.assertTrue(found[0].startswith("chapters/02_b/README.md:3: uses sampling by inversion (\"CDF\")"))

    def test_uses_in_and_after_the_section_and_in_later_lessons_pass(self):
        found = concept_order.problems(lessons({
            "01_a": "# A\n\nNothing about it.\n",
            "02_b": "# B\n\n## Sampling\n\nThe inversion method.\n\n## Later\n\nThe CDF again.\n",
            "03_c": "# C\n\nDerive the inversion.\n",
        }), [INVERSION])
        self.assertEqual(found, [])

    def test_a_section_missing_fails_once_with_the_first_use(self):
        found = concept_order.problems(lessons({
            "01_a": "# A\n\nDerive the inversion.\n",
            "02_b": "# B\n\n## Elsewhere\n\nThe CDF.\n",
        }), [INVERSION])
        self.assertEqual(len(found), 1, found)
        self.assertIn("chapters/01_a/README.md:3: uses sampling by inversion", found[0])
        self.assertIn("taught nowhere", found[0])
        self.assertIn("2 lessons use it", found[0])

    def test_a_section_that_never_says_its_concept_fails(self):
        found = concept_order.problems(lessons({"02_b": "# B\n\n## Sampling\n\nSomething else.\n"}), [INVERSION])
        self.assertEqual(len(found), 1, found)
        self.assertIn("teaches sampling by inversion without any of its words", found[0])

    def test_a_section_ends_at_the_next_heading_of_its_level(self):
        lesson = lessons({"02_b": "# B\n## Sampling\ntext\n### Sub\nmore\n## Next\nrest\n"})[0]
        self.assertEqual(lesson.section_span("Sampling"), (2, 5))
        self.assertIsNone(lesson.section_span("Missing"))

    def test_the_course_keeps_the_order_and_exits_1_when_it_breaks(self):
        root = Path(__file__).resolve().parents[2]
        self.assertEqual(concept_order.main(["concept_order", str(root)]), 0)
        with tempfile.TemporaryDirectory() as scratch:
            lesson = Path(scratch) / "chapters" / "01_ray_generation" / "README.md"
            lesson.parent.mkdir(parents=True)
            lesson.write_text("# 01\n\nThe error falls like 1/√N.\n", encoding="utf-8")
            self.assertEqual(concept_order.main(["concept_order", scratch]), 1)


if __name__ == "__main__":
    unittest.main()
