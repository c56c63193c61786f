"""The student edition: a copy of the repository in which every marked exercise body throws
"not implemented: chNN.name — see <lesson> § <section>", and still builds with warnings as errors (but in the
code a student writes). Also the switchable edition of `exercises.py deps`, built once, in which any one
exercise is stubbed at run time."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

from .cpp_reader import internal_helpers, tokenize
from .marks import Exercise, ToolError, find_exercises, selected
from .wrong_solutions import WrongSolution, load as load_wrong_solutions

EDITION_MARKER = ".student-edition.json"
SWITCH_HEADER = Path(__file__).resolve().parent / "exercise_switch.hpp"  # copied to common/rt/ of a switchable edition
WARNINGS_HEADER = Path(__file__).resolve().parent / "exercise_warnings.hpp"  # copied to common/rt/ of both editions


def cpp_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def stub_file(text: str, exercises: list[Exercise]) -> str:
    """The file with each exercise's marked lines replaced by a throw (the marks themselves are kept, so the
    student sees where to write and the tools still find the exercise); a shader's by an #error line, which
    makes the driver refuse the shader with the message, and so the C++ that compiles it throw."""
    if exercises and exercises[0].glsl:
        return stub_shader(text, exercises)
    lines = text.split("\n")
    tokens = tokenize(text)
    removed: set[str] = set()
    for exercise in exercises:
        removed |= {t.text for t in tokens if exercise.begin < t.line < exercise.end and t.kind == "ident"}
    # Helpers used only by removed code would become "defined but not used" errors: mark them.
    maybe_unused: dict[int, int] = {}
    for helper in internal_helpers(tokens):
        if helper.name in removed:
            maybe_unused.setdefault(helper.line, helper.col)
    out: list[str] = []
    by_begin = {e.begin: e for e in exercises}
    number = 0
    while number < len(lines):
        line = lines[number]
        exercise = by_begin.get(number)
        if exercise is None:
            if number in maybe_unused:
                col = maybe_unused[number]
                line = line[:col] + "[[maybe_unused]] " + line[col:]
            out.append(line)
            number += 1
            continue
        indent = re.match(r"\s*", lines[exercise.begin + 1] if exercise.end > exercise.begin + 1 else line).group(0)
        out.append(f"{indent_of(line)}RT_YOUR_CODE_BEGIN")
        out.append(line)
        unused = exercise.parameters + exercise.locals
        if unused:
            casts = " ".join(f"((void){n[3:]}, ...);" if n.startswith("...") else f"(void){n};" for n in unused)
            out.append(f"{indent}{casts}")
        out.append(f"{indent}throw std::logic_error({cpp_string(not_implemented(exercise))});")
        out.append(lines[exercise.end])
        out.append(f"{indent_of(line)}RT_YOUR_CODE_END")
        number = exercise.end + 1
    return with_warnings_header(add_include("\n".join(out), "<stdexcept>"))


def indent_of(line: str) -> str:
    return re.match(r"\s*", line).group(0)


def with_warnings_header(text: str) -> str:
    return add_include(text, '"rt/exercise_warnings.hpp"')


def stub_shader(text: str, exercises: list[Exercise]) -> str:
    lines = text.split("\n")
    for exercise in sorted(exercises, key=lambda e: e.begin, reverse=True):
        lines[exercise.begin + 1 : exercise.end] = [f"#error {not_implemented(exercise)}"]
    return "\n".join(lines)


def shader_switch(exercise: Exercise) -> str:
    """The preprocessor name that chooses a shader exercise's body in the switchable edition: 0 the right body,
    K its K-th wrong solution, -1 the stub. A shader is compiled when the program runs, from text embedded when
    it is built, so `deps` and `wrong` set it in the edition's source and rebuild (set_shader_switch)."""
    return "RT_EXERCISE_" + exercise.name.replace(".", "_")


def set_shader_switch(edition: Path, exercise: Exercise, value: int) -> None:
    path = edition / exercise.file
    name = shader_switch(exercise)
    text, count = re.subn(rf"^#define {name} -?\d+$", f"#define {name} {value}", path.read_text(encoding="utf-8"),
                          flags=re.MULTILINE)
    if count != 1:
        raise ToolError(f"{path}: no switch #define {name} (not a switchable edition?)")
    path.write_text(text, encoding="utf-8")


