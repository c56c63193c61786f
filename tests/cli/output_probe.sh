#!/usr/bin/env bash
# output_probe.sh EXECUTABLE: every output is probed before the render, by creating and removing the staging
# file a write would use. An output that cannot be written (/proc takes no file, even for root; a name the
# folder cannot hold) gives exit 2 within a second of what the executable takes to start and print its help
# (0.1 s in a release build; 0.4 to 0.8 s under the sanitizers on a loaded machine, measured), however long the
# render would be, with nothing written.
# Staging names are short whatever the output's: a 226-byte output name is written, and the longest name a
# folder takes (255 bytes) is written too, its partial names refused by name. Files of other runs beside the
# output, even under the staging names of other processes, are left as they were.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
n=$(basename "$exe")
slow=(--width 1920 --height 1080 --spp 1048576 --quiet)

now() { date +%s.%N; }
# The floor: the slowest of three starts that print the help and exit (loading the libraries, and under the
# sanitizers mapping their shadow memory).
start_up=0
for _ in 1 2 3; do
    started=$(now)
    "$exe" --help > /dev/null || fail "--help failed"
    start_up=$(echo "$started $(now) $start_up" | awk '{ t = $2 - $1; printf "%.3f", (t > $3 ? t : $3) }')
done
echo "start-up (--help, the slowest of three): $start_up s"
timed_bad_input() {  # timed_bad_input EXPECTED ARGS...: exit 2 with EXPECTED, within a second of the start-up
    local expected=$1
    shift
    local start
    start=$(now)
    expect_bad_input "$*" "$n: $expected" 0 -- "$exe" "$@"
    local took
    took=$(echo "$start $(now)" | awk '{printf "%.3f", $2 - $1}')
    awk -v s="$took" -v f="$start_up" 'BEGIN { exit !(s < f + 1.0) }' ||
        fail "$*: took $took s to refuse, expected under $start_up + 1 s"
}

timed_bad_input "--out: /proc/x.png: cannot be written: folder /proc does not take a new file (No such file or directory)" \
    "${slow[@]}" --out /proc/x.png
long=$(printf 'n%.0s' $(seq 251))
timed_bad_input "--out: $long.partial.png: cannot be written: its name is 263 bytes, longer than the 255 its folder takes" \
    "${slow[@]}" --out "$long.png"

rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
name226=$(printf 'm%.0s' $(seq 222)).png
echo "theirs" > "$name226.staged-1.partial-1"
echo "theirs" > ".rt-1-0.staging"
before=$(snapshot .)
"$exe" --width 8 --height 4 --spp 1 --quiet --out "$name226" > stdout 2> stderr
status=$?
[ "$status" -eq 0 ] || fail "a 226-byte output name: exit status $status: $(cat stderr)"
[ -f "$name226" ] && [ -f "${name226%.png}.pfm" ] || fail "a 226-byte output name: the PNG and the PFM were not both written"
[ "$(cat "$name226.staged-1.partial-1")" = theirs ] && [ "$(cat .rt-1-0.staging)" = theirs ] ||
    fail "a file beside the output, under another process's staging name, was changed"
left=$(ls -a | grep -E '\.staging$' | grep -v '^\.rt-1-0\.staging$')
[ -z "$left" ] || fail "staging files left: $left"
finish
