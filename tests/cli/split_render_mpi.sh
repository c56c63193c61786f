#!/usr/bin/env bash
# split_render_mpi.sh PFM_CHECK MPIEXEC -- EXECUTABLE...: `mpirun -np K` (K = 1, 2, 3) splits a render's
# samples among K processes, and rank 0 writes the image: the same bits as one process, on every chapter's
# default scene (small); its summary counts every rank's rays. Chapter 08's forward tracer refuses to be split
# (exit 2); its --tracer reverse is split. Chapter 10's noisy image (--denoiser none) is split. Exits 77 (skipped) when the build has no MPI (MPIEXEC empty).
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
pfm_check=$1
mpiexec=$2
shift 3
if [ -z "$mpiexec" ]; then
    echo "skipped: this build has no MPI (install libopenmpi-dev openmpi-bin and configure again)"
    exit 77
fi
# Open MPI refuses to run as root without these; the tests run on 2 cores, so 3 ranks oversubscribe.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
size=(--width 24 --height 16 --spp 5 --quiet)
rays_total() { grep -o 'total [0-9]*' "$1" | head -n 1; }

for exe in "$@"; do
    name=$(basename "$exe")
    args=("${size[@]}")
    dir="$scratch/$name" && mkdir -p "$dir" && cd "$dir" || exit 1
    if [[ $name == ch11_* ]]; then
        # Chapter 11's GPU sums in float, not exactly: it refuses to be split among ranks.
        "$mpiexec" --oversubscribe -np 2 "$exe" "${size[@]}" --out split.png > stdout 2> stderr
        status=$?
        [ "$status" -eq 2 ] || fail "$name under mpirun -np 2: exit status $status, expected 2"
        [ ! -e split.png ] || fail "$name under mpirun -np 2: wrote split.png"
        continue
    fi
    if [[ $name == ch08_* ]]; then
        "$mpiexec" --oversubscribe -np 2 "$exe" "${size[@]}" --out forward.png > stdout 2> stderr
        status=$?
        [ "$status" -eq 2 ] || fail "$name forward under mpirun -np 2: exit status $status, expected 2"
        grep -q "^$name: mpirun with 2 ranks: forward tracing splats" stderr ||
            fail "$name forward under mpirun -np 2: no refusal on stderr: $(head -n 3 stderr)"
        [ ! -e forward.png ] || fail "$name forward under mpirun -np 2: wrote forward.png"
        args+=(--tracer reverse)
    fi
    if [[ $name == ch10_* ]]; then
        args+=(--denoiser none)  # chapter 10 denoises only a whole image; its noisy image is split
    fi
    if [[ $name == ch12_* ]]; then
        # A guided render's passes learn from each other: it refuses ranks; unguided it is split.
        "$mpiexec" --oversubscribe -np 2 "$exe" "${size[@]}" --out guided.png > stdout 2> stderr
        status=$?
        [ "$status" -eq 2 ] || fail "$name guided under mpirun -np 2: exit status $status, expected 2"
        [ ! -e guided.png ] || fail "$name guided under mpirun -np 2: wrote guided.png"
        args+=(--training-passes 0)
    fi
    "$exe" "${args[@]}" --out whole.png > whole.stdout 2> stderr || fail "$name whole: $(tail -n 2 stderr)"
    for k in 1 2 3; do
        if ! "$mpiexec" --oversubscribe -np "$k" "$exe" "${args[@]}" --out "ranks$k.png" > "ranks$k.stdout" 2> stderr; then
            fail "$name mpirun -np $k: $(tail -n 3 stderr)"
            continue
        fi
        why=$("$pfm_check" whole.pfm "ranks$k.pfm" 2>&1 > /dev/null) || fail "$name: one process and $k ranks: $why"
        [ "$(rays_total "ranks$k.stdout")" = "$(rays_total whole.stdout)" ] ||
            fail "$name mpirun -np $k: rays $(rays_total "ranks$k.stdout"), one process traced $(rays_total whole.stdout)"
        [ "$(grep -c 'wrote' "ranks$k.stdout")" -eq 1 ] || fail "$name mpirun -np $k: not one summary (rank 0's only)"
    done
    # A piece under mpirun: the ranks split the piece's samples (3 ranks, 2 samples: one rank has none), and
    # rank 0 writes its film, byte for byte one process's.
    "$mpiexec" --oversubscribe -np 3 "$exe" "${args[@]}" --samples 3:5 --out piece.png > /dev/null 2> stderr ||
        fail "$name mpirun -np 3 --samples 3:5: $(tail -n 3 stderr)"
    "$exe" "${args[@]}" --samples 3:5 --out alone.png > /dev/null 2>&1 || fail "$name --samples 3:5 failed"
    cmp -s piece.film alone.film || fail "$name: the film of 3:5 under 3 ranks differs from one process's"
done
finish
