#!/usr/bin/env python3
"""The course as unit-test exercises: find the marked exercises, write the student edition, and say which
exercises are done.

A chapter source marks the statements a student writes, inside one function body:

    Vec3 sphere_normal(const Sphere& sphere, const Vec3& p) {
        // EXERCISE(ch02.sphere_normal) § Each shape's equation
        ...the statements...
        // END EXERCISE
    }

After § comes the heading of the lesson's section that teaches it (the chapter's README.md; it must exist,
or every command stops with the mark's file and line). The END line must be followed by the closing brace of
the function. A shader's function (chapter 11's .glsl files) is marked the same way: its stub is an #error line
with the message, which the driver prints when it refuses the shader; `deps` and `wrong` switch its body by a
#define in the edition's source and rebuild the chapter's test program. Tests that depend on an exercise carry
the Catch2 tag [ex:ch02.sphere_normal] (a test may carry several).

  exercises.py list                     every exercise: name, file:line, function, lesson section (fails when
                                        a mark names no section or one its lesson lacks)
  exercises.py map [--check]            the course map's "needs first" column, written from the tests' [ex:...]
                                        tags (the chapters whose exercises they need, less those needed
                                        through another), and the exercises per chapter; --check fails where
                                        README.md's map or a stated exercise count disagrees
  exercises.py next [--edition DIR]    a student's loop: generates the student edition (default ../rt-student)
                                        where missing, builds only the test program of the next exercise left,
                                        runs its tests that need no other exercise left, and shows the failures
                                        with the file to edit and the lesson section
  exercises.py test NAME               the same for one exercise: ch01.camera_ray
  exercises.py generate OUT             the student edition in OUT: each marked body becomes a line that
                                        throws "not implemented: chNN.name — see <lesson> § <section>"
  exercises.py status [--build DIR]     runs a build's unit tests, lists per chapter exercises done and left
  exercises.py lint --build DIR         any build: every [ex:...] tag names a marked exercise, every
                                        exercise has a tagged test (no test is run)
  exercises.py deps SCRATCH [--only ch03] which tests depend on which exercise: one build in which any one
                                        exercise is stubbed at run time, each stubbed in turn for the
                                        tests that reach it; prints the tags each test needs
  exercises.py wrong SCRATCH [--only ch04]  CI: each exercise's wrong solutions (tests/wrong_solutions/,
                                        at least three each) are caught by its own chapter's tests, in one
                                        build of the switchable edition of `deps`, and its other right
                                        solutions there ("correct": true) pass them; for the whole course,
                                        `check` follows there with every exercise stubbed at run time
  exercises.py warnings --build DIR     CI: a student edition's files with exercises compile without a
                                        warning (syntax only: the tests run in `wrong`'s build)
  exercises.py check --build DIR        CI: in a student edition's build, the failing tests are exactly
                                        the tests tagged with an exercise stubbed, each naming it (in the
                                        full edition's build: every unit test passes)

Only the Python 3 standard library is used (Debian 12: `apt-get install python3`).
"""

from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import sys
from pathlib import Path

sys.dont_write_bytecode = True  # no __pycache__ folders in the repository
from exercise_tool.course_map import (chapters_needed, map_problems, needs_first,  # noqa: E402
                                     needs_first_cell)
from exercise_tool.edition import generate, set_shader_switch  # noqa: E402
from exercise_tool.next_exercise import command_next as run_next  # noqa: E402
from exercise_tool.marks import TAG_PREFIX, Exercise, ToolError, find_exercises  # noqa: E402
from exercise_tool.stub_warnings import stub_warnings  # noqa: E402
from exercise_tool.test_runs import (TestResult, UnitTest, exercise_tags, next_exercise, run_each,  # noqa: E402
                                     run_tests, source_of_build, summarise, unit_tests)
from exercise_tool.wrong_solutions import (MINIMUM_PER_EXERCISE, derive_items,  # noqa: E402
                                          load as load_wrong_solutions)

