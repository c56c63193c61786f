"""Plausible wrong solutions of the exercises, kept as data, and whether each exercise's own chapter catches
them.

tests/wrong_solutions/chNN.json (one file per chapter, so a new chapter adds its own) maps each exercise to a
list of wrong solutions, each a mistake a student might make, written as edits of the right body:

    {
      "ch04.cosine_hemisphere": [
        {"mistake": "cos θ = 1 − u₁: the density of cos θ is then uniform, not 2 cos θ",
         "replace": {"std::sqrt(std::max(Real(0), 1 - u.x))": "1 - u.x"}},
        ...
      ]
    }

An entry may also say what its chapter's tests must print when they catch it, "says": "not normalised" (a text
of the failure message, so a wrong derivation is caught by a message naming its kind). An entry with
"correct": true and an "answer" instead of a "mistake" is another right solution (`1 − u` for `u`, another
inversion), written the same way: `exercises.py wrong` requires the tests to PASS with it, so that a
derivation's tests accept every correct answer, not one closed form.

Each key of "replace" must occur exactly once in the exercise's marked body (so a wrong solution that no longer
fits the code it edits is an error, not a silent pass); "body" instead gives the whole wrong body. The
switchable edition of `exercises.py deps` and `exercises.py wrong` carries every wrong solution beside the right
body, chosen when a test runs by RT_WRONG_SOLUTION=chNN.name:K (the K-th, from 1; see exercise_switch.hpp).
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

from .marks import Exercise, ToolError

DATA_FOLDER = Path("tests/wrong_solutions")
MINIMUM_PER_EXERCISE = 3
DERIVE_ROW = re.compile(r"^\| `(ch\d\d\.\w+)` \|.*\*\*Derive\*\*", re.MULTILINE)


def derive_items(root: Path) -> set[str]:
    """The exercises whose row in their lesson's exercise table asks the student to **Derive**: each needs
    another right solution (a different correct derivation) that its tests accept."""
    return {m.group(1) for lesson in sorted(root.glob("chapters/*/README.md"))
            for m in DERIVE_ROW.finditer(lesson.read_text(encoding="utf-8"))}


@dataclass
class WrongSolution:
    exercise: str  # "ch04.cosine_hemisphere"
    number: int  # 1, 2, ...: its place in the exercise's list
    mistake: str  # what the student got wrong, in one line (for a right solution: its answer)
    body: list[str]  # the wrong body's lines
    source: str  # "tests/wrong_solutions/ch04.json"
    correct: bool = False  # another right solution: the tests must pass with it
    says: str = ""  # a text the failing tests' output must contain (the mistake's kind)

    @property
    def key(self) -> str:  # the value of RT_WRONG_SOLUTION that selects it
        return f"{self.exercise}:{self.number}"


def body_lines(text: str, exercise: Exercise) -> list[str]:
    return text.split("\n")[exercise.begin + 1 : exercise.end]


def load(root: Path, exercises: list[Exercise]) -> dict[str, list[WrongSolution]]:
    """Every wrong solution under tests/wrong_solutions/, applied to the bodies of `exercises` and checked:
    each names a marked exercise, says its mistake, and each edit applies exactly once and changes the body."""
    by_name = {e.name: e for e in exercises}
    found: dict[str, list[WrongSolution]] = {}
    errors: list[str] = []
    folder = root / DATA_FOLDER
    files = sorted(folder.glob("*.json")) if folder.is_dir() else []
    texts: dict[Path, str] = {}
    for path in files:
        where = path.relative_to(root).as_posix()
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except json.JSONDecodeError as error:
            errors.append(f"{where}: not JSON: {error}")
            continue
        if not isinstance(data, dict):
            errors.append(f"{where}: must be an object mapping exercise names to lists of wrong solutions")
            continue
        for name, entries in data.items():
            exercise = by_name.get(name)
            if exercise is None:
                errors.append(f"{where}: {name}: no such exercise is marked (see `exercises.py list`)")
                continue
            if not isinstance(entries, list):
                errors.append(f"{where}: {name}: must be a list of wrong solutions")
                continue
            if exercise.file not in texts:
                texts[exercise.file] = (root / exercise.file).read_text(encoding="utf-8")
            right = body_lines(texts[exercise.file], exercise)
            for number, entry in enumerate(entries, 1):
                label = f"{where}: {name} #{number}"
                correct = isinstance(entry, dict) and entry.get("correct") is True
                what = "answer" if correct else "mistake"
                if not isinstance(entry, dict) or not isinstance(entry.get(what), str) or not entry[what]:
                    errors.append(f"{label}: needs {'an' if correct else 'a'} \"{what}\" (one line saying what "
                                  f"{'the other right answer is' if correct else 'is wrong'})")
                    continue
                says = entry.get("says", "")
                if not isinstance(says, str) or (correct and says):
                    errors.append(f"{label}: \"says\" must be a text of the failure message, on a wrong solution")
                    continue
                if ("replace" in entry) == ("body" in entry):
                    errors.append(f"{label}: give either \"replace\" (edits of the right body) or \"body\"")
                    continue
                if "body" in entry:
                    body = entry["body"]
                    if not isinstance(body, list) or not all(isinstance(line, str) for line in body):
                        errors.append(f"{label}: \"body\" must be a list of lines")
                        continue
                    wrong = list(body)
                else:
                    edits = entry["replace"]
                    if not isinstance(edits, dict) or not edits:
                        errors.append(f"{label}: \"replace\" must map texts of the right body to their wrong text")
                        continue
                    text = "\n".join(right)
                    bad = False
                    for old, new in edits.items():
                        count = text.count(old)
                        if count != 1:
                            errors.append(f"{label}: \"{old}\" occurs {count} times in the body of {name} "
                                          f"({exercise.where()}), not once: the wrong solution no longer fits the code")
                            bad = True
                            break
                        text = text.replace(old, new)
                    if bad:
                        continue
                    wrong = text.split("\n")
                if [line.strip() for line in wrong] == [line.strip() for line in right]:
                    errors.append(f"{label}: the body is the marked one, unchanged")
                    continue
                found.setdefault(name, []).append(
                    WrongSolution(name, number, entry[what], wrong, where, correct, says))
    if errors:
        raise ToolError("\n".join(errors))
    return found
