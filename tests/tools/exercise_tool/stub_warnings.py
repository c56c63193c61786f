"""CI's compile check of the student edition: each file a student writes in compiles without a warning once
its exercises are stubbed (warnings as errors, syntax only). A .cpp file is checked by its own compile command;
a header by a file that only includes it, compiled with the flags of a source beside it. The tests of the
edition then run in the switchable edition's build (`exercises.py wrong`), with every exercise stubbed there at
run time, so CI builds the chapters once for both."""

from __future__ import annotations

import json
import shlex
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from .marks import ToolError, find_exercises

DROPPED_WITH_VALUE = {"-o", "-MT", "-MF", "-MQ"}
DROPPED = {"-c", "-MD", "-MMD"}


def syntax_only(arguments: list[str], source: str) -> list[str]:
    """A compile command made a syntax check of `source`: no object, no dependency file."""
    kept, skip = [], False
    for argument in arguments:
        if skip:
            skip = False
        elif argument in DROPPED_WITH_VALUE:
            skip = True
        elif argument not in DROPPED:
            kept.append(argument)
    return kept + ["-fsyntax-only", source]


def checks(edition: Path, build: Path) -> list[tuple[str, list[str], str]]:
    """(file, command, folder) for each stubbed file of the edition."""
    listing = build / "compile_commands.json"
    if not listing.is_file():
        raise ToolError(f"warnings: {listing} is missing (configure with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)")
    commands = {Path(c["file"]).resolve(): c for c in json.loads(listing.read_text(encoding="utf-8"))}
    files = sorted({e.file for e in find_exercises(edition) if e.stubbed and not e.glsl})
    if not files:
        raise ToolError(f"warnings: {edition} has no stubbed exercise (not a student edition?)")
    result = []
    for file in files:
        path = (edition / file).resolve()
        if file.suffix == ".cpp":
            entry = commands.get(path)
            if entry is None:
                raise ToolError(f"warnings: {file}: not compiled by any target of {build}")
            arguments = [a for a in shlex.split(entry["command"]) if a != entry["file"]]
            result.append((str(file), syntax_only(arguments, entry["file"]), entry["directory"]))
            continue
        beside = [c for p, c in sorted(commands.items()) if p.parent == path.parent]
        if not beside:
            raise ToolError(f"warnings: {file}: no source beside it is compiled, so its flags are unknown")
        arguments = [a for a in shlex.split(beside[0]["command"]) if a != beside[0]["file"]]
        result.append((str(file), syntax_only(arguments + ["-x", "c++", "-include", str(path)], "/dev/null"),
                       beside[0]["directory"]))
    return result


def stub_warnings(edition: Path, build: Path, jobs: int) -> list[str]:
    """The files of the edition whose stubbed exercises do not compile cleanly, each with the compiler's words."""
    def run(check: tuple[str, list[str], str]) -> str:
        file, command, folder = check
        done = subprocess.run(command, cwd=folder, capture_output=True, text=True)
        return "" if done.returncode == 0 else f"{file}:\n{done.stderr[-3000:]}"

    found = checks(edition, build)
    print(f"compiling {len(found)} files with stubbed exercises, syntax only, warnings as errors ...", flush=True)
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        return [problem for problem in pool.map(run, found) if problem]
