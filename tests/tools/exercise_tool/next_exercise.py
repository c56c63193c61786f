"""`exercises.py next` and `exercises.py test NAME`: a student's loop. The student edition is generated where
missing, configured with the course's own flags (its unchanged files are then ccache hits of the course's
build), and only the test program of the exercise's chapter is built; only the exercise's tests that need no
other exercise left are run, so every failure shown is this exercise's."""

from __future__ import annotations

import hashlib
import json
import re
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

from .edition import EDITION_MARKER, generate, write_if_changed
from .marks import TAG_PREFIX, Exercise, ToolError, find_exercises
from .test_runs import exercise_tags

PASSED_FILE = "exercises-passed.json"  # in the build folder: exercises whose tests passed, by source digest
SHOWN_LINES = 20  # distinct lines of a failing run's output


@dataclass
class TaggedTest:
    program: str  # "ch01_test"
    name: str
    tags: list[str]


def program_tests(program: Path) -> list[TaggedTest]:
    """The test program's tests that carry [ex:...] tags, asked of the program (its tags are string literals
    and macros the compiler joins, so they are read from what it built)."""
    return [TaggedTest(name_program, name, tags)
            for (name_program, name), tags in exercise_tags({str(program)}).items()]


def own_tests(exercise: Exercise, tests: list[TaggedTest]) -> list[TaggedTest]:
    return [t for t in tests if exercise.name in t.tags and t.program == f"{exercise.chapter}_test"]


def test_filter(exercise: Exercise, tests: list[TaggedTest], left: set[str]) -> tuple[str, list[TaggedTest]]:
    """The Catch2 filter that runs the exercise's tests needing no other exercise left, and the tests it leaves
    out (they wait for another)."""
    others = sorted({tag for t in own_tests(exercise, tests) for tag in t.tags} & left - {exercise.name})
    waiting = [t for t in own_tests(exercise, tests) if set(t.tags) & set(others)]
    return f"[{TAG_PREFIX}{exercise.name}]" + "".join(f"~[{TAG_PREFIX}{o}]" for o in others), waiting


def course_order(exercises: list[Exercise], tests: list[TaggedTest]) -> list[Exercise]:
    """Chapter by chapter; in a chapter, the exercises with a test that needs no other of the chapter first, then
    in the order of their files and marks."""
    def needs(e: Exercise) -> int:
        counts = [len(set(t.tags) - {e.name}) for t in own_tests(e, tests)]
        return min(counts) if counts else 0
    return sorted(exercises, key=lambda e: (e.chapter, needs(e), str(e.file), e.begin))


def digest(edition: Path, exercise: Exercise) -> str:
    return hashlib.sha256((edition / exercise.file).read_bytes()).hexdigest()[:16]


def find_edition(root: Path, edition: Path | None) -> Path:
    """This repository when it is a student edition; else EDITION (default ../rt-student), generated if missing."""
    if (root / EDITION_MARKER).is_file():
        return root
    edition = (edition or root.parent / "rt-student").resolve()
    if not (edition / EDITION_MARKER).is_file():
        started = time.monotonic()
        generate(root, edition, [], force=False)
        print(f"wrote the student edition in {edition} ({time.monotonic() - started:.0f} s); you work there")
    return edition


def configure(edition: Path, *options: str) -> Path:
    """Configures the edition as the course's release preset does (once), or with `options` changed."""
    build = edition / "build" / "release"
    if not (build / "CMakeCache.txt").is_file():
        print("configuring (cmake --preset release) ...", flush=True)
        configured = subprocess.run(["cmake", "--preset", "release"], cwd=edition, capture_output=True, text=True)
        if configured.returncode != 0:
            raise ToolError("cmake --preset release failed:\n" + configured.stdout[-2000:] + configured.stderr[-2000:])
    if options:
        subprocess.run(["cmake", "-S", str(edition), "-B", str(build), *options], check=True, capture_output=True)
    return build


def build_program(edition: Path, program: str, jobs: int) -> Path:
    """Builds one test program of the edition (configured first where it is not)."""
    build = configure(edition)
    print(f"building {program} (cmake --build build/release --target {program}) ...", flush=True)
    built = subprocess.run(["cmake", "--build", str(build), "-j", str(jobs), "--target", program],
                           capture_output=True, text=True)
    if built.returncode != 0:
        errors = [line for line in (built.stdout + built.stderr).splitlines() if "error" in line or "|" in line]
        raise ToolError(f"{program} does not build:\n" + "\n".join(errors[:SHOWN_LINES]))
    return next(build.glob(f"chapters/*/{program}"))