ROOT = Path(__file__).resolve().parent.parent.parent


def command_list(args: argparse.Namespace) -> int:
    exercises = find_exercises(args.root)
    for e in exercises:
        print(f"{e.name:32} {e.where():48} {e.function + '()':28} {e.reference()}")
    print(f"{len(exercises)} exercises in {len({e.chapter for e in exercises})} chapters")
    return 0


MAP_DOCUMENTS = ["README.md", "common/README.md", "chapters/README.md"]  # where an exercise count may be stated


def command_map(args: argparse.Namespace) -> int:
    """The course map's "needs first" column from the tests' exercise tags; --check: README.md's map and every
    exercise count stated in MAP_DOCUMENTS agree with them."""
    exercises = find_exercises(args.root)
    direct = needs_first(chapters_needed(args.root))
    per_chapter = {}
    for e in exercises:
        per_chapter[e.chapter[2:]] = per_chapter.get(e.chapter[2:], 0) + 1
    print(f"{'chapter':8} {'needs first':14} exercises")
    for chapter in sorted(direct):
        print(f"{chapter:8} {needs_first_cell(direct[chapter]):14} {per_chapter.get(chapter, 0)}")
    print(f"{len(exercises)} exercises in {len(per_chapter)} chapters")
    if not args.check:
        return 0
    problems = map_problems(args.root, exercises, MAP_DOCUMENTS)
    for problem in problems:
        print(problem)
    print("the course map agrees with the tests' tags" if not problems else f"{len(problems)} disagreements")
    return 1 if problems else 0


def command_generate(args: argparse.Namespace) -> int:
    only = [o for o in (args.only or "").split(",") if o]
    chosen = generate(args.root, Path(args.out), only, args.force)
    chapters = sorted({e.chapter for e in chosen})
    print(f"student edition in {Path(args.out).resolve()}: {len(chosen)} exercises stubbed "
          f"({', '.join(chapters) if chapters else 'none'})")
    print(f"then:  cd {args.out} && python3 tests/tools/exercises.py next      (builds and runs the next "
          "exercise's tests only)")
    return 0


def command_next(args: argparse.Namespace) -> int:
    return run_next(args.root, Path(args.edition) if args.edition else None, getattr(args, "name", None), args.jobs)


def default_build() -> Path:
    for candidate in (Path.cwd(), ROOT / "build" / "release", ROOT / "build"):
        if (candidate / "CMakeCache.txt").is_file():
            return candidate
    raise ToolError("no build folder found: give --build DIR (the folder you built the course in)")


def command_status(args: argparse.Namespace) -> int:
    build = Path(args.build) if args.build else default_build()
    source = source_of_build(build)
    exercises = find_exercises(source)
    results = run_tests(build, args.label, args.jobs)
    summary = summarise(exercises, results, args.label)
    warn_if_stale(build, source)
    # Every exercise left in the course, whatever the label: an exercise waits for those its tests need.
    left = {e.name for e in exercises if e.stubbed} | {
        name for r in results for name in r.not_implemented()}
    symbols = {"done": "done", "written": "written", "left": "LEFT", "failing": "FAILING", "untested": "untested"}
    by_chapter: dict[str, list[dict]] = {}
    for entry in summary.values():
        by_chapter.setdefault(entry["exercise"].chapter, []).append(entry)
    total_done = 0
    first = None  # the first chapter's ready exercise: the course's next
    for chapter in sorted(by_chapter):
        entries = by_chapter[chapter]
        done = [x for x in entries if x["state"] == "done"]
        total_done += len(done)
        print(f"{chapter}: {len(done)} of {len(entries)} exercises done")
        for x in sorted(entries, key=lambda x: x["exercise"].name):
            e = x["exercise"]
            tests = x["tests"]
            passed = sum(1 for r in tests if r.passed)
            blocked = ""
            if x["state"] == "written":
                blocked = f" (its failing tests also need {', '.join(sorted(x['blocked_by']))})"
            print(f"  {symbols[x['state']]:9} {e.name:30} {e.where():46} tests {passed}/{len(tests)} pass{blocked}")
            stubbed = {y["exercise"].name for y in summary.values() if y["state"] == "left"}
            for r in tests:
                # A failing test that needs no exercise left is a bug to find; the others wait (with -v).
                waits = bool(set(r.tags) & stubbed)
                if not r.passed and ((x["state"] == "failing" and not waits) or args.verbose):
                    print(f"              failing: {r.name}" + (" (waits for an exercise left)" if waits else ""))
        upcoming, blocking = next_exercise(entries, left)
        if upcoming:
            print(f"  next: {upcoming.name} in {upcoming.where()} — see {upcoming.reference()}")
        elif blocking:
            print(f"  next: none yet; its tests also need {', '.join(sorted(blocking))}")
        if upcoming and first is None:
            first = upcoming
    other = [r for r in results if not r.passed and not r.tags]
    if other:
        print(f"{len(other)} failing tests depend on no exercise:")
        for r in other:
            print(f"  {r.label or '?'}: {r.name}")
    print(f"{total_done} of {len(summary)} exercises done; {sum(r.passed for r in results)} of {len(results)} tests pass")
    if first:
        print(f"write next: {first.name} in {first.where()} — see {first.reference()}")
    return 0


