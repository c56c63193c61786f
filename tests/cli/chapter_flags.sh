#!/usr/bin/env bash
# chapter_flags.sh CH05_EXECUTABLE CH08_EXECUTABLE: the chapters' own flags are read as strictly as the core
# ones (strict_flags.hpp): NaN, infinities and partial numbers are refused with exit 2 and one line, and a flag
# that matters only with another is refused without it (chapter 08's --aperture without --variant aperture,
# --light-paths without --tracer combined).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
ch05=$1
ch08=$2
small=(--width 8 --height 4 --spp 1 --quiet)
real="must be a finite decimal number of magnitude at most 1e30"

check() {  # check EXECUTABLE EXPECTED_LINE ARGS...
    local exe=$1 expected=$2
    shift 2
    expect_bad_input "$(basename "$exe") $*" "$(basename "$exe"): $expected" 0 -- "$exe" "$@"
}
check "$ch05" "usage: --min-throughput: $real, got \"nan\" (see --help)" "${small[@]}" --min-throughput nan
check "$ch05" "usage: --min-throughput: $real, got \"-nan\" (see --help)" "${small[@]}" --min-throughput -nan
check "$ch05" "usage: --min-throughput: $real, got \"0.5x\" (see --help)" "${small[@]}" --min-throughput 0.5x
check "$ch05" "usage: --study-throughputs: $real, got \"nan\" (see --help)" "${small[@]}" --study-throughputs 0.1 nan
check "$ch08" "usage: --aperture: $real, got \"inf\" (see --help)" "${small[@]}" --variant aperture --aperture inf
check "$ch08" "usage: --aperture: $real, got \"1e309\" (see --help)" "${small[@]}" --variant aperture --aperture 1e309
check "$ch08" "usage: --aperture: is used only with --variant aperture, got --variant connect (see --help)" \
    "${small[@]}" --aperture 0.5
check "$ch08" "usage: --light-paths: is used only with --tracer combined (see --help)" "${small[@]}" --light-paths 2
check "$ch08" "usage: --sampler: is used only with --tracer combined (see --help)" "${small[@]}" --sampler sobol
check "$ch08" "usage: --caustics-only: is traced with --variant connect (see --help)" \
    "${small[@]}" --caustics-only --variant aperture
mkdir -p "$work" && cd "$work" || exit 1
"$ch08" "${small[@]}" --variant aperture --aperture 0.5 --out ap.png > stdout 2> stderr ||
    fail "--variant aperture --aperture 0.5 failed: $(cat stderr)"
"$ch08" "${small[@]}" --tracer combined --light-paths 0.5 --out both.png > stdout 2> stderr ||
    fail "--tracer combined --light-paths 0.5 failed: $(cat stderr)"
grep -q "tracer: combined" stdout || fail "--tracer combined: its summary does not say so: $(cat stdout)"
finish