def course_shaders(edition: Path, exercise: Exercise, exercises: list[Exercise]) -> tuple[Path | None, list[str]]:
    """A shader is compiled whole, so one #error stops every test of its chapter. For a shader exercise: a copy of
    its folder (in the build) in which the other shader exercises still left are the course's bodies, read from
    the course the edition was made from; and their names. (None, []) where none is left or the course is gone."""
    others = [e for e in exercises if e.glsl and e.chapter == exercise.chapter and e.name != exercise.name
              and e.stubbed]
    course = Path(json.loads((edition / EDITION_MARKER).read_text(encoding="utf-8")).get("source", ""))
    solutions = {e.name: e for e in find_exercises(course)} if others and course.is_dir() else {}
    if not others or any(o.name not in solutions for o in others):
        return None, []
    copy = edition / "build" / "release" / "exercise-shaders"
    for source in sorted(p for p in (edition / exercise.file.parent).iterdir() if p.is_file()):
        lines = source.read_text(encoding="utf-8").split("\n")
        for other in sorted((o for o in others if o.file == exercise.file.parent / source.name),
                            key=lambda o: o.begin, reverse=True):
            solution = solutions[other.name]
            lines[other.begin + 1 : other.end] = \
                (course / solution.file).read_text(encoding="utf-8").split("\n")[solution.begin + 1 : solution.end]
        write_if_changed(copy / source.name, "\n".join(lines).encode("utf-8"))
    return copy, sorted(o.name for o in others)


def run_exercise(edition: Path, program: Path, exercise: Exercise, tests: list[TaggedTest], left: set[str],
                 jobs: int, again: str) -> bool:
    """Runs the exercise's tests that need no other exercise left (a shader exercise's program rebuilt with the
    other shader exercises left the course's, for this run); shows the failures."""
    shaders, supplied = course_shaders(edition, exercise, find_exercises(edition)) if exercise.glsl else (None, [])
    if not supplied:
        return run_program(edition, program, exercise, tests, left, again)
    print(f"{', '.join(supplied)}: the course's, for this run only (a shader compiles whole)")
    configure(edition, f"-DRT_SHADER_SOURCE_DIR={shaders}")
    try:
        return run_program(edition, build_program(edition, program.name, jobs), exercise, tests, left - set(supplied),
                           again)
    finally:
        configure(edition, "-DRT_SHADER_SOURCE_DIR=")  # the edition's own shaders again, at the next build


def run_program(edition: Path, program: Path, exercise: Exercise, tests: list[TaggedTest], left: set[str],
                again: str) -> bool:
    spec, waiting = test_filter(exercise, tests, left)
    print(f"running {program.name} \"{spec}\" ...", flush=True)
    done = subprocess.run([str(program), spec, "--reporter", "compact", "-w", "NoTests"], cwd=program.parent,
                          capture_output=True, text=True)
    count = len(own_tests(exercise, tests)) - len(waiting)
    if waiting:
        needed = sorted({tag for t in waiting for tag in t.tags} & left - {exercise.name})
        print(f"({len(waiting)} more of its tests also need {', '.join(needed)}: they run once that is written)")
    if done.returncode == 0:
        print(f"{exercise.name}: its {count} tests pass")
        return True
    # One line per failing check (a check in a loop or a section fails alike each time), its file as written.
    lines = list(dict.fromkeys(re.sub(r"^(\.\./)+", "", line) for line in (done.stdout + done.stderr).splitlines()
                               if line.strip()))
    print("\n".join(lines[:SHOWN_LINES]) + (f"\n... ({len(lines) - SHOWN_LINES} lines more)"
                                            if len(lines) > SHOWN_LINES else ""))
    print(f"\nnext exercise: {exercise.name}: write {exercise.function}() in {edition / exercise.file}:"
          f"{exercise.begin + 1}\n  the lesson: {edition / exercise.lesson} § {exercise.section}\n"
          f"  then run this again: python3 tests/tools/exercises.py {again}")
    return False


def command_next(root: Path, edition_arg: Path | None, only: str | None, jobs: int) -> int:
    """Runs the exercises in course order: a written one whose tests passed since its file last changed is
    skipped; the first whose tests fail is shown with its file and lesson section. With `only`, that exercise."""
    started = time.monotonic()
    edition = find_edition(root, edition_arg)
    exercises = find_exercises(edition)
    if only and only not in {e.name for e in exercises}:
        raise ToolError(f"test: {only}: no such exercise (see `exercises.py list`)")
    record = edition / "build" / "release" / PASSED_FILE
    passed = json.loads(record.read_text()) if record.is_file() else {}
    for chapter in sorted({e.chapter for e in exercises}):
        waiting = [e for e in exercises if e.chapter == chapter and (e.name == only if only else
                                                                      passed.get(e.name) != digest(edition, e))]
        if not waiting:
            continue
        program = build_program(edition, f"{chapter}_test", jobs)
        tests = program_tests(program)
        for exercise in course_order(waiting, tests):
            left = {e.name for e in exercises if e.stubbed or passed.get(e.name) != digest(edition, e)}
            ok = run_exercise(edition, program, exercise, tests, left, jobs, f"test {only}" if only else "next")
            if ok:
                passed[exercise.name] = digest(edition, exercise)
                record.write_text(json.dumps(passed, indent=1) + "\n")
            print(f"({time.monotonic() - started:.0f} s)")
            if not ok or only:
                return 0 if ok else 1
    print(f"every exercise's tests pass ({len(exercises)} exercises)")
    return 0
