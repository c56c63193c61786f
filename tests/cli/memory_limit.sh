#!/usr/bin/env bash
# memory_limit.sh EXECUTABLE: under a limit on the process's memory (ulimit -v), an image too large for it is
# refused before allocation (exit 2, naming the flags and the limit), and a scene file too large to read is
# refused naming the file (exit 2), and so is a film too large for it (--resume), never "std::bad_alloc". Skipped under AddressSanitizer, which reserves
# more address space than any such limit allows.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
n=$(basename "$exe")
if ldd "$exe" 2> /dev/null | grep -q asan; then
    echo "skipped: $n is built with AddressSanitizer"
    exit 0
fi
limited() { (ulimit -v 1000000; exec "$exe" "$@"); }  # 1 GB of address space
expect_bad_input "16384x16384 under 1 GB" \
    "$n: --width/--height: image size 16384x16384 needs 20.4 GB of buffers, more than half of the 1.0 GB this process may use (ulimit -v)" 0 -- \
    limited --width 16384 --height 16384 --quiet
truncate -s 3G "$scratch/huge.json"  # sparse: no disk used
expect_bad_input "a 3 GB scene under 1 GB" \
    "$n: $scratch/huge.json: too large to read into memory (3221225472 bytes, more than this machine or this process's limit, ulimit -v, can hold)" 0 -- \
    limited --scene "$scratch/huge.json" --quiet
truncate -s 3G "$scratch/huge.film"  # a film is read whole, and its sums take as much again
expect_bad_input "a 3 GB film under 1 GB" \
    "$n: --resume: $scratch/huge.film: a film of 3221225472 bytes needs 6.4 GB of buffers, more than half of the 1.0 GB this process may use (ulimit -v)" 0 -- \
    limited --resume "$scratch/huge.film" --quiet
finish
