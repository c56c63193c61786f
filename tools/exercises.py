#!/usr/bin/env python3
"""The course as unit-test exercises: find the marked exercises, write the student edition, and say which
exercises are done.

A chapter source marks the statements a student writes, inside one function body:

    Vec3 sphere_normal(const Sphere& sphere, const Vec3& p) {
        // EXERCISE(ch02.sphere_normal)
        ...the statements...
        // END EXERCISE
    }

The END line must be followed by the closing brace of the function. Tests that depend on an exercise carry
the Catch2 tag [ex:ch02.sphere_normal] (a test may carry several).

  exercises.py list                     every exercise: name, file:line, function, lesson section
  exercises.py generate OUT             the student edition in OUT: each marked body becomes a line that
                                        throws "not implemented: chNN.name — see <lesson> § <section>"
  exercises.py status [--build DIR]     runs a build's unit tests, lists per chapter exercises done and left
  exercises.py lint --build DIR         any build: every [ex:...] tag names a marked exercise, every
                                        exercise has a tagged test (no test is run)
  exercises.py deps SCRATCH [--only ch03] which tests depend on which exercise: one exercise stubbed at a
                                        time, rebuilt and tested; prints the tags each test needs
  exercises.py check --build DIR        CI: in a student edition's build, the failing tests are exactly
                                        the tests tagged with an exercise stubbed, each naming it (in the
                                        full edition's build: every unit test passes)

Only the Python 3 standard library is used (Debian 12: `apt-get install python3`).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc", ".hh", ".cxx", ".inl"}
SCANNED_FOLDERS = ("chapters", "common")  # where marks may be; tests/ and tools/ hold none
EDITION_MARKER = ".student-edition.json"

MARK_RE = re.compile(r"^\s*//\s*EXERCISE\(([^)]*)\)")
END_RE = re.compile(r"^\s*//\s*END EXERCISE\b")
NAME_RE = re.compile(r"^ch(\d\d)\.[a-z][a-z0-9_]*$")
NOT_IMPLEMENTED_RE = re.compile(r"not implemented: (ch\d\d\.[a-z][a-z0-9_]*)")
TAG_PREFIX = "ex:"


class ToolError(Exception):
    """A problem the user must fix; printed as one line, exit status 2."""


# ----------------------------------------------------------------------------------------------------------
# A small C++ lexer: enough to find the function around a mark, its parameters, the locals declared before
# the mark, and the file's internal-linkage helpers. Comments, strings and preprocessor lines are skipped.

KEYWORDS = {
    "alignas", "alignof", "and", "asm", "auto", "bool", "break", "case", "catch", "char", "char8_t", "char16_t",
    "char32_t", "class", "co_await", "co_return", "co_yield", "concept", "const", "consteval", "constexpr",
    "constinit", "const_cast", "continue", "decltype", "default", "delete", "do", "double", "dynamic_cast",
    "else", "enum", "explicit", "export", "extern", "false", "float", "for", "friend", "goto", "if", "inline",
    "int", "long", "mutable", "namespace", "new", "noexcept", "not", "nullptr", "operator", "or", "private",
    "protected", "public", "register", "reinterpret_cast", "requires", "return", "short", "signed", "sizeof",
    "static", "static_assert", "static_cast", "struct", "switch", "template", "this", "thread_local", "throw",
    "true", "try", "typedef", "typeid", "typename", "union", "unsigned", "using", "virtual", "void",
    "volatile", "wchar_t", "while",
}
STATEMENT_KEYWORDS = {
    "return", "if", "for", "while", "do", "switch", "throw", "case", "default", "goto", "break", "continue",
    "using", "typedef", "static_assert", "co_return", "else", "try", "delete", "namespace", "struct", "class",
    "enum", "union", "template", "friend", "asm",
}
TOKEN_RE = re.compile(
    r"""(?P<ws>[ \t\r\f\v]+)
      | (?P<nl>\n)
      | (?P<comment>//[^\n]*|/\*.*?\*/)
      | (?P<raw>R"(?P<delim>[^(\s]*)\(.*?\)(?P=delim)")
      | (?P<string>(?:u8|u|U|L)?"(?:\\.|[^"\\\n])*")
      | (?P<char>(?:u8|u|U|L)?'(?:\\.|[^'\\\n])+')
      | (?P<number>\.?\d(?:[\w.']|[eEpP][+-])*)
      | (?P<ident>[A-Za-z_]\w*)
      | (?P<punct>::|->\*?|\.\.\.|<<=|>>=|&&|\|\||==|!=|<=|>=|\+\+|--|[-+*/%&|^!=<>]=?|[{}()\[\];,.?:~#])
      | (?P<other>.)""",
    re.VERBOSE | re.DOTALL,
)


@dataclass
class Token:
    text: str
    kind: str  # ident, number, string, punct
    line: int  # 0-based
    col: int


def tokenize(text: str) -> list[Token]:
    tokens: list[Token] = []
    line, line_start, pos = 0, 0, 0
    at_line_start = True  # only whitespace so far on this line: a '#' starts a preprocessor line
    while pos < len(text):
        m = TOKEN_RE.match(text, pos)
        assert m is not None
        kind = m.lastgroup if m.lastgroup != "delim" else "raw"
        value = m.group(0)
        if kind == "punct" and value == "#" and at_line_start:
            # A preprocessor line, with its backslash continuations: not C++ tokens.
            end = pos
            while True:
                end = text.find("\n", end)
                if end == -1:
                    end = len(text)
                    break
                if text[end - 1] != "\\":
                    break
                line += 1
                line_start = end + 1
                end += 1
            pos = end
            continue
        if kind in ("ident", "number", "string", "char", "raw", "punct", "other"):
            if kind in ("string", "char", "raw"):
                kind = "string"
            tokens.append(Token(value, kind, line, pos - line_start))
            at_line_start = False
        elif kind == "nl":
            at_line_start = True
        newlines = value.count("\n")
        if newlines:
            line += newlines
            line_start = pos + value.rfind("\n") + 1
        pos = m.end()
    return tokens


def matching(tokens: list[Token], index: int) -> int:
    """The index of the bracket that closes (or opens) tokens[index]."""
    pairs = {"(": ")", "[": "]", "{": "}"}
    opening = tokens[index].text
    if opening in pairs:
        closing, step = pairs[opening], 1
    else:
        closing = {v: k for k, v in pairs.items()}[opening]
        step = -1
    depth = 0
    i = index
    while 0 <= i < len(tokens):
        t = tokens[i].text
        if t == opening:
            depth += 1
        elif t == closing:
            depth -= 1
            if depth == 0:
                return i
        i += step
    raise ValueError("unbalanced brackets")


def split_top_level(tokens: list[Token], separator: str = ",") -> list[list[Token]]:
    """Splits on `separator` outside (), [], {} and template angle brackets."""
    parts: list[list[Token]] = [[]]
    depth = 0
    angle = 0
    for t in tokens:
        if t.text in "([{":
            depth += 1
        elif t.text in ")]}":
            depth -= 1
        elif t.text == "<" and depth == 0 and parts[-1] and parts[-1][-1].kind == "ident":
            angle += 1
        elif t.text == ">" and depth == 0 and angle > 0:
            angle -= 1
        elif t.text == ">>" and depth == 0 and angle > 0:
            angle = max(0, angle - 2)
        if t.text == separator and depth == 0 and angle == 0:
            parts.append([])
        else:
            parts[-1].append(t)
    return [p for p in parts if p]


def parameter_names(params: list[Token]) -> list[str]:
    """The names of a parameter list's named parameters (`const Ray& ray, int` gives ["ray"])."""
    names = []
    for part in split_top_level(params):
        # Drop a default argument and attributes.
        cut = [t for t in part]
        for i, t in enumerate(cut):
            if t.text == "=":
                cut = cut[:i]
                break
        while cut and cut[-1].text == "]":  # an array parameter: `int a[3]`
            cut = cut[: matching(cut, len(cut) - 1)]
        if len(cut) < 2:
            continue
        last, before = cut[-1], cut[-2]
        if last.kind != "ident" or last.text in KEYWORDS or before.text == "::":
            continue
        names.append(("..." if any(t.text == "..." for t in cut) else "") + last.text)
    return names


@dataclass
class Function:
    name: str
    parameters: list[str]
    body_open: int  # token index of the body's '{'
    body_close: int  # token index of its '}'


def enclosing_function(tokens: list[Token], line: int) -> Function | None:
    """The innermost function (or lambda) whose body is open on `line`."""
    stack: list[int] = []
    for i, t in enumerate(tokens):
        if t.line >= line:
            break
        if t.text == "{":
            stack.append(i)
        elif t.text == "}" and stack:
            stack.pop()
    for open_index in reversed(stack):
        i = skip_member_initialisers(tokens, open_index - 1)
        # Walk back over what may follow a parameter list: cv, ref and noexcept qualifiers, a trailing return
        # type, attributes, override/final.
        while i >= 0 and tokens[i].text != ")":
            if tokens[i].text in (";", "{", "}", "="):
                i = -1
                break
            if tokens[i].text == "]":
                i = matching(tokens, i)
            i -= 1
        if i < 0:
            continue
        close = i
        open_paren = matching(tokens, close)
        name_index = open_paren - 1
        if name_index < 0:
            continue
        name_token = tokens[name_index]
        if name_token.text == "]":
            name = "lambda"
        elif name_token.kind == "ident" and name_token.text not in ("if", "for", "while", "switch", "catch"):
            name = name_token.text
        elif name_token.kind == "punct":
            # operator() and friends: the word `operator` and what follows it.
            j = name_index
            while j >= 0 and tokens[j].text != "operator" and name_index - j < 4:
                j -= 1
            if j < 0 or tokens[j].text != "operator":
                continue
            name = "operator" + "".join(t.text for t in tokens[j + 1 : open_paren])
        else:
            continue
        return Function(name, parameter_names(tokens[open_paren + 1 : close]), open_index,
                        matching(tokens, open_index))
    return None


def skip_member_initialisers(tokens: list[Token], i: int) -> int:
    """From the token before a body's '{': past a constructor's `: a_(x), b_{y}` to the token before ':'."""
    j = i
    while j >= 1 and tokens[j].text in (")", "}"):
        start = matching(tokens, j)
        if start < 2 or tokens[start - 1].kind != "ident":
            return i
        before = tokens[start - 2].text
        if before == ":":
            return start - 3
        if before != ",":
            return i
        j = start - 3
    return i


def declared_locals(statement: list[Token]) -> list[str]:
    """The variables a block-scope statement declares (`const Vec2 corner{...};` gives ["corner"])."""
    if not statement or statement[0].text in STATEMENT_KEYWORDS or statement[0].kind != "ident":
        return []
    names = []
    for part_index, part in enumerate(split_top_level(statement)):
        j = 0
        depth = 0
        while j < len(part):
            t = part[j].text
            if t == "[" and depth == 0 and j > 0 and part[j - 1].text in ("auto", "&", "&&"):
                # A structured binding: auto [a, b] = ...
                close = matching(part, j)
                names += [x.text for x in part[j + 1 : close] if x.kind == "ident"]
                j = -1
                break
            if t in ("=", "{", "(", "[") and depth == 0:
                break
            if t == "<":
                depth += 1
            elif t == ">" and depth > 0:
                depth -= 1
            j += 1
        if j <= 0:
            continue
        name = part[j - 1]
        before = part[j - 2] if j >= 2 else None
        if name.kind != "ident" or name.text in KEYWORDS:
            continue
        if part_index == 0:
            # The first declarator needs a type before it: an identifier, a keyword type, '>', '&' or '*'.
            if before is None or before.text in (".", "->", "::") or (
                before.kind == "punct" and before.text not in (">", "&", "&&", "*", ">>")
            ):
                continue
        elif before is not None and before.text not in ("*", "&", "&&"):
            continue
        names.append(name.text)
    return names


def locals_before(tokens: list[Token], function: Function, line: int) -> list[str]:
    """Variables declared at the top level of the function body before `line`."""
    names: list[str] = []
    statement: list[Token] = []
    i = function.body_open + 1
    while i < function.body_close and tokens[i].line < line:
        t = tokens[i]
        if t.text == "{":
            close = matching(tokens, i)
            if statement and statement[-1].kind in ("ident", "punct") and statement[-1].text not in (")", "else", "do", "try"):
                # A braced initialiser: part of a declaration.
                statement += tokens[i : close + 1]
                i = close + 1
                continue
            statement = []  # a block of if/for/while/...: its declarations are not in scope after it
            i = close + 1
            continue
        if t.text == ";":
            names += declared_locals(statement)
            statement = []
        else:
            statement.append(t)
        i += 1
    return names


@dataclass
class Helper:
    name: str
    line: int
    col: int


def internal_helpers(tokens: list[Token]) -> list[Helper]:
    """Functions and variables with internal linkage at namespace scope (in an unnamed namespace or
    `static`): the compiler reports them when unused. Templates are left out (unused ones are not reported).
    """
    helpers = []
    anonymous: list[bool] = []  # the namespaces open here, and whether each is unnamed
    start = 0  # where the current namespace-scope declaration starts
    i = 0
    while i < len(tokens):
        t = tokens[i].text
        decl = tokens[start:i]
        texts = [x.text for x in decl]
        if t == "{":
            if texts and (texts[0] == "namespace" or texts[:2] == ["inline", "namespace"] or texts[0] == "extern"):
                anonymous.append(texts[-1] == "namespace")
                start = i + 1
                i += 1
                continue
            close = matching(tokens, i)
            if "(" in texts and "=" not in texts and texts and texts[0] not in ("struct", "class", "union", "enum"):
                helper = _helper_of(decl, any(anonymous))  # a function definition: its body ends it
                if helper:
                    helpers.append(helper)
                start = close + 1
            i = close + 1  # a class body or a braced initialiser: the declaration goes on to its ';'
            continue
        if t == "}":
            if anonymous:
                anonymous.pop()
            start = i + 1
        elif t == ";":
            if texts and not ("(" in texts and "=" not in texts):  # not a function's declaration
                helper = _helper_of(decl, any(anonymous), variable=True)
                if helper:
                    helpers.append(helper)
            start = i + 1
        i += 1
    return helpers


def _helper_of(decl: list[Token], in_unnamed_namespace: bool, variable: bool = False) -> Helper | None:
    if not decl or decl[0].text in ("template", "using", "typedef", "namespace", "struct", "class", "enum",
                                   "union", "extern", "static_assert", "friend"):
        return None
    texts = [t.text for t in decl]
    if not (in_unnamed_namespace or "static" in texts):
        return None
    if variable:
        stop = next((k for k, x in enumerate(texts) if x in ("=", "{", "[")), len(texts))
    else:
        stop = texts.index("(")
    if stop == 0 or decl[stop - 1].kind != "ident" or decl[stop - 1].text in KEYWORDS:
        return None
    return Helper(decl[stop - 1].text, decl[0].line, decl[0].col)


# ----------------------------------------------------------------------------------------------------------
# Marks and lessons


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
    section: str = ""  # "Spheres", or "" when the lesson has no fitting heading

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


def lesson_section(root: Path, exercise: Exercise) -> tuple[str, str]:
    """Where the lesson explains an exercise: the chapter's README and its heading that names the exercise
    or function; else the section whose text names the function; else its "Exercises" section."""
    folder = chapter_folder(root, exercise.chapter)
    if folder is None:
        return "", ""
    readme = folder / "README.md"
    lesson = readme.relative_to(root).as_posix()
    if not readme.is_file():
        return lesson, "Exercises"
    sections: list[tuple[str, list[str]]] = []
    in_code = False
    for line in readme.read_text(encoding="utf-8").splitlines():
        if line.lstrip().startswith("```"):
            in_code = not in_code
        m = None if in_code else re.match(r"^#{2,4}\s+(.*?)\s*#*\s*$", line)
        if m:
            sections.append((m.group(1), []))
        elif sections:
            sections[-1][1].append(line)
    def names(text: str, words: list[str]) -> bool:
        return any(re.search(r"(?<![\w.])" + re.escape(w) + r"(?![\w])", text) for w in words if w)

    function = exercise.function if exercise.function != "lambda" else ""
    file_names = [exercise.file.name, exercise.file.stem + ".hpp", exercise.file.stem + ".cpp"]
    ordinary = [(h, "\n".join(b)) for h, b in sections if not h.lower().startswith("exercises")]
    # The heading that names the exercise or its function; the section whose text names the function (or the
    # exercise); the section that names its file; the lesson's exercises.
    for heading, _ in sections:
        if names(heading, [exercise.short, exercise.name, function]):
            return lesson, heading.replace("`", "")
    for words in ([function, exercise.name], file_names):
        for heading, body in ordinary:
            if names(body, words):
                return lesson, heading.replace("`", "")
    for heading, _ in sections:
        if heading.lower().startswith("exercises"):
            return lesson, heading.replace("`", "")
    return lesson, ""


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
                open_mark = Exercise(name, relative, number, -1)
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
        tokens = tokenize(text)
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
            exercise.stubbed = f'"not implemented: {exercise.name} ' in body
            exercise.function = function.name
            exercise.parameters = function.parameters
            exercise.locals = locals_before(tokens, function, exercise.begin)
            exercise.lesson, exercise.section = lesson_section(root, exercise)
            exercises.append(exercise)
    if errors:
        raise ToolError("\n".join(errors))
    return exercises


def matching_balance(tokens: list[Token]) -> int:
    return sum(1 for t in tokens if t.text == "{") - sum(1 for t in tokens if t.text == "}")


def selected(exercise: Exercise, only: list[str]) -> bool:
    return not only or any(exercise.name == o or exercise.chapter == o for o in only)


# ----------------------------------------------------------------------------------------------------------
# The student edition


def cpp_string(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def stub_file(text: str, exercises: list[Exercise]) -> str:
    """The file with each exercise's marked lines replaced by a throw (the marks themselves are kept, so the
    student sees where to write and the tools still find the exercise)."""
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
        out.append(line)
        unused = exercise.parameters + exercise.locals
        if unused:
            casts = " ".join(f"((void){n[3:]}, ...);" if n.startswith("...") else f"(void){n};" for n in unused)
            out.append(f"{indent}{casts}")
        message = f"not implemented: {exercise.name} — see {exercise.reference()}"
        out.append(f"{indent}throw std::logic_error({cpp_string(message)});")
        out.append(lines[exercise.end])
        number = exercise.end + 1
    result = "\n".join(out)
    if not re.search(r"^\s*#\s*include\s*<stdexcept>", result, re.MULTILINE):
        result = add_include(result, "#include <stdexcept>")
    return result


def add_include(text: str, include: str) -> str:
    lines = text.split("\n")
    last = None
    for i, line in enumerate(lines):
        if re.match(r"^\s*#\s*include\b", line):
            last = i
        elif last is not None and line.strip() and not line.lstrip().startswith(("#", "//")):
            break
    if last is None:
        last = next((i for i, line in enumerate(lines) if re.match(r"^\s*#\s*pragma\s+once", line)), -1)
    lines.insert(last + 1, include)
    return "\n".join(lines)


def edition_note(chosen: list[Exercise]) -> str:
    chapters = ", ".join(sorted({e.chapter for e in chosen}))
    return (f"> **Student edition.** {len(chosen)} functions of this copy ({chapters}) throw \"not implemented\" "
            "until you write them: build with `cmake --preset release && cmake --build --preset release`, then "
            "`python3 tools/exercises.py status` lists the exercises done and left, and each lesson's "
            "\"Exercises\" section says what to write.\n\n")


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


def generate(root: Path, out: Path, only: list[str], force: bool, stub: bool = True) -> list[Exercise]:
    """Writes the edition; with stub=False, a plain copy (the baseline of `deps`)."""
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
    chosen = [e for e in all_exercises if selected(e, only)] if stub else []
    unknown = [o for o in only if not any(e.name == o or e.chapter == o for e in all_exercises)]
    if unknown:
        raise ToolError(f"generate: --only {','.join(unknown)}: no such exercise or chapter (see `exercises.py list`)")
    by_file: dict[Path, list[Exercise]] = {}
    for e in chosen:
        by_file.setdefault(e.file, []).append(e)
    files = repository_files(root)
    wanted = {out / f for f in files} | {out / EDITION_MARKER}
    if out.exists():
        for path in sorted(out.rglob("*"), reverse=True):
            if path.is_file() and path not in wanted and not path.is_relative_to(out / "build"):
                path.unlink()
    for relative in files:
        source = root / relative
        data = source.read_bytes()
        if relative in by_file:
            data = stub_file(data.decode("utf-8"), by_file[relative]).encode("utf-8")
        elif relative == Path("README.md") and chosen:
            data = edition_note(chosen).encode("utf-8") + data
        write_if_changed(out / relative, data)
        shutil.copymode(source, out / relative)
    marker = {"source": str(root), "stubbed": [e.name for e in chosen]}
    write_if_changed(out / EDITION_MARKER, (json.dumps(marker, indent=2) + "\n").encode("utf-8"))
    return chosen


# ----------------------------------------------------------------------------------------------------------
# Running a build's tests


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


def run_one(test: UnitTest, timeout: int) -> tuple[bool, str]:
    try:
        done = subprocess.run(test.command, cwd=test.directory, capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired as expired:
        output = (expired.stdout or b"") + (expired.stderr or b"")
        return False, output.decode("utf-8", "replace") + f"\ntimed out after {timeout} s"
    output = (done.stdout + done.stderr).decode("utf-8", "replace")
    return done.returncode == 0, output


def run_tests(build: Path, label: str | None, jobs: int, timeout: int = 300) -> list[TestResult]:
    """Runs the build's unit tests (one chapter's with `label`), each alone as CTest would run it."""
    tests = [t for t in unit_tests(build) if not label or t.label == label]
    tags = exercise_tags({t.command[0] for t in tests})
    print(f"running {len(tests)} unit tests{' labelled ' + label if label else ''} in {build} ...", flush=True)
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        outcomes = list(pool.map(lambda t: run_one(t, timeout), tests))
    return [TestResult(t.name, t.program, t.label, passed, output, tags.get((t.program, t.name), []))
            for t, (passed, output) in zip(tests, outcomes)]


# ----------------------------------------------------------------------------------------------------------
# Commands


def command_list(args: argparse.Namespace) -> int:
    exercises = find_exercises(args.root)
    for e in exercises:
        print(f"{e.name:32} {e.where():48} {e.function + '()':28} {e.reference()}")
    print(f"{len(exercises)} exercises in {len({e.chapter for e in exercises})} chapters")
    return 0


def command_generate(args: argparse.Namespace) -> int:
    only = [o for o in (args.only or "").split(",") if o]
    chosen = generate(args.root, Path(args.out), only, args.force)
    chapters = sorted({e.chapter for e in chosen})
    print(f"student edition in {Path(args.out).resolve()}: {len(chosen)} exercises stubbed "
          f"({', '.join(chapters) if chapters else 'none'})")
    print(f"build it:  cd {args.out} && cmake --preset release && cmake --build --preset release")
    print("then:      python3 tools/exercises.py status      (there: the exercises done and left)")
    return 0


def default_build() -> Path:
    for candidate in (Path.cwd(), ROOT / "build" / "release", ROOT / "build"):
        if (candidate / "CMakeCache.txt").is_file():
            return candidate
    raise ToolError("no build folder found: give --build DIR (the folder you built the course in)")


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


def next_exercise(entries: list[dict]) -> Exercise | None:
    """The exercise left to write first: one with a test that needs the fewest other exercises left."""
    left = {x["exercise"].name for x in entries if x["state"] == "left"}

    def others_needed(x: dict) -> int:
        return min((len(set(r.tags) & left) for r in x["tests"]), default=99)

    candidates = [x for x in entries if x["state"] == "left"]
    return min(candidates, key=others_needed)["exercise"] if candidates else None


def command_status(args: argparse.Namespace) -> int:
    build = Path(args.build) if args.build else default_build()
    source = source_of_build(build)
    exercises = find_exercises(source)
    results = run_tests(build, args.label, args.jobs)
    summary = summarise(exercises, results, args.label)
    symbols = {"done": "done", "written": "written", "left": "LEFT", "failing": "FAILING", "untested": "untested"}
    by_chapter: dict[str, list[dict]] = {}
    for entry in summary.values():
        by_chapter.setdefault(entry["exercise"].chapter, []).append(entry)
    total_done = 0
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
        upcoming = next_exercise(entries)
        if upcoming:
            print(f"  next: {upcoming.name} in {upcoming.where()} — see {upcoming.reference()}")
    other = [r for r in results if not r.passed and not r.tags]
    if other:
        print(f"{len(other)} failing tests depend on no exercise:")
        for r in other:
            print(f"  {r.label or '?'}: {r.name}")
    print(f"{total_done} of {len(summary)} exercises done; {sum(r.passed for r in results)} of {len(results)} tests pass")
    return 0


def command_check(args: argparse.Namespace) -> int:
    """In a build of the student edition: the failing tests are exactly the tests tagged with an exercise
    still stubbed, and each names one of them; every tag names a marked exercise; every exercise has a test.
    In a build of the full edition (nothing stubbed) that is: every test passes."""
    build = Path(args.build)
    source = source_of_build(build)
    exercises = find_exercises(source)
    names = {e.name for e in exercises}
    stubbed = {e.name for e in exercises if e.stubbed}
    results = run_tests(build, None, args.jobs)
    if not results:
        raise ToolError(f"{build}: no test results")
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
    edition = "student edition" if stubbed else "full edition (nothing stubbed)"
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
    """For instructors and chapter authors: which tests depend on which exercise, found by building an
    edition with one exercise stubbed at a time (one build folder, rebuilt incrementally) and running the
    unit tests. Prints, per test program, the tags each test needs and how they differ from its tags now."""
    out = Path(args.out).resolve()
    build = out / "build"
    only = [o for o in (args.only or "").split(",") if o]
    exercises = [e for e in find_exercises(args.root) if selected(e, only)]

    def run(stub_only: list[str] | None) -> dict[tuple[str, str], bool]:
        generate(args.root, out, stub_only or [], force=True, stub=stub_only is not None)
        if not (build / "CMakeCache.txt").is_file():
            subprocess.run(["cmake", "-S", str(out), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"], check=True,
                           stdout=subprocess.DEVNULL)
        targets = re.findall(r"^\.\.\. (\w+_test)$", subprocess.run(
            ["cmake", "--build", str(build), "--target", "help"], capture_output=True, text=True).stdout, re.M)
        built = subprocess.run(["cmake", "--build", str(build), "-j", str(args.jobs), "--target", *targets],
                               capture_output=True, text=True)
        if built.returncode != 0:
            raise ToolError(f"deps: the edition with {stub_only or 'nothing'} stubbed does not build:\n"
                            + built.stdout[-3000:] + built.stderr[-3000:])
        return {(r.program, r.name): r.passed for r in run_tests(build, None, args.jobs)}

    baseline = run(None)
    broken = sorted(k for k, passed in baseline.items() if not passed)
    needs: dict[tuple[str, str], list[str]] = {k: [] for k in baseline}
    for e in exercises:
        print(f"stubbing {e.name} alone ...", flush=True)
        for key, passed in run([e.name]).items():
            if not passed and baseline.get(key, False):
                needs.setdefault(key, []).append(e.name)
    tests = unit_tests(build)
    tags = exercise_tags({t.command[0] for t in tests})
    chosen = {e.name for e in exercises}
    changes = 0
    for program in sorted({p for p, _ in needs}):
        print(f"{program}:")
        for (p, name), found in needs.items():
            if p != program:
                continue
            now = sorted(t for t in tags.get((p, name), []) if t in chosen)
            found = sorted(found)
            mark = "" if found == now else "   <- now " + ("".join(f"[{TAG_PREFIX}{t}]" for t in now) or "untagged")
            changes += found != now
            if found or now:
                print(f"  \"{name}\": {''.join(f'[{TAG_PREFIX}{t}]' for t in found) or 'no exercise'}{mark}")
    for program, name in broken:
        print(f"  (fails even with nothing stubbed: {program}: \"{name}\")")
    print(f"{changes} tests whose tags differ from what they depend on")
    return 1 if changes else 0


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
    lint = commands.add_parser("lint", help="marks well formed, tags naming marked exercises, every exercise tested")
    lint.add_argument("--build", required=True, help="a build folder with the test programs built")
    deps = commands.add_parser("deps", help="which tests depend on which exercise (one build per exercise)")
    deps.add_argument("out", help="a scratch folder for the editions and their build (outside the repository)")
    deps.add_argument("--only", help="these chapters or exercises only: ch03 or ch03.shadow_ray,ch02.quad")
    deps.add_argument("-j", "--jobs", type=int, default=2, help="build jobs and tests run in parallel")
    args = parser.parse_args(argv)
    try:
        return {"list": command_list, "generate": command_generate, "status": command_status,
                "check": command_check, "lint": command_lint, "deps": command_deps}[args.command](args)
    except ToolError as error:
        print(f"exercises.py: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
