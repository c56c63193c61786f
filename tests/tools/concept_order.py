#!/usr/bin/env python3
"""Taught before used: no lesson may use a Monte Carlo idea before a lesson has taught it.

  concept_order.py [REPOSITORY_ROOT]

CONCEPTS below is the course's concept index: for each idea, the lesson section that teaches it (a chapter
folder and a heading of its README.md) and the words that show a lesson using it. Lessons are read in the
map's order (chapters/NN_*/README.md by NN, each from top to bottom). A use is too early when it comes in an
earlier chapter than the teaching section, or in the same lesson above it. Prints one line per concept and
lesson that uses it too early, at its first such use:
    chapters/04_x/README.md:158: uses sampling by inversion ("CDFs") before it is taught (in
    chapters/06_y/README.md § Sampling, line 84); 4 more uses
or, when the section the index names is missing, one line at the concept's first use ("taught nowhere").
A teaching section that never says any of its concept's words fails too.
Exits 1 if anything is found, 0 otherwise. Only the Python 3 standard library is used.
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True)
class Concept:
    name: str
    chapter: str           # the folder under chapters/ whose lesson teaches it
    section: str           # the heading (without its #s) of the section that teaches it
    words: tuple[str, ...]  # regular expressions, any of which is a use


PRIMER = "Monte Carlo in one page"
SAMPLING = "Sampling a density: inversion, marginals, Jacobians"
CONCEPTS = [
    Concept("the Monte Carlo estimator", "01_ray_generation", PRIMER,
            (r"\bMonte Carlo\b", r"\bestimators?\b", r"\bunbiased\b")),
    Concept("the estimator's variance and 1/√N", "01_ray_generation", PRIMER,
            (r"1/√N", r"\bvariance\b", r"\bRMSE\b", r"\bstandard errors?\b")),
    Concept("probability densities", "01_ray_generation", PRIMER,
            (r"\bpdfs?\b", r"\bprobability density\b", r"\bdensity\b")),
    Concept("sampling by inversion", "01_ray_generation", SAMPLING,
            (r"\binversion\b", r"\bCDFs?\b", r"\bcumulative distribution\b")),
    Concept("marginal and conditional densities", "01_ray_generation", SAMPLING,
            (r"\bmarginal\b", r"\bconditional\b")),
    Concept("the change of variables (Jacobian)", "01_ray_generation", SAMPLING,
            (r"\bJacobians?\b", r"\bchange of variables\b")),
    Concept("the chi-square test of a sampler", "01_ray_generation", SAMPLING,
            (r"\bchi-square\b", r"χ²")),
]

HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*$")


@dataclass(frozen=True)
class Lesson:
    path: Path           # chapters/NN_name/README.md, relative to the root
    lines: list[str]

    @property
    def chapter(self) -> str:
        return self.path.parent.name

    def section_span(self, heading: str) -> tuple[int, int] | None:
        """(first, last) line numbers, from 1, of the section under `heading` up to the next heading of the
        same or a higher level; None if the lesson has no such heading."""
        for number, line in enumerate(self.lines, start=1):
            m = HEADING.match(line)
            if m and m.group(2) == heading:
                level = len(m.group(1))
                for end, later in enumerate(self.lines[number:], start=number + 1):
                    n = HEADING.match(later)
                    if n and len(n.group(1)) <= level:
                        return number, end - 1
                return number, len(self.lines)
        return None


def read_lessons(root: Path) -> list[Lesson]:
    """Every lesson, in the map's order."""
    return [Lesson(p.relative_to(root), p.read_text(encoding="utf-8").splitlines())
            for p in sorted(root.glob("chapters/[0-9][0-9]_*/README.md"))]


def uses(concept: Concept, lesson: Lesson) -> list[tuple[int, str]]:
    """(line, the words matched) for each line of the lesson that uses the concept."""
    patterns = [re.compile(w) for w in concept.words]
    found = []
    for number, line in enumerate(lesson.lines, start=1):
        for pattern in patterns:
            m = pattern.search(line)
            if m:
                found.append((number, m.group(0)))
                break
    return found


def problems(lessons: list[Lesson], concepts: list[Concept]) -> list[str]:
    """What breaks the order: a use before the teaching section, a teaching section missing or silent."""
    found = []
    by_chapter = {lesson.chapter: lesson for lesson in lessons}
    order = [lesson.chapter for lesson in lessons]
    for concept in concepts:
        teacher = by_chapter.get(concept.chapter)
        span = teacher.section_span(concept.section) if teacher else None
        where = f"chapters/{concept.chapter}/README.md § {concept.section}"
        if span is None:
            users = [(lesson, used[0]) for lesson in lessons for used in [uses(concept, lesson)] if used]
            if users:
                lesson, (line, words) = users[0]
                found.append(f"{lesson.path}:{line}: uses {concept.name} (\"{words}\"), which is taught nowhere "
                             f"(the index names {where}, which does not exist); {len(users)} lessons use it")
            continue
        if not any(span[0] <= line <= span[1] for line, _ in uses(concept, teacher)):
            found.append(f"{where}: teaches {concept.name} without any of its words {list(concept.words)}")
        for lesson in lessons:
            if order.index(lesson.chapter) < order.index(concept.chapter):
                early = uses(concept, lesson)  # an earlier lesson: every use comes before the teaching
            elif lesson.chapter == concept.chapter:
                early = [(line, words) for line, words in uses(concept, lesson) if line < span[0]]
            else:
                early = []
            if early:
                line, words = early[0]
                more = f"; {len(early) - 1} more use{'s' if len(early) > 2 else ''}" if len(early) > 1 else ""
                found.append(f"{lesson.path}:{line}: uses {concept.name} (\"{words}\") before it is taught "
                             f"(in {where}, line {span[0]}){more}")
    return found


def main(argv: list[str]) -> int:
    root = Path(argv[1]) if len(argv) > 1 else Path(__file__).resolve().parents[2]
    lessons = read_lessons(root)
    if not lessons:
        print(f"concept_order: no lessons under {root}/chapters", file=sys.stderr)
        return 2
    found = problems(lessons, CONCEPTS)
    for problem in found:
        print(problem)
    print(f"concept_order: {len(CONCEPTS)} concepts in {len(lessons)} lessons: "
          + (f"{len(found)} problems" if found else "each taught before it is used"))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
