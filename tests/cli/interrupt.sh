#!/usr/bin/env bash
# interrupt.sh EXECUTABLE PFM_CHECK SLOW_EXECUTABLE: SIGINT and SIGTERM during a run.
#  1. One SIGINT during the render: it stops at once (within 2 s, or ten start-ups), writes out.partial.png, .pfm and .film
#     (finite, with the samples it has, said in the summary), leaves the earlier out.png and out.pfm as they
#     were, exits 130. SIGTERM does the same and exits 143.
#  2. A render whose every sample is slow (SLOW_EXECUTABLE, chapter 02 testing each of 300,000 triangles for
#     every ray, about 4 ms a sample in a release build) stops within a few samples' time all the same: the
#     interrupt is looked for before every sample, not after a tile's pass (256 samples, a second or more). Interrupted in its first pass,
#     its summary says which pixels have no sample.
#  3. A second signal while the partial image is being written (SIGINT, then SIGTERM) exits at once (within
#     0.5 s, or ten start-ups, of what a SIGKILL at that moment takes), with the status of the second, and leaves no file at all:
#     no partial image, no staging file.
#  4. One SIGINT while the complete image is being written: the files are finished and renamed into place,
#     the run says so and exits 130.
# The writing phase is found by watching for the staging files (.rt-PID-N.staging) of a 4096 × 4096 image.
# A signal that lands before the first sample (the run still loading, on a loaded machine: the 4096 × 4096 run
# needs 0.4 s alone and over 2 s with six busy processes on two cores) is answered "nothing written", which is
# right but not the case under test: such a try is said and made again with twice the wait, up to 16 s.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
pfm_check=$2
slow_exe=$3

# Every time bound below is ten times or more of a floor measured in this run (lib.sh: start_up_seconds, the
# slowest of three starts of the executable), so that a loaded machine or a sanitizer build cannot fail it.
start_up=$(start_up_seconds "$exe") || exit 1
slow_start_up=$(start_up_seconds "$slow_exe") || exit 1
echo "start-up (--help, the slowest of three): $start_up s, and $slow_start_up s for the slow executable"
staging_files() { ls -a | grep -E '\.staging$'; }
no_staging_files() {
    local left
    left=$(staging_files)
    [ -z "$left" ] || fail "$1: staging files left: $left"
}
# signal_and_wait PID SIGNAL: sends SIGNAL, waits for the run to end; sets $status and $stop (seconds taken).
signal_and_wait() {
    local sent
    sent=$(now)
    kill -"$2" "$1"
    wait "$1"
    status=$?
    stop=$(seconds_between "$sent" "$(now)")
}
# expect_stop WHAT EXPECTED_STATUS SECONDS: the run ended with EXPECTED_STATUS within SECONDS of the signal.
expect_stop() {
    echo "$1: exit status $status after $stop s"
    [ "$status" -eq "$2" ] || fail "$1: exit status $status, expected $2; stderr: $(head -c 300 stderr)"
    awk -v s="$stop" -v m="$3" 'BEGIN { exit !(s < m) }' || fail "$1: took $stop s, expected under $3 s"
}
# sampled_before_signal: whether the run just ended had taken a sample when it was interrupted; says why not.
sampled_before_signal() {
    grep -q "interrupted before any sample was taken; nothing written" stderr || return 0
    echo "  (the signal came before the first sample: the machine is loaded; again with a longer wait)"
    return 1
}
# wait_for_writing PID: waits (up to 60 s) until the run writes its image, after its output probes.
wait_for_writing() {
    sleep 0.3
    for _ in $(seq 6000); do
        [ -n "$(staging_files)" ] && return 0
        kill -0 "$1" 2> /dev/null || return 1
        sleep 0.01
    done
    return 1
}

