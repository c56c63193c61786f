#!/usr/bin/env bash
# bad_flags.sh EXECUTABLE: zero, negative and absurd sizes, samples, threads and seeds; references that are
# missing, unreadable or of another size; output paths that cannot be written. Each must exit with status 2
# and one line naming the flag, with no file created or overwritten.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
n=$(basename "$exe")
small=(--width 8 --height 4 --spp 1 --quiet)

check() {  # check EXPECTED_LINE ARGS...
    local expected=$1
    shift
    expect_bad_input "$*" "$n: $expected" 0 -- "$exe" "$@"
}
check_prefix() {  # check_prefix EXPECTED_START ARGS...: for messages that name this machine's memory
    local expected=$1
    shift
    expect_bad_input "$*" "$n: $expected" 1 -- "$exe" "$@"
}

check "usage: --width: Value 0 not in range 1 to 65536 (see --help)" --width 0 --quiet
check "usage: --height: Value -3 not in range 1 to 65536 (see --help)" --height -3 --quiet
check "usage: --width: Value 1e9 not in range 1 to 65536 (see --help)" --width 1e9 --quiet
check "usage: --width: Value 99999999999999999999 not in range 1 to 65536 (see --help)" --width 99999999999999999999
check "usage: --width: Value abc not in range 1 to 65536 (see --help)" --width abc
check "usage: --spp: Value 0 not in range 1 to 1048576 (see --help)" --spp 0
check "usage: --spp: Value -1 not in range 1 to 1048576 (see --help)" --spp -1
check "usage: --spp: Value 2000000 not in range 1 to 1048576 (see --help)" --spp 2000000
check "usage: --threads: Value -1 not in range 0 to 1024 (see --help)" --threads -1
check "usage: --threads: Value 100000 not in range 0 to 1024 (see --help)" --threads 100000
check "usage: --seed: must be a whole number >= 0, got -1 (see --help)" --seed -1
check "usage: The following argument was not expected: --bogus (see --help)" --bogus
check "usage: --width: 1 required INT:INT in [1 - 65536] missing (see --help)" --width
# Buffers that would not fit in memory are refused before allocation, with the size they would need (103.1 GB
# for float pixels; bad_input_test checks the figure).
check_prefix "--width/--height: image size 65536x65536 needs " \
    --width 65536 --height 65536 --quiet

# References: missing, a folder, not a PFM, truncated, another size.
mkdir -p "$scratch/ref"
printf 'P6\n8 4\n255\n' > "$scratch/ref/p6.pfm"
printf 'PF\n8 4\n-1.0\nshort' > "$scratch/ref/short.pfm"
"$exe" --width 6 --height 4 --spp 1 --quiet --out "$scratch/ref/six.png" > /dev/null || fail "could not render a reference"
check "--reference: $scratch/ref/absent.pfm: must be a PFM file, got no such file" "${small[@]}" --reference "$scratch/ref/absent.pfm"
check "--reference: $scratch/ref: must be a PFM file, got something else (a folder?)" "${small[@]}" --reference "$scratch/ref"
check "--reference: $scratch/ref/p6.pfm: must be a colour PFM file starting with \"PF\", got \"P6\"" "${small[@]}" --reference "$scratch/ref/p6.pfm"
check "--reference: $scratch/ref/short.pfm: PFM data must be 384 bytes for 8x4, got 5 (truncated)" "${small[@]}" --reference "$scratch/ref/short.pfm"
check "--reference: $scratch/ref/six.pfm: must be the size of the image, 8x4, got 6x4" "${small[@]}" --reference "$scratch/ref/six.pfm"

# Output paths: a missing folder, a parent that is a file (unwritable even for root), a folder in the way of
# the PNG or of the PFM beside it, a name that is not .png.
check "--out: missing/x.png: cannot be written: folder missing does not exist" "${small[@]}" --out missing/x.png
check "--out: out.png/x.png: cannot be written: out.png is a file, not a folder" "${small[@]}" --out out.png/x.png
check "--out: must end in .png, got out.jpg" "${small[@]}" --out out.jpg
mkdir -p "$scratch/folders/picture.png" "$scratch/folders/other.pfm"
check "--out: $scratch/folders/picture.png: cannot be written: it is a folder" "${small[@]}" --out "$scratch/folders/picture.png"
check "--out: $scratch/folders/other.pfm: cannot be written: it is a folder" "${small[@]}" --out "$scratch/folders/other.png"
check "$scratch/absent.json: must be a scene file (JSON), got no such file" "${small[@]}" --scene "$scratch/absent.json"
check "$scratch: must be a scene file (JSON), got something else (a folder?)" "${small[@]}" --scene "$scratch"
finish
