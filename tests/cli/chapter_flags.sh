#!/usr/bin/env bash
# chapter_flags.sh CH01_EXECUTABLE ... CH10_EXECUTABLE CH12_EXECUTABLE: the chapters' own flags are read as strictly as the
# core ones (strict_flags.hpp): NaN, infinities and partial numbers are refused with exit 2 and one line; a
# flag that matters only with another is refused without it (only_with.hpp), before anything renders; and a
# study probes every file it writes before it renders anything (its --csv, its cached references).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
ch01=$1 ch02=$2 ch03=$3 ch04=$4 ch05=$5 ch06=$6 ch07=$7 ch08=$8 ch09=$9 ch10=${10} ch12=${11}
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
check "$ch05" "usage: --study-throughputs: $real, got \"nan\" (see --help)" "${small[@]}" --depth-study --study-throughputs 0.1 nan
check "$ch08" "usage: --aperture: $real, got \"inf\" (see --help)" "${small[@]}" --variant aperture --aperture inf
check "$ch08" "usage: --aperture: $real, got \"1e309\" (see --help)" "${small[@]}" --variant aperture --aperture 1e309
check "$ch09" "usage: --distance-sampling: foo not in {free-flight,equiangular,mis} (see --help)" "${small[@]}" \
    --distance-sampling foo
check "$ch09" "usage: --tracer: combined not in {auto,paths} (see --help)" "${small[@]}" --tracer combined
# Chapter 09 renders a scene whose glass casts caustics by the combined tracer, which renders whole: a piece
# of it is refused before anything renders (--tracer paths renders in pieces).
check "$ch09" "--samples (or MPI ranks): this scene's caustics are rendered by the combined tracer, which renders whole; --tracer paths renders in pieces" \
    "${small[@]}" --scene cornell.json --samples 0:1 --out out.png
check "$ch12" "usage: --guided-fraction: $real, got \"nan\" (see --help)" "${small[@]}" --guided-fraction nan
# Chapter 12's picture of the guide is probed before the training renders.
check "$ch12" "--guide-picture: missing/g.png: cannot be written: folder missing does not exist" "${small[@]}" \
    --guide-picture missing/g.png --out out.png
# Chapter 04's --quad-lights, which chapters 06 to 09 take too, names one of its two strategies.
for exe in "$ch04" "$ch06" "$ch07" "$ch08" "$ch09"; do
    check "$exe" "usage: --quad-lights: spherical not in {area,solid-angle} (see --help)" "${small[@]}" --quad-lights spherical
done

# A flag that matters only with another, given without it.
only() {  # only EXECUTABLE FLAG CONDITION ARGS...
    local exe=$1 flag=$2 condition=$3
    shift 3
    check "$exe" "usage: $flag: only with $condition (see --help)" "${small[@]}" "$@"
}
only "$ch08" --aperture "--variant aperture, got --variant connect" --aperture 0.5
only "$ch08" --light-paths "--tracer combined, got --tracer forward" --light-paths 2
only "$ch08" --sampler "--tracer combined, got --tracer reverse" --tracer reverse --sampler sobol
only "$ch08" --caustics-only "--variant connect, got --variant aperture" --caustics-only --variant aperture
only "$ch01" --csv --aa-study --csv t.csv
only "$ch03" --csv --offset-study --csv t.csv
only "$ch04" --csv --shadow-study --csv t.csv
only "$ch03" --study-scales --offset-study --study-scales 1 10
only "$ch03" --epsilon "--offset epsilon or --offset-study, got --offset robust" --epsilon 1e-3
only "$ch05" --study-depths --depth-study --study-depths 1 2
only "$ch05" --min-throughput "--termination throughput, got --termination roulette" --min-throughput 0.1
only "$ch05" --roulette-start "--termination roulette or --depth-study, got --termination depth" \
    --termination depth --roulette-start 2
