#!/usr/bin/env bash
# merge_refusals.sh EXECUTABLE OTHER_EXECUTABLE RT_MERGE: what does not fit is refused with exit 2, one line
# naming the offending piece, and no file written: rt_merge given a gap, an overlap, pieces of other renders
# (seed, size, samples per pixel, chapter flags, scene, chapter), an interrupted piece, a corrupt, truncated or
# other-version film, a film holding values no render writes (a negative sum, one past what its samples
# reach, a NaN flag), or a file that is no film; pieces of a scene whose texture image or mesh normals or
# texture coordinates changed between them; a chapter given a bad --samples or a --resume film that does not
# fit or holds such values.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
other=$2
merge=$3
name=$(basename "$exe")
pieces="$scratch/pieces" && mkdir -p "$pieces" && cd "$pieces" || exit 1
base=(--width 16 --height 8 --spp 6 --threads 2 --quiet)
piece() {  # piece OUT RANGE [FLAGS...]: renders one piece into $pieces
    local out=$1 range=$2
    shift 2
    "$exe" "${base[@]}" --samples "$range" --out "$out.png" "$@" > /dev/null 2>&1 || fail "piece $out ($range) failed"
}
piece a 0:2
piece b 2:4
piece c 4:6
piece overlap 3:6
piece seed 2:4 --seed 7
piece flags 2:4 --pixel-sampler uniform
piece scene 2:4 --scene "$here/../../assets/scenes/cornell.json"
"$exe" --width 16 --height 9 --spp 6 --threads 2 --quiet --samples 2:4 --out size.png > /dev/null 2>&1 || fail "size piece"
"$exe" --width 16 --height 8 --spp 8 --threads 2 --quiet --samples 2:4 --out spp.png > /dev/null 2>&1 || fail "spp piece"
"$other" "${base[@]}" --samples 2:4 --out chapter.png > /dev/null 2>&1 || fail "chapter piece"
# One scene's pieces, its files changed between them: its texture image (b.png in place of wood.png), its
# mesh's first normal, its mesh's first texture coordinate. Restored, a piece fits again.
S="$pieces/scene_files" && mkdir -p "$S"
cp "$here/../../assets/textures/ch04_wood.png" "$S/wood.png.original" && cp "$S/wood.png.original" "$S/wood.png"
cp "$here/../../assets/meshes/ch04_torus.obj" "$S/torus.obj.original" && cp "$S/torus.obj.original" "$S/torus.obj"
cat > "$S/scene.json" <<'JSON'
{
  "camera": {"from": [0, 1, 5], "at": [0, 0, 0]},
  "materials": {"wood": {"type": "diffuse", "albedo": {"texture": "wood.png"}},
                "matte": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "shapes": [{"type": "sphere", "center": [-1.5, 0, 0], "radius": 0.5, "material": "wood"},
             {"type": "mesh", "file": "torus.obj", "material": "matte"}]
}
JSON
piece files_a 0:2 --scene "$S/scene.json"
piece files_c 4:6 --scene "$S/scene.json"
cp b.png "$S/wood.png"
piece texture 2:4 --scene "$S/scene.json"
cp "$S/wood.png.original" "$S/wood.png"
sed -i '0,/^vn /s/^vn .*/vn 0.6 0.8 0/' "$S/torus.obj"
piece normal 2:4 --scene "$S/scene.json"
cp "$S/torus.obj.original" "$S/torus.obj"
sed -i '0,/^vt /s/^vt .*/vt 0.5 0.5/' "$S/torus.obj"
piece uv 2:4 --scene "$S/scene.json"
cp "$S/torus.obj.original" "$S/torus.obj"
piece files_b 2:4 --scene "$S/scene.json"
# Corrupt: one byte of the pixel data changed. Truncated: the last 100 bytes cut. Version: the version field
# (bytes 8-11) set to 2. Not a film: a PFM.
cp b.film corrupt.film && printf '\x55' | dd of=corrupt.film bs=1 seek=500 conv=notrunc status=none
head -c -100 b.film > truncated.film
cp b.film version.film && printf '\x01' | dd of=version.film bs=1 seek=8 conv=notrunc status=none
# Interrupted: b.film's range widened to 2:5 (checksum recomputed), so its pixels have 2 of its 3 samples.
python3 - b.film interrupted.film <<'PY'
import struct, sys
data = bytearray(open(sys.argv[1], "rb").read()[:-8])
struct.pack_into("<I", data, 32, 5)  # the end sample (see common/README.md, "The film file")
h = 0xcbf29ce484222325
for b in data:
    h = ((h ^ b) * 0x100000001b3) & 0xffffffffffffffff
open(sys.argv[2], "wb").write(data + struct.pack("<Q", h))
PY
# Values no render writes, in b.film's first pixel (after the header and its three texts): a negative red sum,
# a red sum near 2^127 (two such pieces wrapped the 128-bit sum), a NaN flag. Before they were checked they
# merged to pixels of -1e12, to nonsense, and to exit 1 ("a bug in the chapter").
python3 - b.film <<'PY'
import struct, sys
data = bytearray(open(sys.argv[1], "rb").read()[:-8])
at = 8 + 4 * 7 + 8 * 2
for _ in range(3):
    at += 4 + struct.unpack_from("<I", data, at)[0]
def write(name, red=None, flags=None):
    d = bytearray(data)
    if red is not None:
        d[at:at + 16] = (red & ((1 << 128) - 1)).to_bytes(16, "little")
    if flags is not None:
        struct.pack_into("<I", d, at + 100, flags)  # after the three sums and the three high parts, the count
    h = 0xcbf29ce484222325
    for b in d:
        h = ((h ^ b) * 0x100000001b3) & 0xffffffffffffffff
    open(name, "wb").write(d + struct.pack("<Q", h))
write("negative.film", red=-(10**12 << 56))
write("huge.film", red=(1 << 127) - 5)
write("nan.film", flags=1)
PY
P=$pieces
# The control: the pieces that fit are merged.
"$merge" --out "$scratch/control.png" "$P/c.film" "$P/a.film" "$P/b.film" > /dev/null 2>&1 || fail "a, b and c were not merged"

refused() {  # refused WHAT EXPECTED_PREFIX PIECES...
    local what=$1 expected=$2
    shift 2
    expect_bad_input "rt_merge: $what" "rt_merge: $expected" 1 -- "$merge" --out out.png "$@"
}
refused "a gap" "$P/c.film: takes samples 4:6, but samples 2:4 are in no piece (the piece before is $P/a.film, 0:2)" \
    "$P/a.film" "$P/c.film"
refused "a gap at the start" "$P/b.film: takes samples 2:4, but samples 0:2 are in no piece" "$P/c.film" "$P/b.film"
refused "a gap at the end" "$P/b.film: the last piece ends at sample 4, but samples 4:6 are in no piece" \
    "$P/a.film" "$P/b.film"
refused "an overlap" "$P/overlap.film: takes samples 3:6, which overlap $P/b.film (2:4) at samples 3:4" \
    "$P/a.film" "$P/b.film" "$P/overlap.film"
refused "the same piece twice" "$P/b.film: takes samples 2:4, which overlap $P/b.film (2:4) at samples 2:4" \
    "$P/a.film" "$P/b.film" "$P/b.film" "$P/c.film"
refused "another seed" "$P/seed.film: not a piece of the same render as $P/a.film: seed 7, expected 1" \
    "$P/a.film" "$P/seed.film" "$P/c.film"
refused "another size" "$P/size.film: not a piece of the same render as $P/a.film: size 16x9, expected 16x8" \
    "$P/a.film" "$P/size.film" "$P/c.film"
refused "another spp" "$P/spp.film: not a piece of the same render as $P/a.film: samples per pixel 8, expected 6" \
    "$P/a.film" "$P/spp.film" "$P/c.film"
refused "other chapter flags" "$P/flags.film: not a piece of the same render as $P/a.film: chapter flags \"--pixel-sampler=uniform\", expected \"\"" \
    "$P/a.film" "$P/flags.film" "$P/c.film"
refused "another scene" "$P/scene.film: not a piece of the same render as $P/a.film: scene cornell.json" \
    "$P/a.film" "$P/scene.film" "$P/c.film"
"$merge" --out "$scratch/files.png" "$P/files_a.film" "$P/files_b.film" "$P/files_c.film" > /dev/null 2>&1 ||
    fail "pieces of one scene, its files restored, were not merged"
for changed in texture normal uv; do
    refused "another $changed in the scene's files" \
        "$P/$changed.film: not a piece of the same render as $P/files_a.film: scene scene.json (its files' fingerprint " \
        "$P/files_a.film" "$P/$changed.film" "$P/files_c.film"
done
refused "another chapter" "$P/chapter.film: not a piece of the same render as $P/a.film: chapter $(basename "$other"), expected $name" \
    "$P/a.film" "$P/chapter.film" "$P/c.film"
refused "a corrupt film" "$P/corrupt.film: corrupt: its checksum does not match its contents" \
    "$P/a.film" "$P/corrupt.film" "$P/c.film"
refused "a truncated film" "$P/truncated.film: corrupt: its checksum does not match its contents" \
    "$P/a.film" "$P/truncated.film" "$P/c.film"
refused "another version" "$P/version.film: film version 1, this program reads version 2" \
    "$P/a.film" "$P/version.film" "$P/c.film"
refused "a PFM" "$P/b.pfm: not a film file (it does not start with \"rt-film\")" "$P/a.film" "$P/b.pfm" "$P/c.film"
refused "a missing piece" "$P/none.film: must be a film file, got no such file" "$P/a.film" "$P/none.film"
refused "no piece" "usage: pieces is required (see --help)" 
refused "an interrupted piece" "$P/interrupted.film: an interrupted render (some pixels have 2 of its samples 2:5): finish it first with --resume $P/interrupted.film" \
    "$P/a.film" "$P/interrupted.film" "$P/c.film"
refused "a negative sum" "$P/negative.film: pixel (0, 0) has a sum of -1e+12 in channel 0 for 2 samples, outside [" \
    "$P/a.film" "$P/negative.film" "$P/c.film"
refused "a sum past what its samples reach" "$P/huge.film: pixel (0, 0) has a sum of 2.36118e+21 in channel 0" \
    "$P/a.film" "$P/huge.film" "$P/c.film"
refused "a NaN flag" "$P/nan.film: pixel (0, 0) holds a NaN or infinite sample: the render that wrote it failed" \
    "$P/a.film" "$P/nan.film" "$P/c.film"
expect_bad_input "rt_merge: --out not .png" "rt_merge: --out: must name a file ending in .png or .exr, with a name before the extension, got out.pfm" 0 -- \
    "$merge" --out out.pfm "$P/a.film" "$P/b.film" "$P/c.film"


# The chapter's side: bad --samples and --resume films that do not fit, before any render.
chapter_refused() {  # chapter_refused WHAT EXPECTED ARGS...
    local what=$1 expected=$2
    shift 2
    expect_bad_input "$name $what" "$name: $expected" 1 -- "$exe" "${base[@]}" --out out.png "$@"
}
chapter_refused "--samples empty range" "--samples: must be A:B with 0 <= A < B <= 6 (the samples per pixel), got 3:3" --samples 3:3
chapter_refused "--samples past spp" "--samples: must be A:B with 0 <= A < B <= 6 (the samples per pixel), got 0:7" --samples 0:7
chapter_refused "--samples not a range" "--samples: must be A:B with 0 <= A < B <= 6 (the samples per pixel), got 2" --samples 2
chapter_refused "--resume another seed" "--resume: $P/seed.film: a film of another render: seed 7, expected 1" --resume "$P/seed.film"
sed -i '0,/^vn /s/^vn .*/vn 0.6 0.8 0/' "$S/torus.obj"
chapter_refused "--resume after the mesh's normals changed" \
    "--resume: $P/files_a.film: a film of another render: scene scene.json (its files' fingerprint " \
    --scene "$S/scene.json" --resume "$P/files_a.film"
cp "$S/torus.obj.original" "$S/torus.obj"
chapter_refused "--resume a negative sum" "--resume: $P/negative.film: pixel (0, 0) has a sum of -1e+12" --resume "$P/negative.film"
chapter_refused "--resume corrupt" "--resume: $P/corrupt.film: corrupt" --resume "$P/corrupt.film"
chapter_refused "--resume moved" "--resume: $P/b.film: takes samples 2:4: --samples can only extend it (2:B, B >= 4), got 0:6" \
    --resume "$P/b.film" --samples 0:6
finish
