#!/usr/bin/env bash
# stress.sh PFM_CHECK SCENE_FOLDER... -- EXECUTABLE...: renders every scene of the folders with every chapter
# executable at 48x32, 2 samples per pixel, with 1 and with 2 threads. Each run must exit 0, every pixel of
# its PFM must be finite, and the two PFMs must be the same bit for bit.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
pfm_check=$1
shift
scenes=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    scenes+=("$1"/*.json)
    shift
done
shift
executables=("$@")
[ ${#executables[@]} -gt 0 ] || fail "no chapter executable given"
[ ${#scenes[@]} -gt 0 ] || fail "no scene found"

mkdir -p "$work"
runs=0
for exe in "${executables[@]}"; do
    n=$(basename "$exe")
    if [ ! -x "$exe" ]; then
        fail "$n is not built ($exe)"
        continue
    fi
    for scene in "${scenes[@]}"; do
        s=$(basename "$scene" .json)
        for threads in 1 2; do
            "$exe" --scene "$scene" --width 48 --height 32 --spp 2 --threads "$threads" --quiet \
                --out "$work/$n.$s.t$threads.png" > "$work/stdout" 2> "$work/stderr"
            status=$?
            [ "$status" -eq 0 ] || fail "$n on $s with $threads thread(s): exit status $status: $(tail -n 3 "$work/stderr")"
            runs=$((runs + 1))
        done
        if [ -f "$work/$n.$s.t1.pfm" ] && [ -f "$work/$n.$s.t2.pfm" ]; then
            if result=$("$pfm_check" "$work/$n.$s.t1.pfm" "$work/$n.$s.t2.pfm" 2>&1); then
                echo "$n $s: $result, finite, same for 1 and 2 threads"
            else
                fail "$n on $s: $result"
            fi
        elif [ "$status" -eq 0 ]; then
            fail "$n on $s: no PFM written"
        fi
    done
done
echo "$runs renders of ${#scenes[@]} scenes by ${#executables[@]} chapter executables"
finish