only "$ch06" --max-spp --converge --max-spp 4
only "$ch06" --cache --converge --cache .
only "$ch06" --irradiance-runs --irradiance --irradiance-runs 3
only "$ch07" --depths --depth-study --depths 1 2
only "$ch07" --csv "--fresnel-study or --depth-study" --csv t.csv
only "$ch08" --study-size --forward-study --study-size 16
only "$ch09" --caps --knob-study --caps 1 2
only "$ch09" --study-paths --walk-study --study-paths 10
only "$ch10" --runs --study --runs 3
only "$ch12" --guide-at --guide-picture --guide-at 1 2 3
only "$ch10" --sigma-spatial "--denoiser bilateral or --study, got --denoiser atrous" --denoiser atrous --sigma-spatial 2
only "$ch10" --levels "--denoiser atrous or --study, got --denoiser bilateral" --denoiser bilateral --levels 3
only "$ch10" --sigma-colour "--denoiser bilateral or atrous or --study, got --denoiser none" \
    --denoiser none --sigma-colour 1
check "$ch06" "usage: --max-spp: must be a power of two (1, 2, 4, ...), got 3 (see --help)" "${small[@]}" \
    --converge --max-spp 3

# A study's outputs are probed before it renders anything: no reference is rendered into $work (the cache)
# and left there, no time is spent.
unwritable=/proc/c.csv
study() {  # study EXECUTABLE ARGS...
    local exe=$1
    shift
    expect_bad_input "$(basename "$exe") $*" "$(basename "$exe"): --csv: $unwritable: cannot be written" 1 -- \
        "$exe" "${small[@]}" "$@" --csv "$unwritable"
}
study "$ch01" --aa-study
study "$ch03" --offset-study
study "$ch04" --shadow-study
study "$ch05" --depth-study
study "$ch06" --converge --max-spp 2 --reference-spp 2
study "$ch07" --depth-study --depths 1 --reference-spp 1
study "$ch08" --forward-study --study-size 8 --study-paths 1000 --reference-spp 2 --glass-reference-spp 2
mkdir -p "$work" && cd "$work" || exit 1
"$ch08" "${small[@]}" --variant aperture --aperture 0.5 --out ap.png > stdout 2> stderr ||
    fail "--variant aperture --aperture 0.5 failed: $(cat stderr)"
"$ch08" "${small[@]}" --tracer combined --light-paths 0.5 --out both.png > stdout 2> stderr ||
    fail "--tracer combined --light-paths 0.5 failed: $(cat stderr)"
grep -q "tracer: combined" stdout || fail "--tracer combined: its summary does not say so: $(cat stdout)"
# The values a flag's rule allows are taken: --epsilon with --offset epsilon, --min-throughput with --termination
# throughput, --sigma-spatial with --denoiser bilateral; and --triangle-test moller matters with the BVH on (the
# leak probe counts its escapes), so it is not refused.
"$ch03" "${small[@]}" --offset epsilon --epsilon 1e-3 --out eps.png > stdout 2> stderr ||
    fail "--offset epsilon --epsilon 1e-3 failed: $(cat stderr)"
grep -q "ray offset: epsilon (epsilon 0.001)" stdout || fail "--epsilon 1e-3: its summary does not say so: $(cat stdout)"
"$ch05" "${small[@]}" --termination throughput --min-throughput 0.1 --out thr.png > stdout 2> stderr ||
    fail "--termination throughput --min-throughput 0.1 failed: $(cat stderr)"
"$ch10" "${small[@]}" --denoiser bilateral --sigma-spatial 2 --out bil.png > stdout 2> stderr ||
    fail "--denoiser bilateral --sigma-spatial 2 failed: $(cat stderr)"
"$ch02" --quiet --triangle-test moller --out moller.png > stdout 2> stderr ||
    fail "--triangle-test moller failed: $(cat stderr)"
grep -q "leak probe, [1-9][0-9]* of" stdout || fail "--triangle-test moller: no ray escaped the mesh: $(cat stdout)"
finish
