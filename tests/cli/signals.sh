#!/usr/bin/env bash
# signals.sh EXECUTABLE RT_MERGE: no staging file (.rt-PID-N.staging) survives a signal that lands while a
# chapter or rt_merge writes its files (interrupt.hpp says which signal does what):
#  - SIGINT, SIGTERM, SIGHUP, SIGXCPU: the files being written are finished; exit 128 + the signal's number;
#    a second one, of another of these, quits at once and leaves no file;
#  - SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM: quits at once with 128 + its number, leaving no file;
#  - SIGPIPE, SIGXFSZ: ignored; the files are written, exit 0.
# The writing is caught by watching for the staging files of a 1024 × 1024 image (its PNG, PFM and 59 MB film
# take a quarter of a second or more to write); a run whose writing was not seen is tried again, up to 4 times.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
merge=$2

staging_files() { ls -a | grep -E '\.staging$'; }
# wait_for_writing PID: waits (up to 60 s) until the run has had a staging file for 10 ms (an output probe's,
# before the render, lasts microseconds); false when it ended first.
wait_for_writing() {
    local seen=0
    for _ in $(seq 6000); do
        if [ -n "$(staging_files)" ]; then
            [ $seen = 1 ] && return 0
            seen=1
        else
            seen=0
        fi
        kill -0 "$1" 2> /dev/null || return 1
        sleep 0.01
    done
    return 1
}
declare -A number=([INT]=2 [TERM]=15 [HUP]=1 [XCPU]=24 [QUIT]=3 [USR1]=10 [USR2]=12 [ALRM]=14 [PIPE]=13 [XFSZ]=25)
kind() {
    case $1 in
        INT | TERM | HUP | XCPU) echo stop ;;
        PIPE | XFSZ) echo ignore ;;
        *) echo quit ;;
    esac
}
# signal_while_writing WHAT SIGNAL SECOND_SIGNAL -- COMMAND...: runs COMMAND (which writes out.png, out.pfm
# and out.film) in $work, sends SIGNAL (then SECOND_SIGNAL, when not empty) once it writes, and checks what it
# left: its exit status, no staging file, and the files finished or none.
signal_while_writing() {
    local what=$1 signal=$2 second=$3
    shift 4
    local sent="SIG$signal${second:+, then SIG$second}"
    local try pid status seen=0
    for try in 1 2 3 4; do
        rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
        "$@" > stdout 2> stderr &
        pid=$!
        if wait_for_writing "$pid"; then
            kill -"$signal" "$pid"
            [ -n "$second" ] && sleep 0.05 && kill -"$second" "$pid" 2> /dev/null
            seen=1
        fi
        wait "$pid"
        status=$?
        [ "$seen" = 1 ] && break
    done
    [ "$seen" = 1 ] || { fail "$what: its writing was never seen"; return; }
    local outcome expected
    outcome=$(kind "$signal")
    [ -n "$second" ] && outcome=quit
    expected=$((128 + number[${second:-$signal}]))
    [ "$outcome" = ignore ] && expected=0
    echo "$what: $sent while writing: exit status $status"
    [ "$status" -eq "$expected" ] || fail "$what, $sent: exit status $status, expected $expected: $(head -c 300 stderr)"
    local left
    left=$(staging_files)
    [ -z "$left" ] || fail "$what, $sent: staging files left: $left"
    if [ "$outcome" = quit ]; then
        [ ! -e out.png ] && [ ! -e out.pfm ] && [ ! -e out.film ] || fail "$what, $sent: files written after quitting at once"
    else
        [ -s out.png ] && [ -s out.pfm ] && [ -s out.film ] || fail "$what, $sent: the files being written were not finished"
    fi
}

pieces="$scratch/pieces" && mkdir -p "$pieces" || exit 1
size=(--width 1024 --height 1024 --spp 2 --threads 2 --quiet)
for range in 0:1 1:2; do
    "$exe" "${size[@]}" --samples $range --out "$pieces/p${range%%:*}.png" > /dev/null 2>&1 || fail "piece $range failed"
done
for signal in INT TERM HUP XCPU QUIT USR1 USR2 ALRM PIPE XFSZ; do
    signal_while_writing "$(basename "$exe")" $signal "" -- "$exe" "${size[@]}" --samples 0:2 --out out.png
    signal_while_writing rt_merge $signal "" -- "$merge" --out out.png "$pieces/p0.film" "$pieces/p1.film"
done
signal_while_writing "$(basename "$exe")" HUP INT -- "$exe" "${size[@]}" --samples 0:2 --out out.png
signal_while_writing rt_merge INT TERM -- "$merge" --out out.png "$pieces/p0.film" "$pieces/p1.film"
finish
