#!/usr/bin/env bash
# CI check of the unit-test exercises: the student edition (every marked exercise replaced by a throw) is
# generated, builds cleanly (warnings are errors), and its failing unit tests are exactly the tests tagged
# as depending on an exercise, each failure naming its exercise. (The end-to-end tests of the executables,
# tests/cli, are not built here: they need the executables, and a student edition's renders throw.) The full edition passing every test is the
# ordinary `cmake --workflow --preset release` run.
#   tests/tools/check_student_edition.sh [FOLDER]      (default: build/student-edition-ci; needs python3)
# Only the test programs are built, in Release, two jobs at a time.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:-$root/build/student-edition-ci}"
command -v python3 > /dev/null || { echo "check_student_edition.sh: python3 not found: sudo apt-get install python3" >&2; exit 2; }

start=$(date +%s)
python3 "$root/tests/tools/exercises.py" generate "$out" --force
# The edition keeps warnings as warnings in the files with exercises, for students; the check makes them errors.
# Built in build/release, as deep below the edition as the course's own build is below the repository: every
# unchanged file then compiles with the same relative paths, so ccache (where installed) reuses its object.
build="$out/build/release"
cmake -S "$out" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRT_EXERCISE_WARNINGS_AS_ERRORS=ON > "$out/configure.log" || { cat "$out/configure.log"; exit 1; }
mapfile -t targets < <(cmake --build "$build" --target help | sed -n 's/^\.\.\. \([A-Za-z0-9_]*_test\)$/\1/p')
[ ${#targets[@]} -gt 0 ] || { echo "check_student_edition.sh: no test programs in $build" >&2; exit 1; }
echo "building the student edition's test programs: ${targets[*]}"
cmake --build "$build" -j2 --target "${targets[@]}"
# Runs every unit test as CTest would (each test alone) and compares the failures with the tags.
python3 "$root/tests/tools/exercises.py" check --build "$build"
echo "student edition checked in $(( $(date +%s) - start )) s"
