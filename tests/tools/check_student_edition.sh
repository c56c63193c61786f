#!/usr/bin/env bash
# CI's compile check of the student edition (every marked exercise replaced by a throw): its files with
# exercises compile without a warning, warnings as errors. Its tests run in the switchable edition's build
# (`exercises.py wrong`, CI's next step), with every exercise stubbed at run time: the failing tests are
# exactly those tagged with an exercise, each naming it. So CI compiles the chapters' tests once for both.
#   tests/tools/check_student_edition.sh [FOLDER]      (default: build/student-edition-ci; needs python3)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:-$root/build/student-edition-ci}"
command -v python3 > /dev/null || { echo "check_student_edition.sh: python3 not found: sudo apt-get install python3" >&2; exit 2; }

start=$(date +%s)
python3 "$root/tests/tools/exercises.py" generate "$out" --force
build="$out/build/release"
cmake -S "$out" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON > "$out/configure.log" || { cat "$out/configure.log"; exit 1; }
python3 "$root/tests/tools/exercises.py" warnings --build "$build"
echo "student edition checked in $(( $(date +%s) - start )) s"
