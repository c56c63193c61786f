#!/usr/bin/env bash
# split_benchmark.sh [BUILD_DIR] [SIDE] [SPP]: what splitting a render costs and gives, measured here.
#  1. Strong scaling with MPI ranks: one render (chapter 06, cornell.json, SIDE² pixels, SPP samples) with
#     1 rank and with 2 (one thread each, so one core per rank: this machine has 2), wall time of mpirun.
#  2. The merge: rt_merge of 2 and of 16 pieces of that render (reading and checking the films, adding them,
#     writing the PNG, PFM and film), fitted as a + b·pieces, and a film's size.
#  3. A cluster of N nodes, projected: each node renders 1/N of the samples in (this machine's render time)/N,
#     then one merge of N films (a + b·N) moves N films to the node that merges. Start-up (mpirun's, a job's
#     queueing) and the network are left out: the films moved are shown instead.
# Defaults: build/release, 128, 64. Needs mpirun for part 1 (skipped without it). Timings are wall clock,
# on a machine that may be busy: run it on a quiet one.
set -euo pipefail
build=${1:-build/release}
side=${2:-128}
spp=${3:-64}
exe="$build/chapters/06_monte_carlo/ch06_monte_carlo"
merge="$build/common/rt_merge"
here=$(cd "$(dirname "$0")" && pwd)
scene="$here/../../assets/scenes/cornell.json"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(--scene "$scene" --width "$side" --height "$side" --spp "$spp" --quiet)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# seconds COMMAND...: "WALL RENDER": its wall time and the render's own time from the summary ("time 1.234 s":
# the slowest rank's, without MPI's start-up), each the best of 3 runs (the least disturbed by other work).
seconds() {
    local best="" best_render=0
    for _ in 1 2 3; do
        local start end render
        start=$(date +%s.%N)
        "$@" > "$work/out" 2>&1
        end=$(date +%s.%N)
        render=$(grep -o '  time [0-9.]* s' "$work/out" | grep -o '[0-9.]*' | head -n 1 || true)
        read -r best best_render < <(awk -v s="$start" -v e="$end" -v b="$best" -v r="${render:-0}" -v br="$best_render" \
            'BEGIN { t = e - s; if (b == "" || t < b) b = t; if (br == 0 || (r > 0 && r < br)) br = r; print b, br }')
    done
    echo "$best $best_render"
}

echo "chapter 06, cornell.json, ${side}x${side}, $spp spp, on $(nproc) cores (load average $(cut -d' ' -f1-3 /proc/loadavg):"\
    "above 0 means other work shares them)"
one_node=""
if command -v mpirun > /dev/null; then
    read -r w1 t1 < <(seconds mpirun --oversubscribe -np 1 "$exe" "${args[@]}" --threads 1 --out "$work/r1.png")
    read -r w2 t2 < <(seconds mpirun --oversubscribe -np 2 "$exe" "${args[@]}" --threads 1 --out "$work/r2.png")
    awk -v a="$t1" -v b="$t2" -v wa="$w1" -v wb="$w2" 'BEGIN {
        printf "1. MPI ranks (1 thread each): render 1 rank %.3f s, 2 ranks %.3f s: speed-up %.2f, efficiency %.0f%%\n", a, b, a / b, 50 * a / b
        printf "   wall time with mpirun'"'"'s start-up: %.3f s and %.3f s: speed-up %.2f\n", wa, wb, wa / wb }'
    cmp -s "$work/r1.pfm" "$work/r2.pfm" && echo "   the two images are the same bits" || echo "   THE TWO IMAGES DIFFER"
    one_node=$t2
else
    echo "1. MPI ranks: skipped (no mpirun: install openmpi-bin)"
fi
[ -n "$one_node" ] || read -r _ one_node < <(seconds "$exe" "${args[@]}" --out "$work/whole.png")

for p in 2 16; do
    films=()
    for ((i = 0; i < p; ++i)); do
        first=$((i * spp / p)) end=$(((i + 1) * spp / p))
        "$exe" "${args[@]}" --samples "$first:$end" --out "$work/p$p-$i.png" > /dev/null
        films+=("$work/p$p-$i.film")
    done
    read -r "merge$p" _ < <(seconds "$merge" --out "$work/m$p.png" "${films[@]}")
done
film_bytes=$(stat -c %s "$work/p2-0.film")
awk -v m2="$merge2" -v m16="$merge16" -v bytes="$film_bytes" -v one="$one_node" -v side="$side" 'BEGIN {
    b = (m16 - m2) / 14; a = m2 - 2 * b; if (b < 0) b = 0
    printf "2. rt_merge: 2 pieces %.3f s, 16 pieces %.3f s: %.4f s + %.4f s a piece; a film is %.2f MB (%dx%d)\n", m2, m16, a, b, bytes / 1e6, side, side
    printf "3. projected, each node as this machine (%.3f s for the whole render alone):\n", one
    printf "   %6s %12s %12s %12s %14s\n", "nodes", "render (s)", "merge (s)", "total (s)", "films moved"
    n_count = split("1 4 16 64 256 1024", nodes, " ")
    for (i = 1; i <= n_count; ++i) {
        n = nodes[i]; r = one / n; m = (n > 1) ? a + b * n : 0
        printf "   %6d %12.4f %12.4f %12.4f %11.1f MB\n", n, r, m, r + m, n * bytes / 1e6
    }
    if (b > 0) printf "   the merge costs as much as the render from about %.0f nodes on (sqrt(render / cost a piece))\n", sqrt(one / b)
}'
