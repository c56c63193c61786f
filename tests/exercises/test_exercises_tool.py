#!/usr/bin/env python3
"""Tests of tests/tools/exercises.py on a fixture chapter (tests/exercises/fixture): the marks it finds, the lesson
sections it names, the marks it refuses, that the stubbed sources compile with the course's warnings as
errors, and that the switchable edition of `deps` stubs an exercise only when told to at run time.
Run: python3 tests/exercises/test_exercises_tool.py [--compiler g++]   (CTest: label `tools`)."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
FIXTURE = HERE / "fixture"
COMPILER = "g++"
# A program that prints hypotenuse(3, 4), or the message of the logic_error it throws.
MAIN_CALLING_HYPOTENUSE = r"""#include <cstdio>
#include <stdexcept>
#include "fixture.hpp"
int main() {
    try {
        std::printf("%g\n", fx::hypotenuse(3, 4));
    } catch (const std::logic_error& e) {
        std::printf("%s\n", e.what());
    }
}
"""
WARNINGS = ["-Wall", "-Wextra", "-Wpedantic", "-Wshadow", "-Wconversion", "-Wno-sign-conversion", "-Werror"]

sys.path.insert(0, str(ROOT / "tests" / "tools"))
sys.dont_write_bytecode = True  # no __pycache__ folders in the repository
from exercise_tool import edition, marks, test_runs, wrong_solutions  # noqa: E402  (tests/tools/ is not a package on the path)


def copy_of_fixture(folder: Path) -> Path:
    root = folder / "repo"
    shutil.copytree(FIXTURE, root)
    return root


class Marks(unittest.TestCase):
    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        self.root = copy_of_fixture(self.folder)

    def tearDown(self):
        shutil.rmtree(self.folder)

    def test_finds_every_mark_with_its_function_parameters_and_locals(self):
        found = {e.name: e for e in marks.find_exercises(self.root)}
        self.assertEqual(sorted(found), ["ch07.counter", "ch07.counter_start", "ch07.hypotenuse", "ch07.increment",
                                         "ch07.integrate", "ch07.shader_square"])
        self.assertTrue(found["ch07.shader_square"].glsl)
        self.assertFalse(found["ch07.hypotenuse"].glsl)
        h = found["ch07.hypotenuse"]
        self.assertEqual(h.function, "hypotenuse")
        self.assertEqual(h.parameters, ["a", "b", "scale"])  # the unnamed int has no name to cast
        self.assertEqual(h.locals, ["twice", "p", "q", "pair_of"])
        self.assertEqual(found["ch07.counter"].function, "next")
        self.assertEqual(found["ch07.counter_start"].function, "Counter")  # past its member initialisers
        self.assertEqual(found["ch07.counter_start"].parameters, ["start", "stride"])
        self.assertEqual(found["ch07.integrate"].parameters, ["interval", "steps", "f"])

    def test_names_the_lesson_section_its_mark_names(self):
        found = {e.name: e for e in marks.find_exercises(self.root)}
        lesson = "chapters/07_fixture/README.md"
        self.assertEqual(found["ch07.hypotenuse"].reference(), lesson + " § The hypotenuse")
        self.assertEqual(found["ch07.integrate"].reference(), lesson + " § Integrals")
        self.assertEqual(found["ch07.counter"].reference(), lesson + " § Counting, `next` and all")  # backticks kept

    def test_refuses_a_mark_without_a_section_or_naming_no_heading_of_its_lesson(self):
        self.rewrite("EXERCISE(ch07.counter) § Counting, `next` and all", "EXERCISE(ch07.counter)")
        with self.assertRaisesRegex(marks.ToolError, r"fixture.cpp:\d+: EXERCISE\(ch07.counter\) names no lesson "
                                    r"section: add § and a heading of chapters/07_fixture/README.md"):
            marks.find_exercises(self.root)
        self.rewrite("EXERCISE(ch07.counter)", "EXERCISE(ch07.counter) § Files")
        with self.assertRaisesRegex(marks.ToolError, r"fixture.cpp:\d+: EXERCISE\(ch07.counter\) names § Files, "
                                    r"but chapters/07_fixture/README.md has no such heading"):
            marks.find_exercises(self.root)
        # A heading inside a code block is no heading.
        self.rewrite("EXERCISE(ch07.counter) § Files", "EXERCISE(ch07.counter) § Not a heading")
        with self.assertRaisesRegex(marks.ToolError, "names § Not a heading, but"):
            marks.find_exercises(self.root)

    def test_the_stubbed_sources_compile_with_warnings_as_errors(self):
        out = self.folder / "edition"
        edition.generate(self.root, out, [], force=False)
        source = (out / "chapters/07_fixture/fixture.cpp").read_text(encoding="utf-8")
        self.assertIn('throw std::logic_error("not implemented: ch07.hypotenuse — see '
                      'chapters/07_fixture/README.md § The hypotenuse");', source)
        self.assertNotIn("std::sqrt(square(p)", source)
        self.assertIn("[[maybe_unused]] double square", source)
        self.assertIn("[[maybe_unused]] int calls", source)
        self.assertIn("[[maybe_unused]] static double cube", source)
        self.assertIn("// EXERCISE(ch07.hypotenuse)", source)  # the marks stay, for the student and the tools
        header = (out / "chapters/07_fixture/fixture.hpp").read_text(encoding="utf-8")
        self.assertIn("#include <stdexcept>", header)
        for unit in ("fixture.cpp",):
            compiled = subprocess.run([COMPILER, "-std=c++20", "-fsyntax-only", *WARNINGS, f"-I{out / 'common'}",
                                       unit], cwd=out / "chapters/07_fixture", capture_output=True, text=True)
            self.assertEqual(compiled.returncode, 0, compiled.stderr)
        # The original compiles too, so the edition's success is not an accident of the fixture.
        compiled = subprocess.run([COMPILER, "-std=c++20", "-fsyntax-only", *WARNINGS, "fixture.cpp"],
                                  cwd=self.root / "chapters/07_fixture", capture_output=True, text=True)
        self.assertEqual(compiled.returncode, 0, compiled.stderr)

    def test_a_shader_exercise_is_stubbed_by_an_error_line_and_switched_by_a_define(self):
        message = ("not implemented: ch07.shader_square — see chapters/07_fixture/README.md § Counting, `next` and "
                   "all")
        stubbed = self.folder / "edition"
        edition.generate(self.root, stubbed, [], force=False)
        shader = (stubbed / "chapters/07_fixture/fixture.glsl").read_text(encoding="utf-8")
        self.assertIn(f"    // EXERCISE(ch07.shader_square) § Counting, `next` and all\n#error {message}\n"
                      "    // END EXERCISE\n", shader)
        self.assertNotIn("x * x", shader)
        self.assertTrue({e.name: e for e in marks.find_exercises(stubbed)}["ch07.shader_square"].stubbed)
        switchable = self.folder / "switchable"
        chosen = {e.name: e for e in edition.generate(self.root, switchable, [], force=False, switchable=True)}
        path = switchable / "chapters/07_fixture/fixture.glsl"
        shader = path.read_text(encoding="utf-8")
        self.assertIn("#define RT_EXERCISE_ch07_shader_square 0\n#if RT_EXERCISE_ch07_shader_square == -1\n"
                      f"#error {message}\n", shader)
        self.assertIn("#else\n    return x * x;\n#endif\n", shader)
        self.assertFalse({e.name: e for e in marks.find_exercises(switchable)}["ch07.shader_square"].stubbed)
        edition.set_shader_switch(switchable, chosen["ch07.shader_square"], -1)
        self.assertIn("#define RT_EXERCISE_ch07_shader_square -1\n", path.read_text(encoding="utf-8"))

    def test_only_stubs_the_chosen_exercises_and_refuses_unknown_ones(self):
        out = self.folder / "edition"
        chosen = edition.generate(self.root, out, ["ch07.counter"], force=False)
        self.assertEqual([e.name for e in chosen], ["ch07.counter"])
        source = (out / "chapters/07_fixture/fixture.cpp").read_text(encoding="utf-8")
        self.assertIn("not implemented: ch07.counter", source)
        self.assertIn("std::sqrt(square(p)", source)
        with self.assertRaisesRegex(marks.ToolError, "already there"):
            edition.generate(self.root, out, [], force=False)
        with self.assertRaisesRegex(marks.ToolError, "no such exercise"):
            edition.generate(self.root, out, ["ch07.nothing"], force=True)

    def test_a_warning_in_a_students_code_stays_a_warning_wherever_its_header_is_included(self):
        out = self.folder / "edition"
        edition.generate(self.root, out, [], force=False)
        self.assertTrue((out / "common/rt/exercise_warnings.hpp").is_file())
        header = out / "chapters/07_fixture/fixture.hpp"
        text = header.read_text(encoding="utf-8")
        self.assertIn('#include "rt/exercise_warnings.hpp"', text)
        self.assertIn("    RT_YOUR_CODE_BEGIN\n    // EXERCISE(ch07.integrate)", text)
        self.assertIn("    // END EXERCISE\n    RT_YOUR_CODE_END\n}", text)
        # A student's first attempt, with an unused variable and a narrowing conversion, in the header's exercise.
        attempt = text.replace("    // END EXERCISE\n    RT_YOUR_CODE_END",
                               "    int unused = 0.5 * steps;\n    return 0;\n    // END EXERCISE\n    RT_YOUR_CODE_END")
        self.assertNotEqual(attempt, text)
        user = self.folder / "user.cpp"  # another chapter's file, including the header
        user.write_text('#include "fixture.hpp"\ndouble one() { return fx::integrate(fx::Interval{0, 1}, 4, '
                        '[](double) { return 1.0; }); }\n', encoding="utf-8")

        def compile_user(header_text: str) -> subprocess.CompletedProcess:
            header.write_text(header_text, encoding="utf-8")
            return subprocess.run([COMPILER, "-std=c++20", "-fsyntax-only", *WARNINGS, f"-I{out / 'common'}",
                                   f"-I{header.parent}", str(user)], capture_output=True, text=True)

        compiled = compile_user(attempt)
        self.assertEqual(compiled.returncode, 0, compiled.stderr)
        self.assertIn("unused variable", compiled.stderr)  # said, not fatal
        # The same code outside the student's lines is still an error: the pragmas end with the exercise.
        outside = attempt.replace("int unused = 0.5 * steps;\n    return 0;\n", "").replace(
            "class Counter {", "inline int narrowed(double x) { return x; }\nclass Counter {")
        self.assertNotEqual(compile_user(outside).returncode, 0)

    def test_refuses_to_write_over_a_folder_that_is_not_an_edition(self):
        other = self.folder / "other"
        other.mkdir()
        (other / "notes.txt").write_text("mine")
        with self.assertRaisesRegex(marks.ToolError, "not a student edition"):
            edition.generate(self.root, other, [], force=True)
        with self.assertRaisesRegex(marks.ToolError, "over the repository"):
            edition.generate(self.root, self.root, [], force=True)

    def test_the_switchable_edition_runs_as_written_or_stubs_the_exercise_named_at_run_time(self):
        out = self.folder / "switchable"
        chosen = edition.generate(self.root, out, [], force=False, switchable=True)
        self.assertEqual(len(chosen), 6)
        source = (out / "chapters/07_fixture/fixture.cpp").read_text(encoding="utf-8")
        self.assertIn('#include "rt/exercise_switch.hpp"', source)
        self.assertIn("std::sqrt(square(p)", source)  # every body kept, after its switch
        self.assertNotIn("[[maybe_unused]]", source)
        self.assertTrue((out / "common/rt/exercise_switch.hpp").is_file())
        self.assertEqual([e.name for e in marks.find_exercises(out) if e.stubbed], [])  # written, not stubbed
        main = self.folder / "main.cpp"
        main.write_text(MAIN_CALLING_HYPOTENUSE, encoding="utf-8")
        program = self.folder / "fixture_program"
        chapter = out / "chapters/07_fixture"
        compiled = subprocess.run([COMPILER, "-std=c++20", *WARNINGS, f"-I{out / 'common'}", f"-I{chapter}",
                                   str(chapter / "fixture.cpp"), str(main), "-o", str(program)],
                                  capture_output=True, text=True)
        self.assertEqual(compiled.returncode, 0, compiled.stderr)
        log = self.folder / "reached.log"

        def run(**environment):
            env = {k: v for k, v in os.environ.items()
                   if k not in ("RT_STUB_EXERCISE", "RT_EXERCISE_LOG", "RT_WRONG_SOLUTION")}
            return subprocess.run([str(program)], capture_output=True, text=True, check=True,
                                  env={**env, **environment}).stdout.strip()

        self.assertEqual(run(RT_EXERCISE_LOG=str(log)), "5")  # as written
        self.assertEqual(log.read_text().split(), ["ch07.hypotenuse"])  # the one exercise it reached, once
        self.assertEqual(run(RT_STUB_EXERCISE="ch07.counter"), "5")  # another exercise stubbed: no change
        self.assertTrue(run(RT_STUB_EXERCISE="ch07.hypotenuse").startswith("not implemented: ch07.hypotenuse — see"))
        self.assertTrue(run(RT_STUB_EXERCISE="ch07.counter,ch07.hypotenuse").startswith("not implemented"))  # a list
        self.assertEqual(run(RT_STUB_EXERCISE="ch07.counter,ch07.hypot"), "5")  # a name's prefix is not the name
        # The fixture's wrong solutions (tests/wrong_solutions/ch07.json), chosen at run time.
        self.assertIn("wrong_here", source)
        self.assertEqual(run(RT_WRONG_SOLUTION="ch07.hypotenuse:1"), "2.64575")  # √(3 + 4)
        self.assertEqual(run(RT_WRONG_SOLUTION="ch07.hypotenuse:2"), "0")
        self.assertEqual(run(RT_WRONG_SOLUTION="ch07.counter:1"), "5")  # another exercise's: no change

    def test_a_wrong_solution_that_no_longer_fits_its_exercise_is_refused(self):
        self.rewrite("square(p) + square(q)", "square(q) + square(p)")
        with self.assertRaises(marks.ToolError) as refused:
            edition.generate(self.root, self.folder / "switchable", [], force=False, switchable=True)
        self.assertIn('ch07.hypotenuse #1: "square(p) + square(q)" occurs 0 times', str(refused.exception))

    def test_other_right_solutions_and_what_a_failure_must_say_are_read_and_checked(self):
        path = self.root / "tests/wrong_solutions/ch07.json"
        data = json.loads(path.read_text(encoding="utf-8"))
        data["ch07.hypotenuse"][0]["says"] = "not squared"
        data["ch07.hypotenuse"].append({"correct": True, "answer": "q² + p²",
                                        "replace": {"square(p) + square(q)": "square(q) + square(p)"}})

        def load():
            path.write_text(json.dumps(data), encoding="utf-8")
            return wrong_solutions.load(self.root, marks.find_exercises(self.root))["ch07.hypotenuse"]

        self.assertEqual([(s.correct, s.says, s.mistake) for s in load()],
                         [(False, "not squared", "the sides not squared"), (False, "", "a whole body of its own"),
                          (True, "", "q² + p²")])
        data["ch07.hypotenuse"][2]["says"] = "passes"  # a right solution fails nowhere
        with self.assertRaisesRegex(marks.ToolError, 'ch07.hypotenuse #3: "says" must be'):
            load()
        del data["ch07.hypotenuse"][2]["says"], data["ch07.hypotenuse"][2]["answer"]
        with self.assertRaisesRegex(marks.ToolError, 'ch07.hypotenuse #3: needs an "answer"'):
            load()

    def test_a_derive_item_is_known_by_its_lesson_row(self):
        lesson = self.root / "chapters/07_fixture/README.md"
        lesson.write_text(lesson.read_text(encoding="utf-8") + "\n| exercise | what to write |\n|---|---|\n"
                          "| `ch07.hypotenuse` | the length. **Derive** it from Pythagoras |\n"
                          "| `ch07.counter` | the next value |\n", encoding="utf-8")
        self.assertEqual(wrong_solutions.derive_items(self.root), {"ch07.hypotenuse"})

    def rewrite(self, old, new):
        path = self.root / "chapters/07_fixture/fixture.cpp"
        text = path.read_text(encoding="utf-8")
        self.assertIn(old, text)
        path.write_text(text.replace(old, new, 1), encoding="utf-8")

    def test_refuses_a_mark_that_does_not_end_the_function_body(self):
        self.rewrite("    return value_ + step;\n    // END EXERCISE\n", "    // END EXERCISE\n    return value_ + step;\n")
        with self.assertRaisesRegex(marks.ToolError, r"fixture.cpp:\d+: EXERCISE\(ch07.counter\) must end"):
            marks.find_exercises(self.root)

    def test_refuses_unclosed_nested_and_misnamed_marks(self):
        self.rewrite("    // END EXERCISE\n}\n\nvoid increment_all", "}\n\nvoid increment_all")
        with self.assertRaisesRegex(marks.ToolError, "inside EXERCISE\\(ch07.counter\\)"):
            marks.find_exercises(self.root)
        self.rewrite("EXERCISE(ch07.increment)", "EXERCISE(ch02.increment)")
        with self.assertRaisesRegex(marks.ToolError, "is in chapter folder 07_fixture"):
            marks.find_exercises(self.root)


class Results(unittest.TestCase):
    def result(self, name, passed, output, tags):
        return test_runs.TestResult(name, "ch07_test", "ch07", passed, output, tags)

    def test_a_not_implemented_message_is_found_where_catch_wrapped_it(self):
        # A shader's #error reaches the test's output inside the driver's message, which Catch2 wraps.
        output = ("  the driver did not compile probe.comp: 0:46(1): preprocessor error: #error not\n"
                  "  implemented: ch07.a — see chapters/07_fixture/README.md § Integrals")
        self.assertEqual(self.result("t", False, output, ["ch07.a"]).not_implemented(), ["ch07.a"])

    def test_an_exercise_is_left_failing_or_done(self):
        found = [marks.Exercise(n, Path("x.cpp"), 0, 1) for n in ("ch07.a", "ch07.b", "ch07.c", "ch07.d")]
        results = [
            self.result("t1", False, "due to unexpected exception with message:\n  not implemented: ch07.a — see",
                        ["ch07.a", "ch07.b"]),
            self.result("t2", False, "CHECK( x == 1 ) with expansion: 2 == 1", ["ch07.b"]),
            self.result("t3", True, "", ["ch07.c"]),
        ]
        states = {k: v["state"] for k, v in test_runs.summarise(found, results, None).items()}
        self.assertEqual(states, {"ch07.a": "left", "ch07.b": "failing", "ch07.c": "done", "ch07.d": "untested"})

    def test_the_next_exercise_is_one_whose_tests_need_no_other_exercise_left(self):
        # ch07.path needs ch04.lambert (left, in another chapter); ch07.weight needs nothing else.
        found = [marks.Exercise(n, Path("x.cpp"), 0, 1, stubbed=True) for n in ("ch07.path", "ch07.weight")]
        results = [self.result("path", False, "not implemented: ch04.lambert — see", ["ch04.lambert", "ch07.path"]),
                   self.result("weight", False, "not implemented: ch07.weight — see", ["ch07.weight"])]
        entries = list(test_runs.summarise(found, results, None).values())
        left = {"ch04.lambert", "ch07.path", "ch07.weight"}
        upcoming, blocking = test_runs.next_exercise(entries, left)
        self.assertEqual(upcoming.name, "ch07.weight")
        # With ch07.weight done, ch07.path is not ready until chapter 04's exercise is written.
        upcoming, blocking = test_runs.next_exercise([x for x in entries if x["exercise"].name == "ch07.path"],
                                                     left - {"ch07.weight"})
        self.assertIsNone(upcoming)
        self.assertEqual(blocking, {"ch04.lambert"})
        upcoming, _ = test_runs.next_exercise(entries, {"ch07.path"})
        self.assertEqual(upcoming.name, "ch07.path")


if __name__ == "__main__":
    if "--compiler" in sys.argv:
        at = sys.argv.index("--compiler")
        COMPILER = sys.argv[at + 1]
        del sys.argv[at : at + 2]
    unittest.main()