# --- 1. one interrupt during the render, SIGINT then SIGTERM ---
for signal in INT TERM; do
    expected_status=$([ $signal = INT ] && echo 130 || echo 143)
    for delay in 1.5 3 6 12; do
        rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
        echo "earlier png" > out.png
        echo "earlier pfm" > out.pfm
        before=$(md5sum out.png out.pfm)
        # Background jobs of a script start with SIGINT ignored; the executable installs its own handler anyway.
        "$exe" --width 320 --height 180 --spp 4096 --threads 2 --out out.png > stdout 2> stderr &
        pid=$!
        sleep $delay
        kill -0 "$pid" 2> /dev/null || fail "SIG$signal: the render ended before it was interrupted"
        signal_and_wait "$pid" $signal
        sampled_before_signal && break
    done
    expect_stop "one SIG$signal, stopped and saved" "$expected_status" "$(at_least_ten_times "$start_up" 2.0)"
    [ -f out.partial.png ] || fail "SIG$signal: no out.partial.png"
    [ -f out.partial.pfm ] || fail "SIG$signal: no out.partial.pfm"
    [ -f out.partial.film ] || fail "SIG$signal: no out.partial.film"
    [ "$(md5sum out.png out.pfm)" = "$before" ] || fail "SIG$signal: the earlier out.png or out.pfm was changed"
    grep -q "interrupted: stopping the samples in progress, then saving the partial image" stderr ||
        fail "SIG$signal: no interrupt message on stderr: $(cat stderr)"
    grep -q "interrupted: partial image with" stdout || fail "SIG$signal: the summary does not say the image is partial: $(cat stdout)"
    grep -q "wrote out.partial.png, out.partial.pfm and out.partial.film" stdout || fail "SIG$signal: the summary does not name the partial files"
    if [ -f out.partial.pfm ]; then
        check=$("$pfm_check" out.partial.pfm 2>&1) || fail "partial PFM: $check"
        awk -v m="$(echo "$check" | awk '{print $3}')" 'BEGIN { exit !(m > 0) }' || fail "the partial image is black: $check"
    fi
    no_staging_files "SIG$signal"
done

# --- 2. slow samples: the interrupt is answered within a sample ---
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
# A grid of 150,000 quads (300,000 triangles) facing the camera.
awk 'BEGIN { n = 388; for (j = 0; j < n; ++j) for (i = 0; i < n; ++i) printf "v %.6f %.6f 0\n", i / n - 0.5, j / n - 0.5;
             for (j = 0; j + 1 < n; ++j) for (i = 0; i + 1 < n; ++i) { a = j * n + i + 1; printf "f %d %d %d %d\n", a, a + 1, a + n + 1, a + n } }' > grid.obj
cat > slow.json <<'JSON'
{"camera": {"from": [0, 0, 2], "at": [0, 0, 0]}, "materials": {"w": {"type": "diffuse"}},
 "shapes": [{"type": "mesh", "file": "grid.obj", "material": "w"}]}
JSON
# What one sample costs in this build (4 ms in a release build, far more under the sanitizers), from a render
# of two samples of one pixel: the run must stop within 0.5 s or ten start-ups (writing the partial image and exiting) and 8
# samples' time, where waiting for a tile's pass to end would take 256 samples' time.
# The signal is sent once the render has surely begun: after twice the whole calibration run (loading the
# mesh, under the sanitizers, takes seconds, and a signal during the loading is answered when it ends).
started=$(now)
"$slow_exe" --scene slow.json --accel none --width 1 --height 1 --spp 2 --threads 1 --quiet --out one.png > one.txt 2>&1 ||
    fail "slow samples: the calibration run failed: $(cat one.txt)"
calibration=$(seconds_between "$started" "$(now)")
rate=$(grep -o -E '[0-9.e+-]+ samples/s' one.txt | awk '{print $1}')
limit=$(awk -v r="$rate" -v s="$(at_least_ten_times "$slow_start_up" 0.5)" 'BEGIN { printf "%.3f", s + 8 / r }')
echo "slow samples: $rate samples/s on one thread; the interrupt must be answered within $limit s"
rm -f one.png one.pfm one.txt
# Under AddressSanitizer, LeakSanitizer scans the whole heap when the process exits: 0.65 s for this mesh in the
# sanitize build (measured: 0.86 s from the signal to the exit with the scan, 0.21 s without), the sanitizer's
# time and not the run's. The timed run goes without it; the interrupts of part 1 take the same path (stop,
# save the partial image, exit) with the leak check on.
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
    "$slow_exe" --scene slow.json --accel none --width 320 --height 180 --spp 1048576 --threads 2 --out out.png > stdout 2> stderr &
