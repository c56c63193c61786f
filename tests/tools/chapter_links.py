#!/usr/bin/env python3
"""Links follow the syllabus (tests/tools/chapter_links.py ROOT): a chapter links the chapters it uses.

- Each chapter library's DEPENDS (chapters/NN_name/CMakeLists.txt) is exactly the earlier chapters whose
  headers its sources include ("MM_name/header.hpp"): no chain through chapters it does not use.
- Its program (main.cpp) and its tests (tests/NN_name_test.cpp) include no chapter it does not link (itself or
  through the chapters it links).
- A benchmark lives in the latest chapter it includes, and links that chapter.
- Only chapter 11 needs OpenGL and EGL.
Prints one line per broken rule (file: what is wrong) and exits 1; prints nothing and exits 0 when all hold.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"(\d\d)_[a-z0-9_]+/', re.MULTILINE)
CHAPTER = re.compile(r'rt_chapter\(NAME\s+\w+\s+NUMBER\s+(\d\d)((?:\s+DEPENDS(?:\s+ch\d\d)+)?)')
BENCHMARK = re.compile(r'rt_benchmark\((\w+)\s+(\S+)\s+CHAPTER\s+ch(\d\d)\)')


def included(paths):
    return {m for p in paths for m in INCLUDE.findall(p.read_text(encoding="utf-8"))}


def check(root):
    problems = []
    links = {}  # chapter -> the chapters its DEPENDS names
    for folder in sorted((root / "chapters").glob("[0-9][0-9]_*")):
        cmake = folder / "CMakeLists.txt"
        if not cmake.exists():
            continue
        text = cmake.read_text(encoding="utf-8")
        where = cmake.relative_to(root)
        chapter = CHAPTER.search(text)
        if not chapter:
            problems.append(f"{where}: no rt_chapter(NAME ... NUMBER ...) call")
            continue
        own = chapter.group(1)
        depends = set(re.findall(r"ch(\d\d)", chapter.group(2)))
        library = [p for p in folder.glob("*.[ch]pp") if p.name != "main.cpp"]
        uses = included(library) - {own}
        if depends != uses:
            problems.append(f"{where}: DEPENDS {' '.join('ch' + d for d in sorted(depends)) or '(none)'}, "
                            f"but the library includes {' '.join('ch' + d for d in sorted(uses)) or 'no chapter'}")
        links[own] = depends
        linked, todo = {own}, [own]
        while todo:  # the chapters linked through DEPENDS, transitively (earlier chapters are read first)
            for d in links.get(todo.pop(), ()):
                if d not in linked:
                    linked.add(d)
                    todo.append(d)
        tests = list((root / "tests").glob(f"{own}_*_test.cpp"))
        for user in [folder / "main.cpp", *tests]:
            if user.exists():
                unlinked = included([user]) - linked
                if unlinked:
                    problems.append(f"{user.relative_to(root)}: includes chapter "
                                    f"{', '.join(sorted(unlinked))}, which chapter {own} does not link")
        for name, source, linked_chapter in BENCHMARK.findall(text):
            latest = max(included([folder / source]) | {own})
            if latest != own or linked_chapter != own:
                problems.append(f"{where}: benchmark {name} includes up to chapter {latest} and links "
                                f"ch{linked_chapter}: "
                                f"it belongs in chapter {latest} and links it")
        if own != "11" and re.search(r"OpenGL|EGL", text):
            problems.append(f"{where}: names OpenGL or EGL, which only chapter 11 needs")
    return problems


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
    problems = check(root)
    for line in problems:
        print(line)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
