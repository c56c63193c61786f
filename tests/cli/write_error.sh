#!/usr/bin/env bash
# write_error.sh EXECUTABLE: a write that fails (a full disk, emulated by a file size limit: writes beyond it
# fail with EFBIG) is reported in one line with exit status 1, and the earlier out.png and out.pfm are left
# as they were, with no staging file behind (ls -A: staging names start with a dot). Then, without the limit,
# the same run replaces both whole.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
n=$(basename "$exe")

mkdir -p "$work" && cd "$work" || exit 1
echo "earlier png" > out.png
echo "earlier pfm" > out.pfm
before=$(md5sum out.png out.pfm)
# ulimit -f counts KiB. The executable ignores SIGXFSZ itself (interrupt.hpp), so that the write fails instead
# of the signal killing the process with its staging file behind.
(ulimit -f 8; exec "$exe" --width 320 --height 180 --spp 1 --quiet --out out.png) > stdout 2> stderr
status=$?
echo "under an 8 KiB file size limit: exit status $status: $(cat stderr)"
[ "$status" -eq 1 ] || fail "exit status $status, expected 1"
[ "$(wc -l < stderr)" -eq 1 ] || fail "expected one line on stderr: $(cat stderr)"
expected="$n: failed: out.png: could not write the file (File too large); an earlier file of that name is left as it was"
[ "$(cat stderr)" = "$expected" ] || fail "message was: $(cat stderr) ... expected: $expected"
[ "$(md5sum out.png out.pfm)" = "$before" ] || fail "the earlier out.png or out.pfm was changed"
files=$(ls -A | grep -v -E '^(out\.png|out\.pfm|stdout|stderr)$')
[ -z "$files" ] || fail "files left behind: $files"

"$exe" --width 320 --height 180 --spp 1 --quiet --out out.png > stdout 2> stderr || fail "the run without a limit failed"
[ "$(head -c 4 out.png | tail -c 3)" = "PNG" ] || fail "out.png was not replaced by a PNG"
[ "$(head -c 2 out.pfm)" = "PF" ] || fail "out.pfm was not replaced by a PFM"
files=$(ls -A | grep -v -E '^(out\.png|out\.pfm|stdout|stderr)$')
[ -z "$files" ] || fail "files left behind: $files"
finish