def warn_if_stale(build: Path, source: Path) -> None:
    """Says so when a source file is newer than the build's newest test program: the results are then
    those of the code as it was at the last build, not as it is."""
    programs = [p for p in build.rglob("*_test") if p.is_file()]
    sources = [p for folder in ("chapters", "common", "tests") for p in (source / folder).rglob("*")
               if p.suffix in (".cpp", ".hpp") and p.is_file()]
    if not programs or not sources:
        return
    built = max(p.stat().st_mtime for p in programs)
    newer = [p for p in sources if p.stat().st_mtime > built]
    if newer:
        names = ", ".join(str(p.relative_to(source)) for p in sorted(newer)[:3])
        more = f" and {len(newer) - 3} more" if len(newer) > 3 else ""
        print(f"warning: {names}{more} changed after the last build of {build}: rebuild first "
              f"(cmake --build {build}), or these results are of the old code")


def command_check(args: argparse.Namespace) -> int:
    """In a build of the student edition: the failing tests are exactly the tests tagged with an exercise
    still stubbed, and each names one of them; every tag names a marked exercise; every exercise has a test.
    In a build of the full edition (nothing stubbed) that is: every test passes."""
    build = Path(args.build)
    exercises = find_exercises(source_of_build(build))
    stubbed = {e.name for e in exercises if e.stubbed}
    edition = "student edition" if stubbed else "full edition (nothing stubbed)"
    return report_failures_against_tags(edition, exercises, stubbed, run_tests(build, None, args.jobs))


