#!/usr/bin/env python3
"""Every number a lesson's "Try this" quotes is the number its command prints now.

  try_this.py REPOSITORY_ROOT BUILD_DIR [--slow | --all] [--only 07]

Reads the "## Try this" section of each chapters/NN_*/README.md. In a numbered item:
  - a code span that starts with `$B/` is a command (B is BUILD_DIR/chapters); one that starts with `--` is the
    item's (or else the previous item's) last command with those flags changed or added ("The same with
    `--max-depth 8`");
  - any other code span with a digit in it is a figure the last command printed, written as it prints it
    (`image mean 0.35067`, `rays: camera 160000, shadow 279182, ...`): its words must appear in the output,
    `...` standing for anything on the line, and each number equal to the printed one to the digits shown
    (a count exactly, 0.35067 matches 0.350671). A figure that is no output (a formula, a timing) is written
    without code spans.
The commands run in a scratch folder (their pictures land there) in which assets/ is the repository's. An
item marked "(about N s)", or every item of a block that says "about N s each", with N ≥ 5, is slow: it runs
only with --slow (the slow items only) or --all. A command with --live serves until stopped: it is skipped,
and said so; so is one whose program this build does not configure (chapter 11 without OpenGL). Prints one line per figure that disagrees, with the lesson's file and line, and what was
printed; exits 1 if any disagrees or a command fails. Only the Python 3 standard library is used.
"""

from __future__ import annotations

import argparse
import math
import os
import re
import shlex
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

SLOW_SECONDS = 5
NUMBER = r"-?\d+(?:\.\d+)?(?:e[+-]?\d+)?"
FIGURE_NUMBER = rf"(?<![\w.]){NUMBER}(?![\w])"  # a number, not a digit of a name (ch01_x.png)


@dataclass
class Item:
    lesson: Path
    line: int
    text: str
    slow: bool
    runs: list[tuple[str, list[tuple[int, str]]]] = field(default_factory=list)  # (command, [(line, figure)])


def try_this_items(lesson: Path) -> list[Item]:
    """The numbered items of the lesson's "Try this" section, each with its runs and their figures."""
    lines = lesson.read_text(encoding="utf-8").split("\n")
    start = next((i for i, line in enumerate(lines) if line.strip() == "## Try this"), None)
    if start is None:
        return []
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    intro_slow = False
    items: list[tuple[int, list[str]]] = []
    for i in range(start + 1, end):
        if re.match(r"^\d+\. ", lines[i]):
            items.append((i, [lines[i]]))
        elif items and lines[i].startswith("   "):
            items[-1][1].append(lines[i])
        elif not items and slow_mark(lines[i], each=True):
            intro_slow = True
    result = []
    last_command = None
    for first, block in items:
        item = Item(lesson, first + 1, " ".join(s.strip() for s in block),
                    intro_slow or slow_mark(" ".join(block), each=False))
        # Code spans may break across lines: read the item as one text, and find each span's line.
        for span, offset in code_spans(item.text):
            line = first + 1 + line_of(block, item.text, offset)
            if span.startswith("$B/"):
                last_command = span
                item.runs.append((span, []))
            elif span.startswith("--") and last_command:
                changed = with_flags(last_command, span)
                if changed != last_command or not item.runs:  # a flag the command already has names it
                    last_command = changed
                    item.runs.append((last_command, []))
            elif re.search(FIGURE_NUMBER, span) and item.runs:
                item.runs[-1][1].append((line, span))
            elif re.search(FIGURE_NUMBER, span):
                item.runs.append(("", [(line, span)]))  # a figure with no command before it: reported
        result.append(item)
    return result


def slow_mark(text: str, each: bool) -> bool:
    pattern = r"about (\d+) s each|each (?:command takes )?about (\d+) s" if each else r"\(about (\d+) s(?: each)?\)"
    return any(int(n) >= SLOW_SECONDS for m in re.finditer(pattern, text) for n in m.groups() if n)


def code_spans(text: str) -> list[tuple[str, int]]:
    return [(m.group(1).strip(), m.start()) for m in re.finditer(r"`([^`]+)`", text)]


def line_of(block: list[str], joined: str, offset: int) -> int:
    """The index in `block` of the line that holds character `offset` of the joined text."""
    position = 0
    for index, line in enumerate(block):
        position += len(line.strip()) + 1
        if offset < position:
            return index
    return len(block) - 1


def with_flags(command: str, flags: str) -> str:
    """`command` with each --flag of `flags` given its new value (or added, where the command lacks it)."""
    words = shlex.split(command)
    new = shlex.split(flags)
    i = 0
    while i < len(new):
        flag = new[i]
        value = [new[i + 1]] if i + 1 < len(new) and not new[i + 1].startswith("--") else []
        if flag in words:
            at = words.index(flag)
            has_value = at + 1 < len(words) and not words[at + 1].startswith("--")
            words[at:at + 1 + (1 if has_value else 0)] = [flag] + value
        else:
            words += [flag] + value
        i += 1 + len(value)
    return " ".join(shlex.quote(w) if w != "$B" and not w.startswith("$B/") else w for w in words)


