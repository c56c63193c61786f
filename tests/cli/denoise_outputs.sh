#!/usr/bin/env bash
# denoise_outputs.sh CH10 PFM_CHECK: chapter 10 writes d.png and d.pfm (denoised), d.noisy.pfm, d.albedo.pfm
# and d.normal.pfm together (staged, renamed together); each of them is probed before the render (a folder in
# the way of d.noisy.pfm: exit 2, nothing written); --reference makes the summary give both errors and the
# filter's time; the noisy image is the one --denoiser none writes as its image.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
pfm_check=$2
n=$(basename "$exe")
small=(--width 24 --height 16 --spp 4 --threads 2 --quiet)

rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
"$exe" "${small[@]}" --out d.png > stdout 2> stderr || fail "a render: exit status $?: $(cat stderr)"
for f in d.png d.pfm d.noisy.pfm d.albedo.pfm d.normal.pfm; do
    [ -f "$f" ] || fail "a render did not write $f"
done
grep -q "wrote d.png, d.pfm, d.noisy.pfm, d.albedo.pfm and d.normal.pfm" stdout ||
    fail "the summary does not name the five files: $(grep wrote stdout)"
grep -q "note: filter time" stdout || fail "the summary does not give the filter's time"
ls -a | grep -q staging && fail "staging files left behind: $(ls -a)"

"$exe" "${small[@]}" --denoiser none --out plain.png > stdout 2> stderr || fail "--denoiser none: $(cat stderr)"
why=$("$pfm_check" d.noisy.pfm plain.pfm 2>&1 > /dev/null) || fail "d.noisy.pfm is not the image of --denoiser none: $why"

"$exe" "${small[@]}" --reference plain.pfm --out r.png > stdout 2> stderr || fail "--reference: $(cat stderr)"
grep -q "error against the reference" stdout || fail "--reference: no error of the denoised image"
grep -q "error of the noisy image against the reference: RMSE 0," stdout ||
    fail "--reference: no error of the noisy image (0 against itself): $(grep error stdout)"

mkdir -p "$work/probe" && mkdir "$work/probe/e.noisy.pfm"
expect_bad_input "a folder in the way of e.noisy.pfm" "$n: --out: " 1 -- "$exe" "${small[@]}" --out probe/e.png
[ ! -e "$work/probe/e.png" ] || fail "a folder in the way of e.noisy.pfm: e.png written"

finish
