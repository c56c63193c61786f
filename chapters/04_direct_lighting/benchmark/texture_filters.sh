#!/usr/bin/env bash
# Texture filtering, nearest against bilinear: the error of each at 1, 4, 16 and 64 samples per pixel against
# a supersampled reference (the bilinear image at 1024 spp), and the render time, on a close-up of
# ch04_textured.json where each texel of the wood covers about 4 × 4 pixels (magnified, where the filters
# differ). Each time is the fastest of 3 runs on 1 thread.
# Usage: chapters/04_direct_lighting/benchmark/texture_filters.sh [build/release]
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
build="${1:-$root/build/release}"
ch04="$build/chapters/04_direct_lighting/ch04_direct_lighting"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The scene, moved close to the box and with the texture's path made absolute, once per filter.
for filter in nearest bilinear; do
  sed -e "s|\"\\.\\./textures/ch04_wood.png\"|\"$root/assets/textures/ch04_wood.png\", \"filter\": \"$filter\"|" \
      -e 's|"from": \[0, 1.5, 4.2\], "at": \[0, 0.55, 0\]|"from": [0.4, 0.9, 1.2], "at": [0.85, 0.45, -0.1]|' \
      -e 's|"width": 240, "height": 160|"width": 160, "height": 160|' \
      "$root/assets/scenes/ch04_textured.json" > "$work/$filter.json"
done
"$ch04" --scene "$work/bilinear.json" --spp 1024 --quiet --out "$work/reference.png" > /dev/null
printf '| filter | spp | RMSE to the reference | time (s) |\n|---|---:|---:|---:|\n'
for spp in 1 4 16 64; do
  for filter in nearest bilinear; do
    best=""
    for run in 1 2 3; do
      out="$("$ch04" --scene "$work/$filter.json" --spp "$spp" --threads 1 --quiet --out "$work/$filter.png" \
             --reference "$work/reference.pfm")"
      t="$(sed -n 's/^  time \([0-9.e+-]*\) s.*/\1/p' <<< "$out")"
      if [[ -z "$best" ]] || awk "BEGIN{exit !($t < $best)}"; then best="$t"; fi
    done
    rmse="$(sed -n 's/.*against the reference: RMSE \([0-9.e+-]*\).*/\1/p' <<< "$out")"
    printf '| %s | %d | %s | %s |\n' "$filter" "$spp" "$rmse" "$best"
  done
done
