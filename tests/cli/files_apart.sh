#!/usr/bin/env bash
# files_apart.sh EXECUTABLE RT_MERGE RT_COMPARE: no input of a tool or a run is ever overwritten, and no output
# of one is lost under another (exit 2, one line, before any work, nothing changed), by name or by a link:
#  1. rt_merge --out naming a piece (its x.film), rt_compare --out naming image A or B;
#  2. a run's --heat or --csv naming a file the run writes (x.partial.png, written when interrupted; x.pfm),
#     or its scene; --resume NAME.partial.film may still be replaced by the run's own film; any output (the
#     image, the radiance, the heat maps, the partial image, the film) naming a file the scene reads (a
#     texture, the environment image, a mesh);
#  3. what rt_merge prints of a film (its chapter, scene and flags) and of a piece's name, escaped: no newline,
#     escape byte or NUL reaches the terminal.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
merge=$2
compare=$3
P="$scratch/pieces" && mkdir -p "$P" && cd "$P" || exit 1
base=(--width 16 --height 8 --spp 4 --threads 2 --quiet)
for range in 0:2 2:4; do
    "$exe" "${base[@]}" --samples $range --out "p${range%%:*}.png" > /dev/null 2>&1 || fail "piece $range failed"
done
ln -s p0.film alias.film
"$exe" --width 16 --height 8 --spp 1 --threads 2 --quiet --out ca.png > /dev/null 2>&1 || fail "ca.png failed"
cp ca.png cb.png
cp "$here/../../assets/scenes/ch01_default.json" scene.json
# A scene that reads a texture (and another named like a partial image), an environment image (a PFM) and a
# mesh named like a film.
S="$P/scene_files" && mkdir -p "$S"
cp "$here/../../assets/textures/ch04_wood.png" "$S/wood.png"
cp ca.png "$S/x.partial.png"
cp ca.pfm "$S/sky.pfm"
cp "$here/../../assets/meshes/ch04_torus.obj" "$S/torus.film"
cat > "$S/scene.json" <<'JSON'
{
  "camera": {"from": [0, 1, 5], "at": [0, 0, 0]},
  "materials": {"wood": {"type": "diffuse", "albedo": {"texture": "wood.png"}},
                "tiles": {"type": "diffuse", "albedo": {"texture": "x.partial.png"}},
                "matte": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "shapes": [{"type": "sphere", "center": [-1.5, 0, 0], "radius": 0.5, "material": "wood"},
             {"type": "sphere", "center": [1.5, 0, 0], "radius": 0.5, "material": "tiles"},
             {"type": "mesh", "file": "torus.film", "material": "matte"}],
  "lights": [{"type": "environment", "image": "sky.pfm"}]
}
JSON
inputs_before=$(snapshot "$P")
unchanged() { [ "$(snapshot "$P")" = "$inputs_before" ] || fail "$1: an input was changed"; }

# --- 1. the tools ---
expect_bad_input "rt_merge --out naming a piece" \
    "rt_merge: --out: the merged film $P/p0.film is the piece $P/p0.film: it would be replaced; give another name" \
    0 -- "$merge" --out "$P/p0.png" "$P/p0.film" "$P/p2.film"
unchanged "rt_merge --out naming a piece"
expect_bad_input "rt_merge --out naming a piece by a link" \
    "rt_merge: --out: the merged film $P/p0.film is the piece $P/alias.film: it would be replaced; give another name" \
    0 -- "$merge" --out "$P/p0.png" "$P/alias.film" "$P/p2.film"
unchanged "rt_merge --out naming a piece by a link"
expect_bad_input "rt_merge --out naming a piece by a relative path" \
    "rt_merge: --out: the merged film ../pieces/p2.film is the piece $P/p2.film: it would be replaced; give another name" \
    0 -- "$merge" --out ../pieces/p2.png "$P/p0.film" "$P/p2.film"
unchanged "rt_merge --out naming a piece by a relative path"
expect_bad_input "rt_compare --out naming image A" \
    "rt_compare: --out: the comparison picture $P/ca.png is image A $P/ca.png: it would be replaced; give another name" \
    0 -- "$compare" "$P/ca.png" "$P/cb.png" --out "$P/ca.png"
expect_bad_input "rt_compare --out naming image B" \
    "rt_compare: --out: the comparison picture $P/cb.png is image B $P/cb.png: it would be replaced; give another name" \
    0 -- "$compare" "$P/ca.png" "$P/cb.png" --out "$P/cb.png"
unchanged "rt_compare --out naming an input"
# The control: other names are written.
(cd "$work" && "$merge" --out merged.png "$P/p0.film" "$P/p2.film" > /dev/null) || fail "the merge itself failed"
(cd "$work" && "$compare" "$P/ca.png" "$P/cb.png" --out d.png > /dev/null) || fail "the comparison itself failed"

# --- 2. a run's own outputs, its scene and its films ---
name=$(basename "$exe")
expect_bad_input "--heat naming the partial image" \
    "$name: --heat: the heat maps h.partial.png is the partial image h.partial.png: one would replace the other; give another name" \
    0 -- "$exe" "${base[@]}" --out h.png --heat h.partial.png
expect_bad_input "--csv naming the radiance" \
    "$name: --csv: the table out.pfm is the radiance out.pfm: one would replace the other; give another name" \
    0 -- "$exe" "${base[@]}" --aa-study --csv out.pfm --out out.png
expect_bad_input "--csv naming the scene" \
    "$name: --csv: the table $P/scene.json is the scene $P/scene.json: it would be replaced; give another name" \
    0 -- "$exe" "${base[@]}" --aa-study --scene "$P/scene.json" --csv "$P/scene.json"
unchanged "--csv naming the scene"
# The files the scene reads are inputs: no output may replace one.
scene_files=("$exe" "${base[@]}" --scene "$S/scene.json")
expect_bad_input "--out naming the scene's texture" \
    "$name: --out: the image $S/wood.png is the texture of materials.wood $S/wood.png: it would be replaced; give another name" \
    0 -- "${scene_files[@]}" --out "$S/wood.png"
expect_bad_input "--out whose radiance is the scene's environment image" \
    "$name: --out: the radiance $S/sky.pfm is the environment image $S/sky.pfm: it would be replaced; give another name" \
    0 -- "${scene_files[@]}" --out "$S/sky.png"
expect_bad_input "--heat naming the scene's texture" \
    "$name: --heat: the heat maps ../pieces/scene_files/wood.png is the texture of materials.wood $S/wood.png: it would be replaced; give another name" \
    0 -- "${scene_files[@]}" --out out.png --heat ../pieces/scene_files/wood.png
expect_bad_input "--out whose partial image is the scene's texture" \
    "$name: --out: the partial image $S/x.partial.png is the texture of materials.tiles $S/x.partial.png: it would be replaced; give another name" \
    0 -- "${scene_files[@]}" --out "$S/x.png"
expect_bad_input "--samples whose film is the scene's mesh" \
    "$name: --out: the film $S/torus.film is the mesh of shapes[2] $S/torus.film: it would be replaced; give another name" \
    0 -- "${scene_files[@]}" --samples 0:2 --out "$S/torus.png"
unchanged "an output naming a file the scene reads"
(cd "$work" && "${scene_files[@]}" --out scene_files.png > /dev/null 2>&1) || fail "the scene with files was not rendered"
# --resume may continue a film into the same name (an interrupted run's film, continued and interrupted again).
cp "$P/p0.film" "$work/again.film"
(cd "$work" && "$exe" "${base[@]}" --samples 0:4 --resume again.film --out again.png > /dev/null 2>&1) ||
    fail "--resume again.film --out again.png was refused"

# --- 3. escaping ---
# A film whose chapter text (19 bytes, "ch01_ray_generation") holds a newline, an escape sequence and a NUL;
# its checksum is recomputed, so it is read, and refused as a piece of another render.
python3 - "$P/p2.film" "$P/evil2.film" "$P/p0.film" "$P/evil0.film" <<'PY'
import struct, sys
for source, target in ((sys.argv[1], sys.argv[2]), (sys.argv[3], sys.argv[4])):
    data = bytearray(open(source, "rb").read()[:-8])
    (n,) = struct.unpack_from("<I", data, 52)
    assert data[56:56 + n] == b"ch01_ray_generation"
    data[56:56 + n] = b"ch01\n\x1b[31mRED\x00_gene"
    h = 0xcbf29ce484222325
    for b in data:
        h = ((h ^ b) * 0x100000001b3) & 0xffffffffffffffff
    open(target, "wb").write(data + struct.pack("<Q", h))
PY
clean() {  # clean WHAT FILE: FILE holds one line, with no control byte but its newline
    [ "$(wc -l < "$2")" -eq 1 ] || fail "$1: expected one line: $(cat -v "$2")"
    LC_ALL=C grep -q -P '[\x00-\x08\x0b-\x1f\x7f]' "$2" && fail "$1: a control byte reached the terminal: $(cat -v "$2")"
    [ "$(tr -d '\n' < "$2" | LC_ALL=C tr -d '\000' | wc -c)" -eq "$(tr -d '\n' < "$2" | wc -c)" ] ||
        fail "$1: a NUL reached the terminal: $(cat -v "$2")"
}
(cd "$work" && "$merge" --out m.png "$P/p0.film" "$P/evil2.film" > out.txt 2> err.txt)
status=$?
[ "$status" -eq 2 ] || fail "a film of another chapter: exit status $status, expected 2"
clean "a film's chapter in a refusal" "$work/err.txt"
grep -q -F 'chapter ch01\n\x1b[31mRED\x00_gene, expected' "$work/err.txt" ||
    fail "a film's chapter in a refusal, not escaped: $(cat -v "$work/err.txt")"
(cd "$work" && "$merge" --out m.png "$P/evil0.film" "$P/evil2.film" > out.txt 2> err.txt) ||
    fail "two pieces of one (strangely named) chapter were not merged: $(cat -v "$work/err.txt")"
clean "a film's chapter in the summary" "$work/out.txt"
grep -q -F '2 pieces of ch01\n\x1b[31mRED\x00_gene on' "$work/out.txt" ||
    fail "a film's chapter in the summary, not escaped: $(cat -v "$work/out.txt")"
printf 'not a film' > "$P/"$'bad\e[2J\nname.film'
(cd "$work" && "$merge" --out m.png "$P/p0.film" "$P/"$'bad\e[2J\nname.film' > out.txt 2> err.txt)
clean "a piece's name in a refusal" "$work/err.txt"
finish
