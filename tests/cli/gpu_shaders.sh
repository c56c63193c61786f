#!/usr/bin/env bash
# gpu_shaders.sh CH11_EXECUTABLE PFM_CHECK: chapter 11 through the real program.
#  1. No usable OpenGL (GLVND pointed at no EGL driver): exit 2, one line naming what is missing and the
#     packages to install, nothing written.
#  2. The image does not depend on how llvmpipe shares out the work: LP_NUM_THREADS 1, 2 and 3 give the same
#     PFM bit for bit; and on llvmpipe the compute and the fragment shader give the same bits too.
#  3. Ctrl-C during a long render: exit 130 within a few seconds, the complete image not written, the partial
#     one (whole passes) written when a pass was done.
#  4. On llvmpipe, an image wider than its largest texture (16384 pixels), which rendered black with exit 0:
#     refused before rendering, exit 2, naming the limit, for both shaders.
#  5. An environment image of 3e38 (its float sums overflowed: exit 1, "a bug in the chapter"): refused at
#     load as in every chapter, exit 2 and the line tests/data/bad_scenes/expected.tsv gives it.
# Exits 77 (skipped) after 1 when this machine has no OpenGL for 2.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
pfm_check=$2
name=$(basename "$exe")
size=(--width 24 --height 16 --spp 6 --quiet)

__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/egl_vendor.json \
    expect_bad_input "$name without an EGL driver" "$name: no OpenGL: " 1 -- "$exe" "${size[@]}" --out out.png
grep -q "apt-get install libegl-mesa0 libgl1-mesa-dri" "$scratch/stderr" ||
    fail "$name without an EGL driver: the message does not say what to install: $(cat "$scratch/stderr")"

mkdir -p "$work" && cd "$work" || exit 1
if ! "$exe" "${size[@]}" --out probe.png > probe.stdout 2> probe.stderr; then
    if grep -q "no OpenGL" probe.stderr; then
        echo "skipped: $(cat probe.stderr)"
        [ "$failures" -eq 0 ] && exit 77
    fi
    fail "$name: exit status $?: $(cat probe.stderr)"
fi
llvmpipe=0
if grep -q llvmpipe probe.stdout; then
    llvmpipe=1
    for threads in 1 2 3; do
        LP_NUM_THREADS=$threads "$exe" "${size[@]}" --out "t$threads.png" > /dev/null 2> stderr ||
            fail "$name with LP_NUM_THREADS=$threads: $(tail -n 2 stderr)"
    done
    for threads in 2 3; do
        why=$("$pfm_check" t1.pfm "t$threads.pfm" 2>&1 > /dev/null) ||
            fail "$name: LP_NUM_THREADS 1 and $threads differ: $why"
    done
    "$exe" "${size[@]}" --shader fragment --out fragment.png > /dev/null 2> stderr || fail "$name --shader fragment: $(tail -n 2 stderr)"
    why=$("$pfm_check" t1.pfm fragment.pfm 2>&1 > /dev/null) || fail "$name: compute and fragment shaders differ: $why"
else
    echo "not llvmpipe ($(grep -o 'shader on [^,]*' probe.stdout)): the thread-count check is llvmpipe's"
fi
# 3. Ctrl-C: the renderer looks for it after every dispatch. The bound: ten start-ups, or 5 s where that is less.
start_up=$(start_up_seconds "$exe") || exit 1
"$exe" --width 32 --height 32 --spp 65536 --out long.png > long.stdout 2> long.stderr &
pid=$!
sleep 3
kill -INT "$pid"
started=$(now)
wait "$pid"
status=$?
took=$(seconds_between "$started" "$(now)")
limit=$(at_least_ten_times "$start_up" 5.0)
echo "$name interrupted: stopped after $took s (a dispatch: well under a second; the bound: $limit s)"
[ "$status" -eq 130 ] || fail "$name interrupted: exit status $status, expected 130: $(tail -n 2 long.stderr)"
awk -v s="$took" -v l="$limit" 'BEGIN { exit !(s < l) }' || fail "$name interrupted: took $took s to stop, expected under $limit s"
[ ! -e long.png ] || fail "$name interrupted: wrote the complete long.png"
if [ -e long.partial.pfm ]; then
    grep -q "interrupted: partial image" long.stdout || fail "$name interrupted: a partial image but no summary line"
fi
# 4. (expect_bad_input renders in a fresh $work: after the checks that run there.)
if [ "$llvmpipe" = 1 ]; then
    for shader in compute fragment; do
        expect_bad_input "$name --shader $shader --width 16385" \
            "$name: image 16385x1: this OpenGL's $shader shader renders at most 16384 pixels a side (GL_MAX_" 1 -- \
            "$exe" --width 16385 --height 1 --spp 1 --quiet --shader "$shader" --out out.png
    done
fi
# 5.
data="$here/../data/bad_scenes"
scene=environment_image_beyond_limit.json
expected=$(awk -F'\t' -v f="$scene" '$1 == f { print $2 }' "$data/expected.tsv")
[ -n "$expected" ] || fail "$scene: no line in expected.tsv"
expect_bad_input "$name --scene $scene" "$name: $expected" 0 -- \
    env -C "$data" "$exe" --scene "$scene" --width 8 --height 8 --spp 4 --quiet --out "$work/out.png"
finish
