# Shared by the scripts in tests/cli: a scratch folder, failures that say what went wrong, and a check that a
# folder holds exactly the files it held before (nothing created, nothing overwritten).
set -u

failures=0
scratch=$(mktemp -d "${TMPDIR:-/tmp}/rt_cli_test.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
work="$scratch/work"  # where commands run, and where their output would land

fail() {
    echo "FAIL: $*" >&2
    failures=$((failures + 1))
}

# snapshot DIR: one line per file, "name checksum", sorted.
snapshot() {
    (cd "$1" && find . -type f -print0 | sort -z | xargs -0 -r md5sum)
}

# expect_bad_input WHAT EXPECTED_LINE PREFIX_ONLY -- COMMAND...: runs COMMAND in $work, which holds an
# earlier out.png and out.pfm; checks exit status 2, exactly one line on stderr that equals EXPECTED_LINE (or
# starts with it when PREFIX_ONLY is 1), nothing on stdout, and no file created or changed.
expect_bad_input() {
    local what=$1 expected=$2 prefix_only=$3
    shift 4
    rm -rf "$work" && mkdir -p "$work"
    echo "earlier png" > "$work/out.png"
    echo "earlier pfm" > "$work/out.pfm"
    local before after status
    before=$(snapshot "$work")
    (cd "$work" && "$@" > "$scratch/stdout" 2> "$scratch/stderr")
    status=$?
    after=$(snapshot "$work")
    local lines line
    lines=$(wc -l < "$scratch/stderr")
    line=$(head -n 1 "$scratch/stderr")
    [ "$status" -eq 2 ] || fail "$what: exit status $status, expected 2 (stderr: $line)"
    [ "$lines" -eq 1 ] || fail "$what: $lines lines on stderr, expected 1: $(cat "$scratch/stderr")"
    if [ "$prefix_only" = 1 ]; then
        [[ "$line" == "$expected"* ]] || fail "$what: message was: $line ... expected it to start: $expected"
    else
        [ "$line" = "$expected" ] || fail "$what: message was: $line ... expected: $expected"
    fi
    [ ! -s "$scratch/stdout" ] || fail "$what: printed on stdout: $(head -c 200 "$scratch/stdout")"
    [ "$before" = "$after" ] || fail "$what: files changed: $(diff <(echo "$before") <(echo "$after") | tr '\n' ' ')"
}

# Time bounds. A script may bound a time only by ten times or more of a floor measured in the same run:
# start_up_seconds EXE prints the slowest of three starts of EXE that print the help and exit (loading the
# libraries and, under the sanitizers, mapping their shadow memory), which a loaded machine slows as much as
# the run under test; at_least_ten_times FLOOR MINIMUM prints max(10 × FLOOR, MINIMUM).
now() { date +%s.%N; }
seconds_between() { echo "$1 $2" | awk '{printf "%.3f", $2 - $1}'; }
start_up_seconds() {
    local slowest=0 started _
    for _ in 1 2 3; do
        started=$(now)
        "$1" --help > /dev/null || { echo "start_up_seconds: $1 --help failed" >&2; return 1; }
        slowest=$(echo "$(seconds_between "$started" "$(now)") $slowest" | awk '{ printf "%.3f", ($1 > $2 ? $1 : $2) }')
    done
    echo "$slowest"
}
at_least_ten_times() { awk -v f="$1" -v m="$2" 'BEGIN { b = 10 * f; printf "%.3f", (b > m ? b : m) }'; }

finish() {
    if [ "$failures" -gt 0 ]; then
        echo "$failures failure(s)" >&2
        exit 1
    fi
    echo "all checks passed"
}
