"""A build's unit tests: the Catch2 tests CTest knows, their [ex:...] tags, running them, and what the
results say about each exercise."""

from __future__ import annotations

import json
import os
import re
import subprocess
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from .marks import NOT_IMPLEMENTED_RE, TAG_PREFIX, Exercise, ToolError


@dataclass
class TestResult:
    name: str
    program: str  # the test executable's file name, "ch02_test"
    label: str  # the CTest label, "ch02"
    passed: bool
    output: str
    tags: list[str] = field(default_factory=list)  # the exercises it depends on, from [ex:...] tags

    def not_implemented(self) -> list[str]:
        return sorted(set(NOT_IMPLEMENTED_RE.findall(self.output)))


def source_of_build(build: Path) -> Path:
    cache = build / "CMakeCache.txt"
    if not cache.is_file():
        raise ToolError(f"{build}: not a CMake build folder (no CMakeCache.txt); configure and build it first")
    for line in cache.read_text(encoding="utf-8", errors="replace").splitlines():
        if line.startswith("CMAKE_HOME_DIRECTORY:"):
            return Path(line.split("=", 1)[1])
    raise ToolError(f"{cache}: no CMAKE_HOME_DIRECTORY")


@dataclass
class UnitTest:
    name: str
    command: list[str]
    directory: str
    label: str

    @property
    def program(self) -> str:
        return Path(self.command[0]).name


def unit_tests(build: Path) -> list[UnitTest]:
    """The build's unit tests as CTest knows them: every test run by a Catch2 program (`*_test`). The
    end-to-end tests of the executables (tests/cli, which need the executables built) are not among them."""
    shown = subprocess.run(["ctest", "--test-dir", str(build), "--show-only=json-v1"], capture_output=True,
                           text=True)
    if shown.returncode != 0:
        raise ToolError(f"ctest --show-only failed in {build}: {shown.stderr.strip()}")
    tests = []
    for test in json.loads(shown.stdout).get("tests", []):
        command = test.get("command") or []
        if not command or not Path(command[0]).name.endswith("_test"):
            continue
        properties = {p.get("name"): p.get("value") for p in test.get("properties", [])}
        labels = properties.get("LABELS") or [""]
        tests.append(UnitTest(test["name"], command, properties.get("WORKING_DIRECTORY") or str(build), labels[0]))
    return tests


def exercise_tags(programs: set[str]) -> dict[tuple[str, str], list[str]]:
    """(program, test name) → the exercises named by its [ex:...] tags, asked of each Catch2 program."""
    tagged: dict[tuple[str, str], list[str]] = {}
    for program in sorted(programs):
        if not Path(program).is_file():
            raise ToolError(f"{program}: not built; build the test programs first")
        listed = subprocess.run([program, "--list-tags"], capture_output=True, text=True)
        tags = sorted(set(re.findall(r"\[" + re.escape(TAG_PREFIX) + r"([^\]]+)\]", listed.stdout)))
        for tag in tags:
            names = subprocess.run([program, f"[{TAG_PREFIX}{tag}]", "--list-test-names-only"], capture_output=True,
                                   text=True)
            for name in names.stdout.splitlines():
                if name.strip():
                    tagged.setdefault((Path(program).name, name.strip()), []).append(tag)
    return tagged


def run_one(test: UnitTest, timeout: int, environment: dict[str, str] | None = None) -> tuple[bool, str]:
    """Runs one test as CTest would, with `environment` added to this process's; (passed, its output)."""
    try:
        done = subprocess.run(test.command, cwd=test.directory, capture_output=True, timeout=timeout,
                              env={**os.environ, **environment} if environment else None)
    except subprocess.TimeoutExpired as expired:
        output = (expired.stdout or b"") + (expired.stderr or b"")
        return False, output.decode("utf-8", "replace") + f"\ntimed out after {timeout} s"
    output = (done.stdout + done.stderr).decode("utf-8", "replace")
    return done.returncode == 0, output


def run_each(tests: list[UnitTest], jobs: int, timeout: int = 300,
             environment_of: Callable[[int], dict[str, str]] | None = None) -> list[tuple[bool, str]]:
    """Runs the tests, `jobs` at a time, test i with environment_of(i) added: (passed, output) of each."""
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        return list(pool.map(lambda i: run_one(tests[i], timeout, environment_of(i) if environment_of else None),
                             range(len(tests))))


def run_tests(build: Path, label: str | None, jobs: int, timeout: int = 300,
              environment: dict[str, str] | None = None) -> list[TestResult]:
    """Runs the build's unit tests (one chapter's with `label`), each alone as CTest would run it (with
    `environment` added to this process's)."""
    tests = [t for t in unit_tests(build) if not label or t.label == label]
    tags = exercise_tags({t.command[0] for t in tests})
    print(f"running {len(tests)} unit tests{' labelled ' + label if label else ''} in {build} ...", flush=True)
    outcomes = run_each(tests, jobs, timeout, environment_of=(lambda _: environment) if environment else None)
    return [TestResult(t.name, t.program, t.label, passed, output, tags.get((t.program, t.name), []))
            for t, (passed, output) in zip(tests, outcomes)]


def summarise(exercises: list[Exercise], results: list[TestResult], label: str | None) -> dict[str, dict]:
    """Per exercise: its tests, and whether it is left (its body is still the throw of the student
    edition), done (written, and every test tagged with it passes), written (its failing tests also need an
    exercise left, named in `blocked_by`), failing (a test tagged with it fails for another reason: a bug)
    or untested."""
    summary: dict[str, dict] = {}
    for e in exercises:
        summary.setdefault(e.name, {"exercise": e, "tests": [], "state": "done", "blocked_by": set()})
    for r in results:
        for name in r.tags:
            if name in summary:
                summary[name]["tests"].append(r)
    stubbed = {e.name for e in exercises if e.stubbed}
    for name, entry in summary.items():
        tests = entry["tests"]
        if name in stubbed or any(name in r.not_implemented() for r in results):
            entry["state"] = "left"
        elif not tests:
            entry["state"] = "untested"
        elif any(not r.passed for r in tests):
            failing = [r for r in tests if not r.passed]
            entry["blocked_by"] = {t for r in failing for t in r.tags if t in stubbed}
            # Written, and its only failing tests also need an exercise left: it waits for that one.
            blocked = all(set(r.tags) & stubbed or set(r.not_implemented()) - {name} for r in failing)
            entry["state"] = "written" if blocked else "failing"
    if label:
        summary = {k: v for k, v in summary.items() if v["exercise"].chapter == label}
    return summary


def next_exercise(entries: list[dict], left: set[str]) -> tuple[Exercise | None, set[str]]:
    """The exercise of `entries` to write next, and what it waits for. `left` holds every exercise left in the
    whole course, not only in these entries: an exercise is ready when one of its tests needs no other
    exercise left. The ready one whose tests need the fewest is chosen, by name among equals; when none is
    ready, (None, the exercises left elsewhere that the closest one waits for)."""
    def waits_for(x: dict) -> set[str]:
        needs = [set(r.tags) & left - {x["exercise"].name} for r in x["tests"]]
        return min(needs, key=len) if needs else set()

    candidates = sorted((x for x in entries if x["state"] == "left"), key=lambda x: x["exercise"].name)
    if not candidates:
        return None, set()
    best = min(candidates, key=lambda x: len(waits_for(x)))
    blocking = waits_for(best)
    return (None, blocking) if blocking else (best["exercise"], set())