def report_failures_against_tags(edition: str, exercises: list[Exercise], stubbed: set[str],
                                 results: list[TestResult]) -> int:
    """Prints whether the failing tests are exactly those tagged with an exercise in `stubbed`, each naming one
    of them (and every tag a marked exercise, every exercise tested): 0 if so, 1 with the problems if not."""
    if not results:
        raise ToolError("no test results")
    names = {e.name for e in exercises}
    problems = []
    expected = [r for r in results if set(r.tags) & stubbed]
    failing = [r for r in results if not r.passed]
    for r in results:
        where = f"{r.program}: \"{r.name}\""
        for tag in r.tags:
            if tag not in names:
                problems.append(f"{where} is tagged [{TAG_PREFIX}{tag}], but no such exercise is marked")
        named = r.not_implemented()
        missing = sorted(set(named) - set(r.tags))
        if r.passed:
            if set(r.tags) & stubbed:
                problems.append(f"{where} is tagged {sorted(set(r.tags) & stubbed)} but passes while they are not "
                                "written: it does not depend on them")
        elif missing:
            add = " ".join(f"[{TAG_PREFIX}{n}]" for n in missing)
            problems.append(f"{where} fails with \"not implemented: {missing[0]}\": it depends on {', '.join(missing)}"
                            f"{' too' if r.tags else ''}; add {add} (`exercises.py deps` finds every dependency)")
        elif not named:
            why = "no 'not implemented' in its output"
            if "terminate called" in r.output:
                why += (" (std::terminate: an exception escaped a thread; a render loop must pass its threads' "
                        "exceptions to the caller)")
            problems.append(f"{where} fails without naming an exercise{' it is tagged with' if r.tags else ''}: {why}")
    tested = {tag for r in results for tag in r.tags}
    for e in exercises:
        if e.name not in tested:
            problems.append(f"{e.where()}: exercise {e.name} has no test tagged [{TAG_PREFIX}{e.name}]")
    print(f"{edition}: {len(results)} unit tests, {len(failing)} failing, {len(expected)} tagged as depending on "
          f"the {len(stubbed)} exercises stubbed ({len(exercises)} marked, {len(tested)} with tests)")
    if len(failing) != len(expected):
        problems.append(f"{len(failing)} tests fail but {len(expected)} are tagged as depending on exercises stubbed")
    if problems:
        print(f"{edition} check FAILED:")
        for p in problems:
            print("  " + p)
        return 1
    print(f"{edition} check passed: the failing tests are exactly the tests of the exercises left, each naming "
          "its exercise")
    return 0


def command_deps(args: argparse.Namespace) -> int:
    """For instructors and chapter authors: which tests depend on which exercise. One build of the switchable
    edition, in which each exercise is stubbed at run time when RT_STUB_EXERCISE names it (see
    exercise_tool/exercise_switch.hpp); a first run of every unit test records the exercises it reaches; then
    each exercise is stubbed in turn for the tests that reach it, and those that fail depend on it (a test
    that never reaches an exercise runs the same with it stubbed). Prints, per test program, the tags each
    test needs and how they differ from its tags now."""
    out = Path(args.out).resolve()
    only = [o for o in (args.only or "").split(",") if o]
    exercises = generate(args.root, out, only, force=True, switchable=True)
    build = build_test_programs(out, args.jobs)
    tests = unit_tests(build)
    logs = out / "reached"
    shutil.rmtree(logs, ignore_errors=True)
    logs.mkdir()
    print(f"running {len(tests)} unit tests in {build}, recording the exercises each reaches ...", flush=True)
    baseline = run_each(tests, args.jobs, environment_of=lambda i: {"RT_EXERCISE_LOG": str(logs / f"{i}.log")})
    reached = [set((logs / f"{i}.log").read_text().split()) if (logs / f"{i}.log").is_file() else set()
               for i in range(len(tests))]
    needs: dict[int, list[str]] = {i: [] for i in range(len(tests))}
    for e in exercises:
        if e.glsl:  # a shader logs nothing when it runs: every test of its chapter's program, stubbed at once
            reaching = [i for i in range(len(tests)) if tests[i].program == f"{e.chapter}_test" and baseline[i][0]]
            outcomes = run_with_shader_switch(out, e, -1, [tests[i] for i in reaching], args)
        else:
            reaching = [i for i in range(len(tests)) if e.name in reached[i] and baseline[i][0]]
            outcomes = run_each([tests[i] for i in reaching], args.jobs,
                                environment_of=lambda _: {"RT_STUB_EXERCISE": e.name})
        failing = [i for i, (passed, _) in zip(reaching, outcomes) if not passed]
        print(f"{e.name}: reached by {len(reaching)} tests, {len(failing)} fail without it", flush=True)
        for i in failing:
            needs[i].append(e.name)
    tags = exercise_tags({t.command[0] for t in tests})
    chosen = {e.name for e in exercises}
    changes = 0
    for program in sorted({t.program for t in tests}):
        print(f"{program}:")
        for i, t in enumerate(tests):
            if t.program != program:
                continue
            now = sorted(tag for tag in tags.get((t.program, t.name), []) if tag in chosen)
            found = sorted(needs[i])
            mark = "" if found == now else "   <- now " + ("".join(f"[{TAG_PREFIX}{x}]" for x in now) or "untagged")
            changes += found != now
            if found or now:
                print(f"  \"{t.name}\": {''.join(f'[{TAG_PREFIX}{x}]' for x in found) or 'no exercise'}{mark}")
    for i, t in enumerate(tests):
        if not baseline[i][0]:
            print(f"  (fails even with nothing stubbed: {t.program}: \"{t.name}\")")
    print(f"{changes} tests whose tags differ from what they depend on")
    return 1 if changes else 0