def switch_shader(text: str, exercises: list[Exercise], wrong: dict[str, list[WrongSolution]]) -> str:
    lines = text.split("\n")
    for exercise in sorted(exercises, key=lambda e: e.begin, reverse=True):
        name = shader_switch(exercise)
        switch = [f"#define {name} 0", f"#if {name} == -1", f"#error {not_implemented(exercise)}"]
        for s in wrong.get(exercise.name, []):
            switch += [f"#elif {name} == {s.number}"] + s.body
        switch += ["#else"] + lines[exercise.begin + 1 : exercise.end] + ["#endif"]
        lines[exercise.begin + 1 : exercise.end] = switch
    return "\n".join(lines)


def switch_file(text: str, exercises: list[Exercise], wrong: dict[str, list[WrongSolution]] | None = None) -> str:
    """For `deps` and `wrong`: each exercise keeps its body, which first throws as the student edition's does
    when the environment variable RT_STUB_EXERCISE names it, and beside which its wrong solutions are compiled,
    the K-th run instead when RT_WRONG_SOLUTION is chNN.name:K (see exercise_switch.hpp). A shader's exercises
    are chosen by a #define instead (shader_switch)."""
    if exercises and exercises[0].glsl:
        return switch_shader(text, exercises, wrong or {})
    lines = text.split("\n")
    for exercise in sorted(exercises, key=lambda e: e.begin, reverse=True):
        indent = re.match(r"\s*", lines[exercise.begin + 1]).group(0)
        switch = [
            f"{indent}static const bool stubbed_here = rt::exercise_switch::stubbed({cpp_string(exercise.name)});",
            f"{indent}if (stubbed_here) throw std::logic_error({cpp_string(not_implemented(exercise))});",
        ]
        solutions = (wrong or {}).get(exercise.name, [])
        if solutions:
            right = lines[exercise.begin + 1 : exercise.end]
            switch.append(f"{indent}static const int wrong_here = "
                          f"rt::exercise_switch::wrong_solution({cpp_string(exercise.name)});")
            for s in solutions:
                switch.append(f"{indent}{'if' if s.number == 1 else '} else if'} (wrong_here == {s.number}) {{")
                switch += ["    " + line if line.strip() else line for line in s.body]
            switch.append(f"{indent}}} else {{")
            switch += ["    " + line if line.strip() else line for line in right]
            switch.append(f"{indent}}}")
            lines[exercise.begin + 1 : exercise.end] = switch
            end_marker = exercise.begin + 1 + len(switch)
        else:
            lines[exercise.begin + 1 : exercise.begin + 1] = switch
            end_marker = exercise.end + len(switch)
        marker = indent_of(lines[exercise.begin])
        lines.insert(end_marker + 1, f"{marker}RT_YOUR_CODE_END")
        lines.insert(exercise.begin, f"{marker}RT_YOUR_CODE_BEGIN")
    return with_warnings_header(add_include(add_include("\n".join(lines), "<stdexcept>"), '"rt/exercise_switch.hpp"'))


def not_implemented(exercise: Exercise) -> str:
    return f"not implemented: {exercise.name} — see {exercise.reference()}"


def add_include(text: str, header: str) -> str:
    """The text with `#include <header>` after its last include, unless it has it already."""
    if re.search(r"^\s*#\s*include\s*" + re.escape(header), text, re.MULTILINE):
        return text
    lines = text.split("\n")
    last = None
    for i, line in enumerate(lines):
        if re.match(r"^\s*#\s*include\b", line):
            last = i
        elif last is not None and line.strip() and not line.lstrip().startswith(("#", "//")):
            break
    if last is None:
        last = next((i for i, line in enumerate(lines) if re.match(r"^\s*#\s*pragma\s+once", line)), -1)
    lines.insert(last + 1, f"#include {header}")
    return "\n".join(lines)


def edition_note(chosen: list[Exercise]) -> str:
    chapters = ", ".join(sorted({e.chapter for e in chosen}))
    return (f"> **Student edition.** {len(chosen)} functions of this copy ({chapters}) throw \"not implemented\" "
            "until you write them. `python3 tests/tools/exercises.py next` builds only what the next exercise's "
            "tests need, runs them and shows the failures with the file to edit and the lesson section; run it "
            "again after each change (`test ch02.quad`: one exercise; `status`: the exercises done and left). "
            "Each lesson's \"Exercises\" section says what to write. A compiler warning in what you write "
            "between `RT_YOUR_CODE_BEGIN` and `RT_YOUR_CODE_END` stays a warning; everywhere else warnings are "
            "errors, as in the course's own build.\n\n")


