"""Exercise marks in the chapter sources, their names, and the lesson section that explains each."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from .cpp_reader import Token, enclosing_function, locals_before, matching, tokenize

GLSL_SUFFIXES = {".glsl", ".comp", ".frag", ".vert"}  # a shader's exercises are stubbed by #error, not a throw
SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc", ".hh", ".cxx", ".inl"} | GLSL_SUFFIXES
SCANNED_FOLDERS = ("chapters", "common")  # where marks may be; tests/ holds none
MARK_RE = re.compile(r"^\s*//\s*EXERCISE\(([^)]*)\)(?:\s*§\s*(.*?))?\s*$")
END_RE = re.compile(r"^\s*//\s*END EXERCISE\b")
NAME_RE = re.compile(r"^ch(\d\d)\.[a-z][a-z0-9_]*$")
NOT_IMPLEMENTED_RE = re.compile(r"not\s+implemented:\s+(ch\d\d\.[a-z][a-z0-9_]*)")  # a report may wrap its lines
TAG_PREFIX = "ex:"


class ToolError(Exception):
    """A problem the user must fix; printed as one line, exit status 2."""


@dataclass
class Exercise:
    name: str  # "ch02.sphere_stable"
    file: Path  # relative to the root
    begin: int  # 0-based line of // EXERCISE(...)
    end: int  # 0-based line of // END EXERCISE
    function: str = ""
    parameters: list[str] = field(default_factory=list)
    locals: list[str] = field(default_factory=list)
    stubbed: bool = False  # its body is still the student edition's throw: not written yet
    lesson: str = ""  # "chapters/02_intersection/README.md"
    section: str = ""  # "Spheres": the heading of the lesson's section that teaches it, named by the mark

    @property
    def glsl(self) -> bool:  # in a shader, which C++ compiles when it runs (chapter 11)
        return self.file.suffix in GLSL_SUFFIXES

    @property
    def chapter(self) -> str:
        return self.name.split(".")[0]

    @property
    def short(self) -> str:
        return self.name.split(".", 1)[1]

    def where(self) -> str:
        return f"{self.file}:{self.begin + 1}"

    def reference(self) -> str:
        return f"{self.lesson} § {self.section}" if self.section else self.lesson


def chapter_folder(root: Path, chapter: str) -> Path | None:
    number = chapter[2:]
    found = sorted((root / "chapters").glob(f"{number}_*"))
    return found[0] if found else None


def lesson_headings(readme: Path) -> set[str]:
    """The headings (## to ####, outside code blocks) of a lesson, without their backticks."""
    headings = set()
    in_code = False
    for line in readme.read_text(encoding="utf-8").splitlines():
        if line.lstrip().startswith("```"):
            in_code = not in_code
        m = None if in_code else re.match(r"^#{2,4}\s+(.*?)\s*#*\s*$", line)
        if m:
            headings.add(m.group(1).replace("`", ""))
    return headings


def lesson_section(root: Path, exercise: Exercise, section: str) -> tuple[str, str | None]:
    """The lesson of an exercise (its chapter's README) and the section its mark names (`// EXERCISE(name) §
    heading`), or an error: the mark names none, or the lesson has no such heading."""
    folder = chapter_folder(root, exercise.chapter)
    if folder is None:
        return "", None
    readme = folder / "README.md"
    lesson = readme.relative_to(root).as_posix()
    if not section:
        return lesson, (f"{exercise.where()}: EXERCISE({exercise.name}) names no lesson section: add § and a heading "
                        f"of {lesson}, the section that teaches it (// EXERCISE({exercise.name}) § Heading)")
    if not readme.is_file() or section.replace("`", "") not in lesson_headings(readme):
        return lesson, (f"{exercise.where()}: EXERCISE({exercise.name}) names § {section}, but {lesson} has no such "
                        "heading: name the heading of the section that teaches it")
    return lesson, None


def source_files(root: Path) -> list[Path]:
    files = []
    for folder in SCANNED_FOLDERS:
        base = root / folder
        if base.is_dir():
            for path in sorted(base.rglob("*")):
                if path.suffix in SOURCE_SUFFIXES and path.is_file():
                    files.append(path)
    return files


def find_exercises(root: Path) -> list[Exercise]:
    """Every marked exercise under chapters/ and common/, checked: names chNN.snake_case matching the
    chapter folder, marks paired and not nested, inside a function body, ending it."""
    exercises: list[Exercise] = []
    errors: list[str] = []
    for path in source_files(root):
        text = path.read_text(encoding="utf-8")
        lines = text.split("\n")
        relative = path.relative_to(root)
        found: list[Exercise] = []
        open_mark: Exercise | None = None
        for number, line in enumerate(lines):
            m = MARK_RE.match(line)
            if m:
                name = m.group(1).strip()
                where = f"{relative.as_posix()}:{number + 1}"
                if open_mark is not None:
                    errors.append(f"{where}: EXERCISE({name}) inside EXERCISE({open_mark.name}) (line "
                                  f"{open_mark.begin + 1}); close it with // END EXERCISE first")
                name_match = NAME_RE.match(name)
                if not name_match:
                    errors.append(f"{where}: exercise name \"{name}\" must be chNN.snake_case, e.g. ch02.sphere")
                parts = relative.parts
                if name_match and parts[0] == "chapters" and not parts[1].startswith(name_match.group(1) + "_"):
                    errors.append(f"{where}: exercise {name} is in chapter folder {parts[1]}; name it ch{parts[1][:2]}.…")
                open_mark = Exercise(name, relative, number, -1, section=m.group(2) or "")
            elif END_RE.match(line):
                if open_mark is None:
                    errors.append(f"{relative.as_posix()}:{number + 1}: END EXERCISE without an EXERCISE(...) before it")
                else:
                    open_mark.end = number
                    found.append(open_mark)
                    open_mark = None
        if open_mark is not None:
            errors.append(f"{open_mark.where()}: EXERCISE({open_mark.name}) has no // END EXERCISE")
        if not found:
            continue
        # An edition's RT_YOUR_CODE_BEGIN/END (rt/exercise_warnings.hpp) stand around the marks: not code.
        tokens = [t for t in tokenize(text) if t.text not in ("RT_YOUR_CODE_BEGIN", "RT_YOUR_CODE_END")]
        for exercise in found:
            function = enclosing_function(tokens, exercise.begin)
            if function is None:
                errors.append(f"{exercise.where()}: EXERCISE({exercise.name}) is not inside a function body")
                continue
            after = next((t for t in tokens if t.line > exercise.end), None)
            if after is None or tokens.index(after) != function.body_close:
                errors.append(f"{exercise.where()}: EXERCISE({exercise.name}) must end the body of "
                              f"{function.name}(): its // END EXERCISE (line {exercise.end + 1}) must be followed "
                              "by the function's closing brace")
                continue
            inside = [t for t in tokens if exercise.begin < t.line < exercise.end]
            if any(t.text == "}" for t in inside) and matching_balance(inside) != 0:
                errors.append(f"{exercise.where()}: the braces between EXERCISE({exercise.name}) and END EXERCISE do "
                              "not balance")
                continue
            body = "\n".join(lines[exercise.begin + 1 : exercise.end])
            # (The switchable edition of `deps` keeps the body after its throw: not stubbed.)
            # (A shader's stub is an #error line; its switchable body an #if on RT_EXERCISE_chNN_name.)
            exercise.stubbed = (f'"not implemented: {exercise.name} ' in body
                                or f"#error not implemented: {exercise.name} " in body) and \
                "exercise_switch::" not in body and not re.search(r"^\s*#if RT_EXERCISE_", body, re.MULTILINE)
            exercise.function = function.name
            exercise.parameters = function.parameters
            exercise.locals = locals_before(tokens, function, exercise.begin)
            exercise.lesson, error = lesson_section(root, exercise, exercise.section)
            if error:
                errors.append(error)
                continue
            exercises.append(exercise)
    if errors:
        raise ToolError("\n".join(errors))
    return exercises


def matching_balance(tokens: list[Token]) -> int:
    return sum(1 for t in tokens if t.text == "{") - sum(1 for t in tokens if t.text == "}")


def selected(exercise: Exercise, only: list[str]) -> bool:
    return not only or any(exercise.name == o or exercise.chapter == o for o in only)
