#!/usr/bin/env bash
# write_mesh.sh CH02_EXECUTABLE: `--write-mesh PATH` writes the OBJ under a staging name of its own and renames
# it into place: a folder as PATH is refused (exit 2) with nothing created beside it, and a file named
# PATH.tmp (someone else's) is never touched. The OBJ written loads back.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
n=$(basename "$exe")

mkdir -p "$scratch/meshes/folder.obj"
expect_bad_input "--write-mesh FOLDER" "$n: $scratch/meshes/folder.obj: cannot be written: it is a folder" 0 -- \
    "$exe" --quiet --write-mesh "$scratch/meshes/folder.obj"
files=$(ls -a "$scratch/meshes" | grep -v -E '^(\.|\.\.|folder\.obj)$')
[ -z "$files" ] || fail "--write-mesh FOLDER left: $files"
expect_bad_input "--write-mesh missing/m.obj" "$n: missing/m.obj: cannot be written: folder missing does not exist" 0 -- \
    "$exe" --quiet --write-mesh missing/m.obj

rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
echo "someone else's" > m.obj.tmp
"$exe" --quiet --write-mesh m.obj > stdout 2> stderr || fail "--write-mesh m.obj failed: $(cat stderr)"
[ "$(cat m.obj.tmp)" = "someone else's" ] || fail "--write-mesh m.obj changed or removed m.obj.tmp"
files=$(ls -a | grep -v -E '^(\.|\.\.|m\.obj|m\.obj\.tmp|stdout|stderr)$')
[ -z "$files" ] || fail "--write-mesh m.obj left: $files"
cat > scene.json <<'JSON'
{"camera": {"from": [0, 0, 4], "at": [0, 0, 0]}, "materials": {"w": {"type": "diffuse"}},
 "shapes": [{"type": "mesh", "file": "m.obj", "material": "w"}]}
JSON
"$exe" --scene scene.json --width 8 --height 4 --spp 1 --quiet --out back.png > stdout 2> stderr ||
    fail "the mesh written does not load back: $(cat stderr)"
finish
