#!/usr/bin/env bash
# output_probe.sh EXECUTABLE: every output is probed before the render, by creating and removing the staging
# file a write would use. An output that cannot be written (/proc takes no file, even for root; a name the
# folder cannot hold) gives exit 2 with nothing written, long before the render would end (hours): within ten
# times what the executable takes to start and print its help (0.1 s in a release build; 0.4 to 0.8 s under the
# sanitizers on a loaded machine, measured), or 5 s where that is less.
# Staging names are short whatever the output's: a 226-byte output name is written, and the longest name a
# folder takes (255 bytes) is written too, its partial names refused by name. Files of other runs beside the
# output, even under the staging names of other processes, are left as they were.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
n=$(basename "$exe")
slow=(--width 1920 --height 1080 --spp 1048576 --quiet)

start_up=$(start_up_seconds "$exe") || exit 1
limit=$(at_least_ten_times "$start_up" 5.0)
echo "start-up (--help, the slowest of three): $start_up s; a refusal must come within $limit s"
timed_bad_input() {  # timed_bad_input EXPECTED ARGS...: exit 2 with EXPECTED, within $limit s (the render: hours)
    local expected=$1
    shift
    local start
    start=$(now)
    expect_bad_input "$*" "$n: $expected" 0 -- "$exe" "$@"
    local took
    took=$(seconds_between "$start" "$(now)")
    awk -v s="$took" -v l="$limit" 'BEGIN { exit !(s < l) }' || fail "$*: took $took s to refuse, expected under $limit s"
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