def tokens(text: str) -> list[str]:
    """Numbers, words and marks; "..." (or "…") is a gap: anything on the line."""
    return re.findall(rf"\.\.\.|{FIGURE_NUMBER}|\w+|[^\w\s]", text.replace("…", "..."))


def is_number(token: str) -> bool:
    return re.fullmatch(NUMBER, token) is not None


def matches(figure: list[str], line: list[str], at: int) -> bool:
    """The figure's tokens are the line's from `at` on, one after another but across a gap, numbers equal to
    the digits shown."""
    if not figure:
        return True
    if figure[0] == "...":
        return any(matches(figure[1:], line, k) for k in range(at, len(line) + 1))
    if at >= len(line):
        return False
    same = agrees(figure[0], line[at]) if is_number(figure[0]) and is_number(line[at]) else figure[0] == line[at]
    return same and matches(figure[1:], line, at + 1)


def agrees(shown: str, printed: str) -> bool:
    """The printed number equals the shown one to the digits shown."""
    if shown == printed:
        return True
    mantissa = shown.lower().split("e")[0]
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    value, out = float(shown), float(printed)
    if "e" in shown.lower():
        exponent = int(shown.lower().split("e")[1])
        return math.isclose(out, value, abs_tol=0.5 * 10 ** (exponent - decimals) * (1 + 1e-9))
    if decimals == 0 and "." not in printed and "e" not in printed.lower():
        return False  # counts exactly
    return abs(out - value) <= 0.5 * 10 ** -decimals * (1 + 1e-9)


def check_figure(figure: str, output: str) -> str | None:
    """None where the output prints the figure; otherwise the line that prints its first words."""
    wanted = tokens(figure)
    for line in output.split("\n"):
        printed = tokens(line)
        if any(matches(wanted, printed, k) for k in range(len(printed))):
            return None
    words = [t for t in wanted if not is_number(t) and t != "..."][:2]
    near = next((line.strip() for line in output.split("\n") if words and all(w in line for w in words)), None)
    return f"printed `{near}`" if near else "printed no such line"


def run(command: str, build: Path, scratch: Path) -> tuple[int, str, float]:
    started = time.monotonic()
    done = subprocess.run(["bash", "-c", command], cwd=scratch, capture_output=True, text=True,
                          env={**os.environ, "B": str(build / "chapters")}, timeout=600)
    return done.returncode, done.stdout + done.stderr, time.monotonic() - started


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", type=Path)
    parser.add_argument("build", type=Path)
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--slow", action="store_true", help="the slow items only")
    which.add_argument("--all", action="store_true", help="every item")
    parser.add_argument("--only", help="one chapter's lesson, e.g. 07")
    args = parser.parse_args(argv)
    root, build = args.root.resolve(), args.build.resolve()
    problems = checked = skipped = 0
    with tempfile.TemporaryDirectory(prefix="try_this.") as folder:
        scratch = Path(folder)
        (scratch / "assets").symlink_to(root / "assets")
        for lesson in sorted(root.glob("chapters/[0-9][0-9]_*/README.md")):
            if args.only and not lesson.parent.name.startswith(args.only):
                continue
            name = lesson.relative_to(root)
            for item in try_this_items(lesson):
                if not args.all and item.slow != args.slow:
                    continue
                for command, figures in item.runs:
                    if not command:
                        for line, figure in figures:
                            print(f"{name}:{line}: `{figure}` follows no command of its item")
                            problems += 1
                        continue
                    if "--live" in command.split():
                        print(f"{name}:{item.line}: skipped `{command}`: the live view serves until stopped")
                        skipped += 1
                        continue
                    program = build / "chapters" / command.split()[0][len("$B/"):]
                    if not program.is_file() and not (program.parent / "CMakeFiles" / f"{program.name}.dir").is_dir():
                        print(f"{name}:{item.line}: skipped `{command}`: {program.name} is not configured in this "
                              "build (its chapter was skipped: see the configure log)")
                        skipped += 1
                        continue
                    status, output, seconds = run(command, build, scratch)
                    if status != 0:
                        print(f"{name}:{item.line}: `{command}` exits {status}:\n{output[-1500:]}")
                        problems += 1
                        continue
                    for line, figure in figures:
                        checked += 1
                        wrong = check_figure(figure, output)
                        if wrong:
                            print(f"{name}:{line}: the lesson says `{figure}`; `{command}` {wrong}")
                            problems += 1
                    print(f"{name}:{item.line}: {len(figures)} figures, {seconds:.1f} s: {command}", flush=True)
    kind = "slow items" if args.slow else "every item" if args.all else "quick items"
    print(f"try this ({kind}): {checked} figures checked, {problems} problems, {skipped} commands skipped")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
