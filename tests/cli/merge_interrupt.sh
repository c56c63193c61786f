#!/usr/bin/env bash
# merge_interrupt.sh EXECUTABLE RT_MERGE: SIGINT while rt_merge reads its pieces. The pieces it has not read
# yet are missing through no fault of theirs: it exits 130, says "rt_merge: interrupted; nothing written" and
# writes nothing, as a signal a moment later does (it used to exit 2, blaming the unread piece's samples).
# The signal is made to land while the first of two pieces (a 59 MB film) is read: once /proc shows the file
# open, the run is stopped (SIGSTOP), the file checked open still, and the run sent SIGINT and continued. A try
# that finds the file closed already is made again, up to 8 times.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
merge=$2

pieces="$scratch/pieces" && mkdir -p "$pieces" || exit 1
size=(--width 1024 --height 1024 --spp 2 --threads 2 --quiet)
for range in 0:1 1:2; do
    "$exe" "${size[@]}" --samples $range --out "$pieces/p${range%%:*}.png" > /dev/null 2>&1 || fail "piece $range failed"
done
first="$pieces/p0.film"
# reading_first PID: whether the run has the first piece open.
reading_first() {
    local fd
    for fd in /proc/"$1"/fd/*; do
        [ "$(readlink "$fd" 2> /dev/null)" = "$first" ] && return 0
    done
    return 1
}
# wait_for_first PID: waits (up to 60 s) until the run opens the first piece; false when it ended first.
wait_for_first() {
    for _ in $(seq 6000); do
        reading_first "$1" && return 0
        kill -0 "$1" 2> /dev/null || return 1
        sleep 0.01
    done
    return 1
}

seen=0
for try in 1 2 3 4 5 6 7 8; do
    rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
    "$merge" --out out.png "$first" "$pieces/p1.film" > stdout 2> stderr &
    pid=$!
    if wait_for_first "$pid"; then
        kill -STOP "$pid"
        if reading_first "$pid"; then
            kill -INT "$pid"
            seen=1
        fi
        kill -CONT "$pid"
    fi
    wait "$pid"
    status=$?
    [ "$seen" = 1 ] && break
    echo "  (try $try: the first piece was read before the signal could land; again)"
done
if [ "$seen" = 1 ]; then
    echo "SIGINT while rt_merge reads its first piece: exit status $status: $(tail -n 1 stderr)"
    [ "$status" -eq 130 ] || fail "exit status $status, expected 130: $(head -c 300 stderr)"
    grep -q "^rt_merge: interrupted; nothing written$" stderr || fail "no \"nothing written\": $(head -c 300 stderr)"
    grep -q "in no piece" stderr && fail "an unread piece is blamed: $(head -c 300 stderr)"
    files=$(ls -a | grep -v -E '^(\.|\.\.|stdout|stderr)$')
    [ -z "$files" ] || fail "files left: $files"
else
    fail "the signal never landed while the first piece was read"
fi
finish