def build_test_programs(source: Path, jobs: int, only: set[str] | None = None) -> Path:
    """Configures and builds the test programs of the edition in `source`, in source/build/release (with
    `only`, those programs only, e.g. {"ch04_test"}). With the course's flags, so that ccache reuses the course's
    objects of every file without an exercise; within an exercise's lines warnings stay warnings
    (rt/exercise_warnings.hpp: a wrong solution may leave a variable unused)."""
    build = source / "build" / "release"  # as deep as the course's own build: ccache reuses unchanged objects
    # Configured every time: `--target help` lists the targets of the last configure, which may predate a chapter.
    subprocess.run(["cmake", "-S", str(source), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"],
                   check=True, stdout=subprocess.DEVNULL)
    targets = re.findall(r"^\.\.\. (\w+_test)$", subprocess.run(
        ["cmake", "--build", str(build), "--target", "help"], capture_output=True, text=True).stdout, re.M)
    if only is not None:
        targets = [t for t in targets if t in only]
    built = subprocess.run(["cmake", "--build", str(build), "-j", str(jobs), "--target", *targets],
                           capture_output=True, text=True)
    if built.returncode != 0:
        raise ToolError(f"deps: the switchable edition in {source} does not build:\n"
                        + built.stdout[-3000:] + built.stderr[-3000:])
    return build


def command_wrong(args: argparse.Namespace) -> int:
    """CI: every exercise has at least three plausible wrong solutions in tests/wrong_solutions/, and each is
    caught by its own chapter's tests: one build of the switchable edition (as `deps`), then for each wrong
    solution the chapter's tests tagged with the exercise are run with it in place of the right body, and at
    least one must fail (or crash, or time out), its output containing the entry's "says" where it has one.
    With the right body, and with each other right solution (an entry "correct": true), they must all pass."""
    out = Path(args.out).resolve()
    only = [o for o in (args.only or "").split(",") if o]
    exercises = generate(args.root, out, only, force=True, switchable=True)
    wrong = load_wrong_solutions(args.root, find_exercises(args.root))
    counts = {e.name: sum(1 for s in wrong.get(e.name, []) if not s.correct) for e in exercises}
    problems = [f"{e.where()}: exercise {e.name} has {counts[e.name]} wrong solutions in "
                f"tests/wrong_solutions/{e.chapter}.json; at least {MINIMUM_PER_EXERCISE} are needed"
                for e in exercises if counts[e.name] < MINIMUM_PER_EXERCISE]
    derive = derive_items(args.root)
    problems += [f"{e.where()}: exercise {e.name} asks to derive, but tests/wrong_solutions/{e.chapter}.json has no "
                 "other right solution (\"correct\": true) that its tests must accept" for e in exercises
                 if e.name in derive and not any(s.correct for s in wrong.get(e.name, []))]
    programs = {f"{e.chapter}_test" for e in exercises}
    build = build_test_programs(out, args.jobs, programs if only else None)
    program_of = {t.program: t.command[0] for t in unit_tests(build)}
    # The right bodies are the same program for every exercise of a chapter: one run of all their tests per
    # chapter (a test tagged with several exercises runs once), then one per wrong or other right solution.
    runs = []  # (exercise, wrong solution or None for the right bodies of its chapter's exercises)
    specs = {}  # chapter → the Catch2 test spec of its exercises' tests
    for e in exercises:
        if f"{e.chapter}_test" not in program_of:
            problems.append(f"{e.where()}: exercise {e.name}: its chapter has no test program {e.chapter}_test")
            continue
        if e.chapter not in specs:
            runs.append((e, None))
        specs[e.chapter] = ",".join(filter(None, [specs.get(e.chapter), f"[{TAG_PREFIX}{e.name}]"]))
        runs += [(e, s) for s in wrong.get(e.name, [])]
    right = sum(1 for _, s in runs if s and s.correct)
    print(f"running {len(runs)} times the tests of {len(exercises)} exercises: with the right bodies (a run per "
          f"chapter), then with each of their {sum(counts.values())} wrong solutions and {right} other right "
          "solutions ...", flush=True)
    # A run stops at its first failure, unless the wrong solution names what a failure must say: that may be
    # a later test's (the one about the mistake's kind), so all the exercise's tests run.
    tests = [UnitTest(spec, [program_of[f"{e.chapter}_test"], spec] + ([] if s and s.says else ["--abort"]),
                      str(build), e.chapter)
             for e, s in runs for spec in [specs[e.chapter] if s is None else f"[{TAG_PREFIX}{e.name}]"]]
    # A shader's exercise is switched in its source, then rebuilt: those runs one at a time, the others at once
    # (the right bodies too: every switch is at 0, the right body, outside run_with_shader_switch).
    in_shader = [i for i, (e, s) in enumerate(runs) if e.glsl and s is not None]
    in_cpp = [i for i in range(len(runs)) if i not in in_shader]
    outcomes = [(False, "")] * len(runs)
    for i, outcome in zip(in_cpp, run_each([tests[i] for i in in_cpp], args.jobs, args.timeout,
                                           environment_of=lambda k: {"RT_WRONG_SOLUTION": runs[in_cpp[k]][1].key}
                                           if runs[in_cpp[k]][1] else {})):
        outcomes[i] = outcome
    for i in in_shader:
        e, s = runs[i]
        outcomes[i] = run_with_shader_switch(out, e, s.number if s else 0, [tests[i]], args)[0]
    caught = accepted = 0
    for (e, s), (passed, output) in zip(runs, outcomes):
        if s is None or s.correct:
            if not passed:
                which = f"{s.source}: {s.key}, the right solution \"{s.mistake}\"" if s else "the right bodies"
                problems.append(f"{e.name if s else e.chapter}: its tests fail with {which}:\n" + output[-2000:])
            accepted += passed and s is not None
            if args.verbose and s:
                print(f"  {s.key:34} {'passes' if passed else 'FAILS'} (a right solution): {s.mistake}")
            continue
        how = "" if passed else failed_test(output)
        # Catch2 wraps a message's lines: compared with every run of white space made one space.
        unsaid = not passed and s.says and " ".join(s.says.split()) not in " ".join(output.split())
        if passed:
            problems.append(f"{s.source}: {s.key} is not caught by {e.chapter}_test \"[{TAG_PREFIX}{e.name}]\": "
                            f"{s.mistake}")
        elif unsaid:
            problems.append(f"{s.source}: {s.key} is caught, but the failure never says \"{s.says}\": {s.mistake}")
        else:
            caught += 1
        if args.verbose or passed or unsaid:
            print(f"  {s.key:34} {'caught' if not passed else 'NOT CAUGHT'}{' by ' + how if how else ''}: {s.mistake}")
    print(f"{caught} of {sum(counts.values())} wrong solutions caught by their own chapter's tests (saying what "
          f"they were asked to); {accepted} of {right} other right solutions pass")
    for p in problems:
        print("  " + p)
    status = 1 if problems else 0
    if not only:
        status |= check_stubbed_at_run_time(out, build, exercises, args)
    return status


def check_stubbed_at_run_time(edition: Path, build: Path, exercises: list[Exercise], args: argparse.Namespace) -> int:
    """CI's check of the student edition, in the switchable edition's build: with every exercise stubbed at run
    time (RT_STUB_EXERCISE=*, and each shader's switch at -1, its chapter's test program rebuilt), the failing
    tests are exactly those tagged with an exercise, each naming it (as `check` in a student edition's build)."""
    shaders = [e for e in exercises if e.glsl]
    for e in shaders:
        set_shader_switch(edition, e, -1)
    try:
        build_test_programs(edition, args.jobs, {f"{e.chapter}_test" for e in shaders})
        results = run_tests(build, None, args.jobs, environment={"RT_STUB_EXERCISE": "*"})
    finally:
        for e in shaders:
            set_shader_switch(edition, e, 0)
    return report_failures_against_tags("student edition (every exercise stubbed at run time)", exercises,
                                        {e.name for e in exercises}, results)


def command_warnings(args: argparse.Namespace) -> int:
    """CI: the student edition's files with exercises compile without a warning (see stub_warnings.py)."""
    build = Path(args.build)
    problems = stub_warnings(source_of_build(build), build, args.jobs)
    for p in problems:
        print(p)
    print(f"{len(problems)} files with stubbed exercises warn" if problems else
          "every file with a stubbed exercise compiles without a warning")
    return 1 if problems else 0


def run_with_shader_switch(edition: Path, exercise, value: int, tests: list[UnitTest],
                           args: argparse.Namespace) -> list[tuple[bool, str]]:
    """Runs `tests` with a shader exercise's body switched to `value` (0 right, K the K-th wrong solution, -1 the
    stub): the edition's shader source is changed and its chapter's test program rebuilt (the shaders are
    embedded when it is built), then switched back."""
    set_shader_switch(edition, exercise, value)
    try:
        build_test_programs(edition, args.jobs, {f"{exercise.chapter}_test"})
        return run_each(tests, args.jobs, getattr(args, "timeout", 300))
    finally:
        set_shader_switch(edition, exercise, 0)


def failed_test(output: str) -> str:
    """The first failing test of a Catch2 run's output, quoted, or how the run ended otherwise."""
    if "timed out after" in output:
        return "a time-out"
    lines = output.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("-----") and i + 1 < len(lines) and lines[i + 1].strip() and i >= 1 and \
                (i < 2 or not lines[i - 2].startswith("-----")):
            return f'"{lines[i + 1].strip()}"'
    return ""


def command_lint(args: argparse.Namespace) -> int:
    """In any build (the full edition too), without running tests: the marks are well formed, every
    [ex:...] tag names a marked exercise, and every marked exercise has a test tagged with it."""
    build = Path(args.build)
    source = source_of_build(build)
    exercises = find_exercises(source)
    names = {e.name for e in exercises}
    tests = unit_tests(build)
    tags = exercise_tags({t.command[0] for t in tests})
    problems = []
    for (program, test), tagged in sorted(tags.items()):
        for tag in tagged:
            if tag not in names:
                problems.append(f"{program}: \"{test}\" is tagged [{TAG_PREFIX}{tag}], but no such exercise is marked")
    tested = {tag for tagged in tags.values() for tag in tagged}
    for e in exercises:
        if e.name not in tested:
            problems.append(f"{e.where()}: exercise {e.name} has no test tagged [{TAG_PREFIX}{e.name}]")
    # A CTest test must be one Catch2 test: a ';' in a test name splits it into two that match nothing.
    for program in sorted({t.command[0] for t in tests}):
        listed = subprocess.run([program, "--list-test-names-only"], capture_output=True, text=True).stdout
        known = {line.strip() for line in listed.splitlines()}
        for t in tests:
            if t.command[0] == program and t.name.strip() not in known:
                problems.append(f"{t.program}: CTest test \"{t.name}\" is no Catch2 test (a ';' in a test name "
                                "splits it: use ',' or ':')")
    print(f"{len(exercises)} exercises marked, {len(tags)} tests tagged [{TAG_PREFIX}...] in {build}")
    for p in problems:
        print("  " + p)
    return 1 if problems else 0


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--root", type=Path, default=ROOT, help="the repository (default: this tool's)")
    commands = parser.add_subparsers(dest="command", required=True)
    commands.add_parser("list", help="every marked exercise")
    m = commands.add_parser("map", help="the course map's \"needs first\" column, from the tests' exercise tags")
    m.add_argument("--check", action="store_true", help="fail where README.md's map or an exercise count "
                   "disagrees")
    for name, text in (("next", "build and run the next exercise left, show its failures"),
                       ("test", "build and run one exercise's tests that need no other exercise left")):
        n = commands.add_parser(name, help=text)
        if name == "test":
            n.add_argument("name", help="the exercise, e.g. ch01.camera_ray")
        n.add_argument("--edition", help="the student edition (default: this repository if it is one, else "
                       "../rt-student, generated if missing)")
        n.add_argument("-j", "--jobs", type=int, default=2, help="build jobs (default 2)")
    g = commands.add_parser("generate", help="write the student edition")
    g.add_argument("out", help="an empty folder outside the repository (or under its ignored build/)")
    g.add_argument("--only", help="stub only these chapters or exercises: ch02 or ch01.camera_ray,ch02.quad")
    g.add_argument("--force", action="store_true", help="overwrite an earlier student edition in OUT")
    for name, text in (("status", "run a build's tests and list exercises done and left"),
                       ("check", "CI: the failing tests of a student edition are exactly its exercises' tests")):
        c = commands.add_parser(name, help=text)
        c.add_argument("--build", required=(name == "check"), help="the build folder (default: the current one "
                       "or build/release)")
        c.add_argument("-j", "--jobs", type=int, default=2, help="tests run in parallel (default 2)")
        if name == "status":
            c.add_argument("-L", "--label", help="one chapter's tests only, e.g. ch02")
            c.add_argument("-v", "--verbose", action="store_true", help="name the failing tests")
    warn = commands.add_parser("warnings", help="CI: a student edition's files with exercises compile without a "
                               "warning (syntax only)")
    warn.add_argument("--build", required=True, help="the edition's build folder, configured with "
                      "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON")
    warn.add_argument("-j", "--jobs", type=int, default=2, help="compilers run in parallel (default 2)")
    lint = commands.add_parser("lint", help="marks well formed, tags naming marked exercises, every exercise tested")
    lint.add_argument("--build", required=True, help="a build folder with the test programs built")
    deps = commands.add_parser("deps", help="which tests depend on which exercise (one build, one run per exercise)")
    deps.add_argument("out", help="a scratch folder for the editions and their build (outside the repository)")
    deps.add_argument("--only", help="these chapters or exercises only: ch03 or ch03.shadow_ray,ch02.quad")
    deps.add_argument("-j", "--jobs", type=int, default=2, help="build jobs and tests run in parallel")
    w = commands.add_parser("wrong", help="CI: each exercise's wrong solutions (tests/wrong_solutions/) are caught "
                            "by its chapter's tests")
    w.add_argument("out", help="a scratch folder for the edition and its build (outside the repository)")
    w.add_argument("--only", help="these chapters or exercises only: ch04 or ch04.cosine_hemisphere")
    w.add_argument("-j", "--jobs", type=int, default=2, help="build jobs and tests run in parallel")
    w.add_argument("--timeout", type=int, default=600, help="seconds a run may take; longer counts as caught "
                   "(default 600)")
    w.add_argument("-v", "--verbose", action="store_true", help="name each wrong solution and the test catching it")
    args = parser.parse_args(argv)
    try:
        return {"list": command_list, "map": command_map, "generate": command_generate, "status": command_status,
                "check": command_check, "warnings": command_warnings, "lint": command_lint, "deps": command_deps,
                "wrong": command_wrong, "next": command_next, "test": command_next}[args.command](args)
    except ToolError as error:
        print(f"exercises.py: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
