#!/usr/bin/env bash
# split_render.sh PFM_CHECK RT_MERGE -- EXECUTABLE...: a render split by sample range gives the same image,
# bit for bit, as the render whole, on every chapter's default scene (small, to stay fast):
#  1. uneven pieces (0:1, 1:3, 3:5 of --spp 5), given to rt_merge out of order;
#  2. single samples (0:1 … 4:5);
#  3. resumed: a piece's film (0:2) continued to 0:5 with --resume;
#  4. interrupted: Ctrl-C, then --resume NAME.partial.film (the first executable only: it takes a second or two).
# Each piece's PNG and PFM are its own image; rt_merge writes PNG, PFM and film. Chapter 08's forward
# tracer splats light paths, so it refuses --samples with one line (exit 2); its --tracer reverse is split.
# Chapter 11 (the GPU) sums in float and refuses --samples too.
# Chapter 10 denoises the whole image: it refuses --samples too, and --denoiser none (its noisy image) is split.
# Chapter 12's training passes learn from each other: a guided render refuses --samples, --training-passes 0
# is split.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
pfm_check=$1
merge=$2
shift 3
size=(--width 24 --height 16 --spp 5 --threads 2 --quiet)

# same NAME A.pfm B.pfm: A and B are the same image bit for bit.
same() {
    local why
    why=$("$pfm_check" "$2" "$3" 2>&1 > /dev/null) || fail "$1: $why"
}
# render NAME EXECUTABLE ARGS...: a run that must succeed.
render() {
    local what=$1
    shift
    "$@" > "$scratch/stdout" 2> "$scratch/stderr" || fail "$what: exit status $?: $(tail -n 2 "$scratch/stderr")"
}
# merged NAME OUT PIECES...: rt_merge that must succeed.
merged() {
    local what=$1 out=$2
    shift 2
    "$merge" --out "$out" "$@" > "$scratch/stdout" 2> "$scratch/stderr" ||
        fail "$what: rt_merge exit status $?: $(cat "$scratch/stderr")"
}

for exe in "$@"; do
    name=$(basename "$exe")
    args=("${size[@]}")
    if [[ $name == ch08_* ]]; then
        # Every sample (0:5 of --spp 5) is refused too: such a run writes a film, which these tracers have not.
        for r in 0:2 0:5; do
            expect_bad_input "$name forward --samples $r" "$name: --samples: forward tracing splats" 1 -- \
                "$exe" "${size[@]}" --samples $r --out out.png
            expect_bad_input "$name combined --samples $r" "$name: --samples: the combined tracer adds light paths" 1 -- \
                "$exe" "${size[@]}" --tracer combined --samples $r --out out.png
        done
        args+=(--tracer reverse)
    fi
    # Chapter 11's GPU sums in float, not exactly: it renders whole and refuses pieces and resumes.
    if [[ $name == ch11_* ]]; then
        for r in 0:2 0:5; do
            expect_bad_input "$name --samples $r" "$name: --samples: the GPU sums" 1 -- \
                "$exe" "${size[@]}" --samples $r --out out.png
        done
        continue
    fi
    if [[ $name == ch10_* ]]; then
        for r in 0:2 0:5; do
            expect_bad_input "$name denoised --samples $r" "$name: --samples: chapter 10 denoises the whole image" 1 -- \
                "$exe" "${size[@]}" --samples $r --out out.png
        done
        args+=(--denoiser none)
    fi
    if [[ $name == ch12_* ]]; then
        for r in 0:2 0:5; do
            expect_bad_input "$name guided --samples $r" "$name: --samples: each training pass learns" 1 -- \
                "$exe" "${size[@]}" --samples $r --out out.png
        done
        args+=(--training-passes 0)
    fi
    dir="$scratch/$name" && mkdir -p "$dir" && cd "$dir" || exit 1
    render "$name whole" "$exe" "${args[@]}" --out whole.png
    [ ! -e whole.film ] || fail "$name: a whole render (no --samples) wrote a film"
    # 1. uneven pieces, merged out of order
    for r in 0:1 1:3 3:5; do render "$name piece $r" "$exe" "${args[@]}" --samples "$r" --out "piece${r/:/_}.png"; done
    for f in piece0_1 piece1_3 piece3_5; do
        [ -f "$f.png" ] && [ -f "$f.pfm" ] && [ -f "$f.film" ] || fail "$name: $f.png, .pfm or .film missing"
    done
    merged "$name uneven pieces" uneven.png piece3_5.film piece0_1.film piece1_3.film
    same "$name: whole and uneven pieces 0:1 1:3 3:5" whole.pfm uneven.pfm
    [ -f uneven.png ] && [ -f uneven.film ] || fail "$name: rt_merge did not write uneven.png and uneven.film"
    # A piece's PFM is its own image: a single sample's differs from the whole's.
    "$pfm_check" whole.pfm piece0_1.pfm > /dev/null 2>&1 && fail "$name: piece 0:1's image is the whole's"
    # 2. single samples
    singles=()
    for s in 0 1 2 3 4; do
        render "$name sample $s" "$exe" "${args[@]}" --samples "$s:$((s + 1))" --out "single$s.png"
        singles+=("single$s.film")
    done
    merged "$name single samples" singles.png "${singles[@]}"
    same "$name: whole and single samples 0:1 … 4:5" whole.pfm singles.pfm
    # 3. resumed: the film of 0:2 continued to 0:5
    render "$name piece 0:2" "$exe" "${args[@]}" --samples 0:2 --out first.png
    render "$name resumed" "$exe" "${args[@]}" --resume first.film --samples 0:5 --out resumed.png
    same "$name: whole and 0:2 resumed to 0:5" whole.pfm resumed.pfm
done

# 4. A render interrupted by Ctrl-C leaves its film; --resume finishes it with the bits of an uninterrupted
# render. The render must still be running when the signal comes: if it was not, again with 4x the samples
# (from few, so that a slow build, under the sanitizers, does not render long).
exe=$1
dir="$scratch/interrupted" && mkdir -p "$dir" && cd "$dir" || exit 1
spp=256
for attempt in 1 2 3 4 5 6; do
    run=(--width 64 --height 48 --spp "$spp" --threads 2 --quiet)
    "$exe" "${run[@]}" --out out.png > stdout 2> stderr &
    pid=$!
    sleep 0.3
    kill -INT "$pid" 2> /dev/null  # (it may have ended already: then again, longer)
    wait "$pid"
    status=$?
    [ "$status" -eq 130 ] && break
    spp=$((spp * 4))
done
[ "$status" -eq 130 ] || fail "interrupted: exit status $status, expected 130 (the render ended before the signal?)"
[ -f out.partial.film ] || fail "interrupted: no out.partial.film"
had=$(grep -o 'at least [0-9]*' stdout | head -n 1)
"$exe" "${run[@]}" --resume out.partial.film --out out.png > stdout 2> stderr ||
    fail "interrupted: --resume out.partial.film: exit status $?: $(cat stderr)"
"$exe" "${run[@]}" --out whole.png > /dev/null 2>&1 || fail "interrupted: the whole render failed"
same "interrupted with $had of $spp spp, then resumed" whole.pfm out.pfm
echo "interrupted with $had of $spp samples per pixel, resumed: the same image as the whole render"
finish
