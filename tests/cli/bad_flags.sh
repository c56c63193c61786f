#!/usr/bin/env bash
# bad_flags.sh EXECUTABLE: zero, negative and absurd sizes, samples, threads and seeds; references that are
# missing, unreadable or of another size; output paths that cannot be written. Each must exit with status 2
# and one line naming the flag, with no file created or overwritten.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
n=$(basename "$exe")
small=(--width 8 --height 4 --spp 1 --quiet)
W_NUMBER="must be a whole number (decimal digits, a '-' before them if negative)"

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
check "usage: --width: must be a whole number (decimal digits, a '-' before them if negative), got \"1e9\" (see --help)" --width 1e9 --quiet
check "usage: --width: must be a whole number (decimal digits, a '-' before them if negative) that fits in 64 bits (at most 9223372036854775807), got \"99999999999999999999\" (see --help)" --width 99999999999999999999
check "usage: --width: must be a whole number (decimal digits, a '-' before them if negative), got \"abc\" (see --help)" --width abc
check "usage: --spp: Value 0 not in range 1 to 1048576 (see --help)" --spp 0
check "usage: --spp: Value -1 not in range 1 to 1048576 (see --help)" --spp -1
check "usage: --spp: Value 2000000 not in range 1 to 1048576 (see --help)" --spp 2000000
check "usage: --threads: Value -1 not in range 0 to 1024 (see --help)" --threads -1
check "usage: --threads: Value 100000 not in range 0 to 1024 (see --help)" --threads 100000
check "usage: --seed: must be a whole number >= 0 (decimal digits only), got \"-1\" (see --help)" --seed -1
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
check "--reference: $scratch/ref: must be a PFM file, got a folder" "${small[@]}" --reference "$scratch/ref"
check "--reference: $scratch/ref/p6.pfm: must be a colour PFM file starting with \"PF\", got \"P6\"" "${small[@]}" --reference "$scratch/ref/p6.pfm"
check "--reference: $scratch/ref/short.pfm: PFM data must be 384 bytes for 8x4, got 5 (truncated)" "${small[@]}" --reference "$scratch/ref/short.pfm"
check "--reference: $scratch/ref/six.pfm: must be the size of the image, 8x4, got 6x4" "${small[@]}" --reference "$scratch/ref/six.pfm"

