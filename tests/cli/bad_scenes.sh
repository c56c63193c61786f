#!/usr/bin/env bash
# bad_scenes.sh EXECUTABLE: every broken scene in tests/data/bad_scenes, through the real executable: exit
# status 2, the one line of tests/data/bad_scenes/expected.tsv (after "chNN_name: "), no file written.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
name=$(basename "$exe")
data="$here/../data/bad_scenes"

count=0
while IFS=$'\t' read -r file message; do
    [[ -z "$file" || "$file" == \#* ]] && continue
    expect_bad_input "$file" "$name: $message" 0 -- env -C "$data" "$exe" --scene "$file" --out "$work/out.png" --quiet
    count=$((count + 1))
done < "$data/expected.tsv"
echo "$count bad scenes checked with $name"
[ "$count" -ge 50 ] || fail "only $count bad scenes in expected.tsv"
finish
