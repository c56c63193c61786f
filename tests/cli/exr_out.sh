#!/usr/bin/env bash
# exr_out.sh EXECUTABLE RT_COMPARE RT_MERGE (a build with OpenEXR): --out x.exr writes x.exr and x.png, the
# radiance of --out x.png's x.pfm (bit for bit with --exr-float, within half precision without) and the same
# PNG; rt_merge writes the whole render as a .exr; rt_compare reads .exr files and writes one, and refuses a
# truncated or corrupt one with exit 2 and one line naming it; --out x.exr in a folder that does not exist or
# takes no file, and --exr-float without a .exr, are refused before the render, nothing written.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
compare=$2
merge=$3
n=$(basename "$exe")
E="$scratch/exr" && mkdir -p "$E" && cd "$E" || exit 1
base=(--width 16 --height 8 --spp 4 --threads 2 --quiet)

# --- the same render as .png and .pfm, as a float EXR and as a half-float EXR ---
"$exe" "${base[@]}" --out p.png > p.txt 2>&1 || fail "--out p.png: $(cat p.txt)"
"$exe" "${base[@]}" --out f.exr --exr-float > f.txt 2>&1 || fail "--out f.exr --exr-float: $(cat f.txt)"
"$exe" "${base[@]}" --out h.exr > h.txt 2>&1 || fail "--out h.exr: $(cat h.txt)"
grep -qx "  wrote f.exr and f.png" f.txt || fail "--out f.exr: the summary does not say 'wrote f.exr and f.png'"
listed=$(ls -a | tr '\n' ' ')
[ "$listed" = ". .. f.exr f.png f.txt h.exr h.png h.txt p.pfm p.png p.txt " ] || fail "files written: $listed"
cmp -s f.png p.png && cmp -s h.png p.png || fail "the PNG beside a .exr is not the PNG of --out x.png"
"$compare" f.exr p.pfm > c.txt 2>&1 || fail "rt_compare f.exr p.pfm: $(cat c.txt)"
grep -q "radiance: RMSE 0, relative MSE 0, mean error +0$" c.txt || fail "the float EXR is not the PFM: $(cat c.txt)"
# Half floats round each channel to 11 significant bits: the picture may move by a level, not more.
"$compare" h.exr p.pfm --tolerance 1 > c.txt 2>&1 || fail "rt_compare h.exr p.pfm: $(cat c.txt)"
"$compare" f.exr p.pfm --out d.exr > /dev/null 2>&1 && [ -s d.exr ] || fail "rt_compare --out d.exr wrote no file"

# --- rt_merge: the pieces of the render, merged into a float EXR, are the whole render ---
"$exe" "${base[@]}" --samples 0:2 --out a.png > /dev/null 2>&1 || fail "piece 0:2 failed"
"$exe" "${base[@]}" --samples 2:4 --out b.png > /dev/null 2>&1 || fail "piece 2:4 failed"
"$merge" --out m.exr --exr-float a.film b.film > m.txt 2>&1 || fail "rt_merge --out m.exr: $(cat m.txt)"
[ -f m.exr ] && [ -f m.png ] && [ -f m.film ] && [ ! -e m.pfm ] || fail "rt_merge --out m.exr: not m.exr, m.png, m.film"
"$compare" m.exr p.pfm > c.txt 2>&1 && grep -q "radiance: RMSE 0," c.txt || fail "the merged EXR is not the whole render"

# --- broken files: refused by rt_compare with exit 2 and one line naming the file ---
size=$(stat -c %s f.exr)
head -c $((size / 2)) f.exr > "$scratch/half.exr"
head -c 100 f.exr > "$scratch/header.exr"
{ printf 'XXXX'; tail -c +5 f.exr; } > "$scratch/magic.exr"
{ head -c $((size - 30)) f.exr; head -c 30 /dev/zero | tr '\0' '\377'; } > "$scratch/data.exr"
for broken in half header magic data; do
    expect_bad_input "rt_compare: a broken EXR ($broken)" "rt_compare: $scratch/$broken.exr: " 1 -- \
        "$compare" "$scratch/$broken.exr" "$E/p.pfm"
done

# --- refused before the render (a render of these would take hours), nothing written ---
slow=(--width 1920 --height 1080 --spp 1048576 --quiet)
expect_bad_input "--out x.exr in a folder that does not exist" \
    "$n: --out: missing/x.exr: cannot be written: folder missing does not exist" 0 -- timeout 60 "$exe" "${slow[@]}" --out missing/x.exr
expect_bad_input "--out x.exr in a folder that takes no file" \
    "$n: --out: /proc/x.exr: cannot be written: folder /proc does not take a new file" 1 -- timeout 60 "$exe" "${slow[@]}" --out /proc/x.exr
expect_bad_input "--exr-float with --out x.png" "$n: --exr-float: is used only with --out naming a .exr file" 0 -- \
    timeout 60 "$exe" "${slow[@]}" --out x.png --exr-float
finish