def repository_files(root: Path) -> list[Path]:
    """The files of the working tree that git does not ignore (or, outside git, every file but build*/)."""
    try:
        listing = subprocess.run(
            ["git", "-C", str(root), "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
            check=True, capture_output=True,
        ).stdout.decode("utf-8")
        files = sorted({Path(p) for p in listing.split("\0") if p})
        return [p for p in files if (root / p).is_file()]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for dirpath, dirnames, filenames in os.walk(root):
            dirnames[:] = [d for d in dirnames if not d.startswith("build") and d != ".git"]
            for f in filenames:
                files.append((Path(dirpath) / f).relative_to(root))
        return sorted(files)


def write_if_changed(path: Path, data: bytes) -> None:
    """Leaves an identical file untouched, so a regenerated edition rebuilds only what changed."""
    if path.is_file() and path.read_bytes() == data:
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)


def generate(root: Path, out: Path, only: list[str], force: bool, switchable: bool = False) -> list[Exercise]:
    """Writes the student edition, with the chosen exercises (all when `only` is empty) stubbed; with
    `switchable`, the edition of `deps` instead: the chosen exercises written, each stubbed at run time when
    RT_STUB_EXERCISE names it."""
    out = out.resolve()
    root = root.resolve()
    if out == root or root.is_relative_to(out):
        raise ToolError(f"generate: {out}: the edition cannot be written over the repository")
    if out.is_relative_to(root):
        top = out.relative_to(root).parts[0]
        ignored = subprocess.run(["git", "-C", str(root), "check-ignore", "-q", top]).returncode == 0
        if not ignored:
            raise ToolError(f"generate: {out}: inside the repository but not in an ignored folder (use build/... "
                            "or a folder outside it)")
    if out.exists() and any(out.iterdir()):
        if not (out / EDITION_MARKER).is_file():
            raise ToolError(f"generate: {out}: exists and is not a student edition; choose an empty folder")
        if not force:
            raise ToolError(f"generate: {out}: a student edition is already there (a student's work?); add --force "
                            "to overwrite it")
    all_exercises = find_exercises(root)
    chosen = [e for e in all_exercises if selected(e, only)]
    unknown = [o for o in only if not any(e.name == o or e.chapter == o for e in all_exercises)]
    if unknown:
        raise ToolError(f"generate: --only {','.join(unknown)}: no such exercise or chapter (see `exercises.py list`)")
    by_file: dict[Path, list[Exercise]] = {}
    for e in chosen:
        by_file.setdefault(e.file, []).append(e)
    files = repository_files(root)
    switch_header, warnings_header = Path("common/rt") / SWITCH_HEADER.name, Path("common/rt") / WARNINGS_HEADER.name
    wanted = ({out / f for f in files} | {out / EDITION_MARKER, out / warnings_header} |
              ({out / switch_header} if switchable else set()))
    if out.exists():
        for path in sorted(out.rglob("*"), reverse=True):
            if path.is_file() and path not in wanted and not path.is_relative_to(out / "build"):
                path.unlink()
    wrong = load_wrong_solutions(root, all_exercises) if switchable else {}  # checked whole; used for `chosen`
    for relative in files:
        source = root / relative
        data = source.read_bytes()
        if relative in by_file:
            text = data.decode("utf-8")
            rewritten = switch_file(text, by_file[relative], wrong) if switchable else stub_file(text, by_file[relative])
            data = rewritten.encode("utf-8")
        elif relative == Path("README.md") and chosen and not switchable:
            data = edition_note(chosen).encode("utf-8") + data
        write_if_changed(out / relative, data)
        shutil.copymode(source, out / relative)
    write_if_changed(out / warnings_header, WARNINGS_HEADER.read_bytes())
    if switchable:
        write_if_changed(out / switch_header, SWITCH_HEADER.read_bytes())
    marker = {"source": str(root), "switchable" if switchable else "stubbed": [e.name for e in chosen]}
    write_if_changed(out / EDITION_MARKER, (json.dumps(marker, indent=2) + "\n").encode("utf-8"))
    return chosen
