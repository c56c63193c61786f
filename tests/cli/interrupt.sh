#!/usr/bin/env bash
# interrupt.sh EXECUTABLE PFM_CHECK SLOW_EXECUTABLE: Ctrl-C during a render.
#  1. One SIGINT: the render stops within a second, writes out.partial.png, .pfm and .film (finite, with
#     the samples it has, said in the summary), leaves the earlier out.png and out.pfm as they were, exits 130.
#  2. Two SIGINTs while the tiles in progress are still being finished: the second exits at once, with 130,
#     and leaves no file at all (no partial image, no temporary file). SLOW_EXECUTABLE is chapter 02's, run
#     without acceleration, so that finishing a tile's pass takes a tenth of a second or more.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
pfm_check=$2
slow_exe=$3

now() { date +%s.%N; }
seconds_between() { echo "$1 $2" | awk '{printf "%.3f", $2 - $1}'; }

# --- 1. one interrupt ---
mkdir -p "$work" && cd "$work" || exit 1
echo "earlier png" > out.png
echo "earlier pfm" > out.pfm
before=$(md5sum out.png out.pfm)
# Background jobs of a script start with SIGINT ignored; the executable installs its own handler anyway.
# 4096 samples per pixel take many seconds; each tile's pass is at most 16 samples of 256 pixels: about 1 ms in
# a release build, a few hundredths of a second under the sanitizers.
"$exe" --width 320 --height 180 --spp 4096 --threads 2 --out out.png > stdout 2> stderr &
pid=$!
sleep 1.5
kill -0 "$pid" 2> /dev/null || fail "the render ended before it was interrupted"
sent=$(now)
kill -INT "$pid"
wait "$pid"
status=$?
stop=$(seconds_between "$sent" "$(now)")
echo "one SIGINT: exit status $status, stopped and saved in $stop s"
[ "$status" -eq 130 ] || fail "exit status $status after SIGINT, expected 130; stderr: $(cat stderr)"
awk -v s="$stop" 'BEGIN { exit !(s < 1.0) }' || fail "took $stop s to stop after SIGINT, expected under 1 s"
[ -f out.partial.png ] || fail "no out.partial.png"
[ -f out.partial.pfm ] || fail "no out.partial.pfm"
[ -f out.partial.film ] || fail "no out.partial.film"
[ "$(md5sum out.png out.pfm)" = "$before" ] || fail "the earlier out.png or out.pfm was changed"
grep -q "interrupted: finishing the tiles in progress" stderr || fail "no interrupt message on stderr: $(cat stderr)"
grep -q "interrupted: partial image with" stdout || fail "the summary does not say the image is partial: $(cat stdout)"
grep -q "wrote out.partial.png, out.partial.pfm and out.partial.film" stdout || fail "the summary does not name the partial files"
grep "interrupted: partial" stdout
if [ -f out.partial.pfm ]; then
    check=$("$pfm_check" out.partial.pfm 2>&1) || fail "partial PFM: $check"
    echo "partial PFM: $check"
    awk -v m="$(echo "$check" | awk '{print $3}')" 'BEGIN { exit !(m > 0) }' || fail "the partial image is black: $check"
fi
leftovers=$(ls | grep -E '\.(partial|staged)-[0-9]+$')
[ -z "$leftovers" ] || fail "temporary files left: $leftovers"

# --- 2. two interrupts ---
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
# Chapter 02 testing every primitive for every ray: a tile's pass of 16 samples of 256 pixels takes about 0.1 s
# in a release build (and much longer under the sanitizers), so 20 ms after the first SIGINT the threads are
# still finishing their tiles when the second arrives.
"$slow_exe" --accel none --width 320 --height 180 --spp 1048576 --threads 2 --out out.png > stdout 2> stderr &
pid=$!
sleep 2
kill -INT "$pid"
sleep 0.02
kill -0 "$pid" 2> /dev/null || fail "the render ended within 0.02 s of the first SIGINT; the second cannot be tested"
sent=$(now)
kill -INT "$pid"
wait "$pid"
status=$?
stop=$(seconds_between "$sent" "$(now)")
echo "second SIGINT: exit status $status after $stop s"
[ "$status" -eq 130 ] || fail "exit status $status after the second SIGINT, expected 130"
awk -v s="$stop" 'BEGIN { exit !(s < 0.5) }' || fail "took $stop s to exit after the second SIGINT"
files=$(ls | grep -v -E '^std(out|err)$')
[ -z "$files" ] || fail "files left after the second SIGINT: $files"
finish