pid=$!
sleep "$(awk -v c="$calibration" 'BEGIN { printf "%.2f", (2 * c > 3.5 ? 2 * c : 3.5) }')"
kill -0 "$pid" 2> /dev/null || fail "the slow render ended before it was interrupted: $(cat stderr)"
signal_and_wait "$pid" INT
expect_stop "slow samples, one SIGINT" 130 "$limit"
# A tile's first pass takes about a second here (256 samples): some tiles have their sample, most have none
# (under the sanitizers, maybe none has: then nothing is written, and the run says so).
if [ -f out.partial.pfm ]; then
    grep -E "interrupted in the first pass: [0-9]+ of 57600 pixels have no sample and are black, all within x \[[0-9]+, [0-9]+\), y \[[0-9]+, [0-9]+\)" stdout ||
        fail "slow samples: the summary does not say which pixels have no sample: $(grep interrupted stdout)"
else
    grep -q "interrupted before any sample was taken; nothing written" stderr ||
        fail "slow samples: no partial image, and no word why: $(cat stderr)"
fi
no_staging_files "slow samples"

# --- 3. a second signal while the partial image is written ---
# interrupt_into_writing: starts the 4096 × 4096 run, interrupts it once, and returns once it writes its partial
# image (sets $pid); fails when it never does.
interrupt_into_writing() {
    for delay in 2 4 8 16; do
        rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
        "$exe" --width 4096 --height 4096 --spp 1048576 --threads 2 --quiet --out out.png > stdout 2> stderr &
        pid=$!
        sleep $delay
        kill -INT "$pid"
        wait_for_writing "$pid" && return 0
        wait "$pid"
        sampled_before_signal || continue
        return 1
    done
    return 1
}
# "At once" is measured against the kernel's own floor: the time a SIGKILL at the same moment takes to end the
# process (unmapping its 1.3 GB; about 0.2 s on an idle machine, seconds on a loaded one). The run may add at
# most 0.5 s, or ten start-ups, to it.
if interrupt_into_writing; then
    signal_and_wait "$pid" KILL
    kill_floor=$stop
else
    fail "SIGKILL while writing: the partial image was never written; stderr: $(head -c 300 stderr)"
    kill_floor=0
fi
echo "SIGKILL while writing (the floor): the run ended after $kill_floor s"
for second in INT TERM; do
    expected_status=$([ $second = INT ] && echo 130 || echo 143)
    if ! interrupt_into_writing; then
        fail "second SIG$second: the partial image was never written; stderr: $(head -c 300 stderr)"
        continue
    fi
    kill -0 "$pid" 2> /dev/null || fail "second SIG$second: the run ended before the second signal"
    signal_and_wait "$pid" $second
    expect_stop "SIGINT, then SIG$second while writing" "$expected_status" \
        "$(awk -v f="$kill_floor" -v s="$(at_least_ten_times "$start_up" 0.5)" 'BEGIN { printf "%.3f", f + s }')"
    files=$(ls -a | grep -v -E '^(\.|\.\.|stdout|stderr)$')
    [ -z "$files" ] || fail "files left after the second signal (SIG$second): $files"
done

# --- 4. one SIGINT while the complete image is written ---
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
"$exe" --width 4096 --height 4096 --spp 1 --threads 2 --quiet --out out.png > stdout 2> stderr &
pid=$!
if wait_for_writing "$pid"; then
    kill -INT "$pid"
else
    fail "complete image: its writing was never seen"
fi
wait "$pid"
status=$?
echo "SIGINT while the complete image is written: exit status $status: $(tail -n 1 stderr)"
[ "$status" -eq 130 ] || fail "complete image: exit status $status after SIGINT while writing, expected 130"
grep -q "interrupted: finishing the files being written" stderr || fail "complete image: no message that the files are finished: $(cat stderr)"
grep -q "interrupted while writing; the complete image was written all the same" stderr ||
    fail "complete image: the run does not say the complete image was written: $(cat stderr)"
grep -q "saving the partial image" stderr && fail "complete image: the message speaks of a partial image: $(cat stderr)"
[ -f out.png ] && [ -f out.pfm ] || fail "complete image: out.png and out.pfm were not both written"
[ ! -f out.partial.png ] || fail "complete image: a partial image was written"
if [ -f out.pfm ]; then
    check=$("$pfm_check" out.pfm 2>&1) || fail "complete image PFM: $check"
fi
no_staging_files "complete image"
finish
