#!/usr/bin/env python3
"""Stale lesson pictures: regenerates every lesson picture from the command that made it and fails on any the
code no longer makes.

Each chapter's images/pictures.json lists every PNG of that folder, with either
    "command": "chNN_name FLAGS..."   the render that made it (by chapter NN's executable, which may be a later
                                      chapter's than the lesson's): run again (with --out, --quiet and, unless
                                      given, --threads 2), and compared with the committed PNG by rt_compare;
                                      "tolerance" (levels of 255 a channel may differ by, default 0) and
                                      "max_differing" (the fraction of pixels that may differ, default 0) state
                                      how close it must be
or  "timing": "..."                   a plot of measured times (the report's, chapter 06's convergence in
                                      seconds): it changes from run to run, so it is listed and not compared.
or  "not_compared": "..."             a picture CI does not regenerate, with the reason (its command and why:
                                      it needs a converged reference minutes long, or llvmpipe compiles its
                                      shaders for the CPU it runs on): listed, and counted apart.
Renders are deterministic (every sample's random numbers come from its pixel, its index and the seed, and
pixels are exact sums), so a render's picture is the same to the byte on any thread count: the default
tolerance is none. A PNG with no entry, or an entry with no PNG, fails the check too.

  check_pictures.py BUILD [--only 02,04] [--update]   (BUILD: a release build with the executables and
                                                     rt_compare; --update copies the regenerated pictures
                                                     over the stale ones)
CMake: `cmake --build --preset release --target check-pictures`. Only the Python 3 standard library is used.
"""

from __future__ import annotations

import argparse
import json
import shlex
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build", type=Path, help="the release build folder")
    parser.add_argument("--only", help="these chapters only, by number: 02 or 02,04")
    parser.add_argument("--update", action="store_true", help="copy regenerated pictures over the stale ones")
    args = parser.parse_args(argv)
    args.build = args.build.resolve()
    compare = args.build / "common" / "rt_compare"
    if not compare.is_file():
        print(f"check_pictures.py: {compare}: not built (cmake --build {args.build} --target rt_compare)",
              file=sys.stderr)
        return 2
    only = [o for o in (args.only or "").split(",") if o]
    problems: list[str] = []
    checked = timing = not_compared = 0
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="rt-pictures-") as scratch:
        for folder in sorted((ROOT / "chapters").glob("[0-9][0-9]_*")):
            if only and folder.name[:2] not in only:
                continue
            images = folder / "images"
            pngs = {p.name for p in images.glob("*.png")} if images.is_dir() else set()
            manifest = images / "pictures.json"
            if not manifest.is_file():
                if pngs:
                    problems.append(f"{images.relative_to(ROOT)}: {len(pngs)} pictures but no pictures.json saying "
                                    "what makes them")
                continue
            entries = json.loads(manifest.read_text(encoding="utf-8"))
            where = manifest.relative_to(ROOT)
            for name in sorted(pngs - set(entries)):
                problems.append(f"{where}: {name} is in the folder but not listed (give its command)")
            for name in sorted(set(entries) - pngs):
                problems.append(f"{where}: {name} is listed but not in the folder")
            for name in sorted(set(entries) & pngs):
                entry = entries[name]
                if "not_compared" in entry:
                    not_compared += 1
                    print(f"  {folder.name}/images/{name}: not regenerated here ({entry['not_compared']})")
                    continue
                if "timing" in entry:
                    timing += 1
                    print(f"  {folder.name}/images/{name}: not compared, its numbers are timings ({entry['timing']})")
                    continue
                words = shlex.split(entry["command"])
                # The executable's own chapter (chNN_...), which may be another than the lesson's: chapter 01's
                # thin lens is shown by chapter 02, which intersects.
                owners = sorted((ROOT / "chapters").glob(words[0][2:4] + "_*"))
                owner = owners[0].name if owners else folder.name
                executable = args.build / "chapters" / owner / words[0]
                if not executable.is_file():
                    problems.append(f"{where}: {name}: {executable} is not built")
                    continue
                out = Path(scratch) / folder.name / name
                out.parent.mkdir(parents=True, exist_ok=True)
                flags = words[1:] + ["--out", str(out), "--quiet"]
                if "--threads" not in flags:
                    flags += ["--threads", "2"]
                began = time.monotonic()
                run = subprocess.run([str(executable), *flags], cwd=scratch, capture_output=True, text=True)
                seconds = time.monotonic() - began
                if run.returncode != 0:
                    problems.append(f"{where}: {name}: `{entry['command']}` failed (exit {run.returncode}): "
                                    + (run.stderr.strip().splitlines() or ["no message"])[-1])
                    continue
                tolerance = int(entry.get("tolerance", 0))
                max_differing = float(entry.get("max_differing", 0))
                compared = subprocess.run([str(compare), str(out), str(images / name), "--tolerance", str(tolerance),
                                           "--max-differing", str(max_differing)], capture_output=True, text=True)
                checked += 1
                stale = compared.returncode != 0
                print(f"  {folder.name}/images/{name}: {'STALE' if stale else 'as the code makes it'} "
                      f"({seconds:.1f} s: {entry['command']})", flush=True)
                if stale:
                    print("\n".join("      " + line for line in compared.stdout.splitlines()[1:-1]))
                    if args.update:
                        shutil.copyfile(out, images / name)
                        print(f"      updated {images.relative_to(ROOT) / name}")
                    else:
                        problems.append(f"{folder.name}/images/{name} is stale: `{entry['command']}` no longer makes "
                                        f"it (regenerate: tests/tools/check_pictures.py {args.build} --only "
                                        f"{folder.name[:2]} --update)")
    print(f"{checked} pictures regenerated and compared, {timing} plots of timings listed, {not_compared} pictures "
          f"listed as not regenerated here, in "
          f"{time.monotonic() - start:.0f} s")
    for p in problems:
        print("  " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
