#!/usr/bin/env bash
# program_flags.sh PROGRAM...: the programs that are not chapters (the benchmarks, rt_scene) refuse a flag
# they do not know, and some refuse values a run cannot take (no runs, an image of no pixels, a missing
# scene), as a chapter does: exit status 2 and one line, before any work, with nothing written.
here=$(cd "$(dirname "$0")" && pwd)
source "$here/lib.sh"
scenes=$(cd "$here/../../assets/scenes" && pwd)

for exe in "$@"; do
    n=$(basename "$exe")
    unexpected="The following argument was not expected: --bogus"
    [ "$n" = rt_scene ] && unexpected="--to-json is required"
    expect_bad_input "$n --bogus" "$n: usage: $unexpected (see --help)" 0 -- "$exe" --bogus
    case "$n" in
        rt_scene)
            expect_bad_input "$n --to-json" "$n: usage: --to-json: 1 required TEXT missing (see --help)" 0 \
                -- "$exe" --to-json ;;
        ch02_benchmark)
            expect_bad_input "$n --repeats 0" "$n: usage: --repeats: Value 0 not in range 1 to 99 (see --help)" 0 \
                -- "$exe" --repeats 0
            expect_bad_input "$n --walk-bound" "$n: usage: --walk-bound requires --embree (see --help)" 0 \
                -- "$exe" --walk-bound ;;
        ch09_benchmark)
            expect_bad_input "$n 0" "$n: usage: runs: Value 0 not in range 1 to 99 (see --help)" 0 -- "$exe" 0
            expect_bad_input "$n 7 abc" "$n: usage: size: must be a whole number (decimal digits, a '-' before them if negative), got \"abc\" (see --help)" 0 \
                -- "$exe" 7 abc ;;
        ch09_distance_benchmark)
            expect_bad_input "$n absent.json" "$n: $scenes/absent.json: must be a scene file (JSON or pbrt-v4), got no such file" 0 \
                -- "$exe" absent.json
            expect_bad_input "$n ... 0" "$n: usage: size: Value 0 not in range 1 to 4096 (see --help)" 0 \
                -- "$exe" ch09_thin_fog.json 0
            expect_bad_input "$n ... grey" "$n: usage: surfaces: grey not in {as given,black} (see --help)" 0 \
                -- "$exe" ch09_thin_fog.json 64 16 4096 5 1 grey ;;
    esac
done
[ "$failures" -eq 0 ] || exit 1
echo "$# programs: bad flags refused with exit 2 and one line"