# Output paths: a missing folder, a parent that is a file (unwritable even for root), a folder in the way of
# the PNG or of the PFM beside it, a name that is not .png.
check "--out: missing/x.png: cannot be written: folder missing does not exist" "${small[@]}" --out missing/x.png
check "--out: out.png/x.png: cannot be written: out.png is a file, not a folder" "${small[@]}" --out out.png/x.png
check "--out: must name a file ending in .png or .exr, with a name before the extension, got out.jpg" "${small[@]}" --out out.jpg
mkdir -p "$scratch/folders/picture.png" "$scratch/folders/other.pfm"
check "--out: $scratch/folders/picture.png: cannot be written: it is a folder" "${small[@]}" --out "$scratch/folders/picture.png"
check "--out: $scratch/folders/other.pfm: cannot be written: it is a folder" "${small[@]}" --out "$scratch/folders/other.png"
check "$scratch/absent.json: must be a scene file (JSON or pbrt-v4), got no such file" "${small[@]}" --scene "$scratch/absent.json"
check "$scratch: must be a scene file (JSON or pbrt-v4), got a folder" "${small[@]}" --scene "$scratch"
# Empty values and values CLI11 alone would read as something else: refused, never replaced.
check "usage: --scene: must not be empty (see --help)" "${small[@]}" --scene ""
check "usage: --out: must not be empty (see --help)" "${small[@]}" --out ""
check "usage: --reference: must not be empty (see --help)" "${small[@]}" --reference ""
check "usage: --seed: must be a whole number >= 0 (decimal digits only) that fits in 64 bits (at most 18446744073709551615), got \"18446744073709551616\" (see --help)" "${small[@]}" --seed 18446744073709551616
check "usage: --seed: must be a whole number >= 0 (decimal digits only), got \" -1\" (see --help)" "${small[@]}" --seed " -1"
check "usage: --seed: must be a whole number >= 0 (decimal digits only) without a leading 0, got \"010\" (see --help)" "${small[@]}" --seed 010
check "usage: --spp: $W_NUMBER, got \"0x10\" (see --help)" --width 8 --height 4 --quiet --spp 0x10
check "usage: --threads: $W_NUMBER, got \"2 \" (see --help)" "${small[@]}" --threads "2 "
# A value holding a newline or an escape byte stays on one line, escaped.
check "usage: --width: $W_NUMBER, got \"8\\n9\" (see --help)" --width $'8\n9' --quiet
check "--out: \"x\\x1b[31m/y.png\": cannot be written: folder \"x\\x1b[31m\" does not exist" "${small[@]}" --out $'x\e[31m/y.png'
check "--out: must name a file ending in .png or .exr, with a name before the extension, got .png" "${small[@]}" --out .png
check "--out: must name a file ending in .png or .exr, with a name before the extension, got out/" "${small[@]}" --out out/
# A symbolic link loop is named as one, not as a missing file.
ln -s loop_b "$scratch/loop_a"
ln -s loop_a "$scratch/loop_b"
check "$scratch/loop_a: must be a scene file (JSON or pbrt-v4), got a path that cannot be followed (Too many levels of symbolic links)" "${small[@]}" --scene "$scratch/loop_a"
check "--reference: $scratch/loop_a: must be a PFM file, got a path that cannot be followed (Too many levels of symbolic links)" "${small[@]}" --reference "$scratch/loop_a"
# References: negative radiance; a CRLF header; the file this run would write.
{ printf 'PF\n8 4\n-1.0\n'; head -c 380 /dev/zero; printf '\x00\x00\x80\xbf'; } > "$scratch/ref/negative.pfm"
check "--reference: $scratch/ref/negative.pfm: pixel (7, 0) must be finite radiance, >= 0, got 0 0 -1" "${small[@]}" --reference "$scratch/ref/negative.pfm"
{ printf 'PF\r\n8 4\r\n-1.0\r\n'; head -c 384 /dev/zero; } > "$scratch/ref/crlf.pfm"
check "--reference: $scratch/ref/crlf.pfm: PFM header must end in one whitespace byte before the pixels, got \"\\r\\n\" (a Windows line end)" "${small[@]}" --reference "$scratch/ref/crlf.pfm"
"$exe" "${small[@]}" --out "$scratch/ref/mine.png" > /dev/null || fail "could not render mine.png"
cp "$scratch/ref/mine.pfm" "$scratch/ref/mine.before"
check "--out: the radiance $scratch/ref/mine.pfm is the reference $scratch/ref/mine.pfm: it would be replaced; give another name" "${small[@]}" --out "$scratch/ref/mine.png" --reference "$scratch/ref/mine.pfm"
cmp -s "$scratch/ref/mine.pfm" "$scratch/ref/mine.before" || fail "the reference that is the output was changed"
# PNG references (a lesson's picture): missing, not a PNG, another size, the run's own PNG; and a good one
# compared level by level.
printf 'not a png' > "$scratch/ref/text.png"
check "--reference: $scratch/ref/absent.png: must be a PNG file, got no such file" "${small[@]}" --reference "$scratch/ref/absent.png"
check_prefix "--reference: $scratch/ref/text.png: must be a PNG file, got one stb_image cannot read (" "${small[@]}" --reference "$scratch/ref/text.png"
check "--reference: $scratch/ref/six.png: must be the size of the image, 8x4, got 6x4" "${small[@]}" --reference "$scratch/ref/six.png"
check "--out: the image $scratch/ref/mine.png is the reference $scratch/ref/mine.png: it would be replaced; give another name" "${small[@]}" --out "$scratch/ref/mine.png" --reference "$scratch/ref/mine.png"
cp "$scratch/ref/mine.png" "$scratch/ref/expected.png"
"$exe" "${small[@]}" --out "$scratch/ref/again.png" --reference "$scratch/ref/expected.png" > "$scratch/ref/again.txt" || fail "a PNG reference of the same render was refused"
grep -q "^    0 of 32 pixels differ by more than 0 of 255" "$scratch/ref/again.txt" || fail "the same render against its own picture: $(cat "$scratch/ref/again.txt")"
# --heat: a PNG name other than the image's; written beside it with the summary's line.
check "--heat: must end in .png, got $scratch/ref/heat.jpg" "${small[@]}" --heat "$scratch/ref/heat.jpg"
check "--heat: the heat maps $scratch/ref/mine.png is the image $scratch/ref/mine.png: one would replace the other; give another name" "${small[@]}" --out "$scratch/ref/mine.png" --heat "$scratch/ref/mine.png"
"$exe" "${small[@]}" --out "$scratch/ref/h.png" --heat "$scratch/ref/heat.png" > "$scratch/ref/heat.txt" || fail "--heat failed"
[ -s "$scratch/ref/heat.png" ] || fail "--heat wrote no picture"
grep -q "note: heat maps in $scratch/ref/heat.png: rays per sample (up to 1) | bounces per sample (up to 0) | samples (up to 1)" "$scratch/ref/heat.txt" || fail "--heat: $(cat "$scratch/ref/heat.txt")"
# A scene's own image too large is not refused when the flags set the size; the size rendered is checked.
printf '{"camera": {"from": [0, 0, 5], "at": [0, 0, 0]}, "image": {"width": 65536, "height": 65536}}' > "$scratch/huge_image.json"
check_prefix "$scratch/huge_image.json: image: image size 65536x65536 needs " --scene "$scratch/huge_image.json" --quiet
"$exe" --scene "$scratch/huge_image.json" "${small[@]}" --out "$scratch/small.png" > /dev/null 2>&1 || fail "--width/--height do not override a scene's too large image"
finish
