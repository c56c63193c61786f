#!/usr/bin/env bash
# slurm_script.sh EXECUTABLE PFM_CHECK RT_MERGE: tests/tools/slurm_render.sbatch without a Slurm cluster. Each
# array task's command is run here, as Slurm would run it (SLURM_ARRAY_TASK_ID set), then the merge job's;
# the merged image is the whole render's, bit for bit. Twice: 3 pieces of 7 samples (uneven: 3, 2, 2), and 9
# pieces of 7 (two tasks left without samples render nothing, and the merge leaves them out).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
exe=$1
pfm_check=$2
script="$here/../tools/slurm_render.sbatch"
export RT_MERGE=$3
mkdir -p "$work" && cd "$work" || exit 1
args=(--width 24 --height 16 --quiet --spp 7)
"$exe" "${args[@]}" --out whole.png > /dev/null 2>&1 || fail "the whole render failed"
for pieces in 3 9; do
    mkdir -p "refs$pieces"
    for ((task = 0; task < pieces; ++task)); do
        SLURM_ARRAY_TASK_ID=$task SLURM_CPUS_PER_TASK=1 bash "$script" piece "$pieces" "$exe" "${args[@]}" \
            --out "refs$pieces/x.png" > "task$task.log" 2>&1 || fail "$pieces pieces: task $task: $(tail -n 1 "task$task.log")"
    done
    bash "$script" merge "$pieces" "$exe" "${args[@]}" --out "refs$pieces/x.png" > merge.log 2>&1 ||
        fail "$pieces pieces: the merge job: $(cat merge.log)"
    why=$("$pfm_check" whole.pfm "refs$pieces/x.pfm" 2>&1 > /dev/null) || fail "$pieces pieces: $why"
    films=$(ls "refs$pieces"/*.film | grep -c piece)
    expected=$((pieces < 7 ? pieces : 7))
    [ "$films" -eq "$expected" ] || fail "$pieces pieces: $films pieces' films, expected $expected"
done
[ -f refs3/x.piece-0-of-3.film ] && [ -f refs3/x.piece-2-of-3.pfm ] || fail "the pieces are not named x.piece-I-of-N"
# The script's own refusals.
bash "$script" piece 3 "$exe" --width 8 --out x.png > /dev/null 2> err && fail "no --spp: accepted"
grep -q "ARGS must give --spp N and --out" err || fail "no --spp: $(cat err)"
SLURM_ARRAY_TASK_ID= bash "$script" piece 3 "$exe" "${args[@]}" --out x.png > /dev/null 2>&1 && fail "no array task id: accepted"
finish
