# Shared by the CLI test scripts (sourced): expect, within and the summary line.
# The caller sets `locus` and `tmp` first.
failures=0
passes=0

fail() {
    echo "FAIL $*"; failures=$((failures + 1))
}

# expect NAME EXPECTED_EXIT PATTERN_IN_OUTPUT -- COMMAND...
expect() {
    local name="$1" code="$2" pattern="$3"
    shift 4
    local out
    out=$("$@" 2>&1)
    local got=$?
    if [[ $got -ne $code ]]; then
        fail "$name: exit $got, expected $code"; echo "$out" | head -5
    elif [[ -n "$pattern" ]] && ! grep -qF -- "$pattern" <<<"$out"; then
        fail "$name: output lacks '$pattern'"; echo "$out" | head -5
    else
        echo "ok   $name"; passes=$((passes + 1))
    fi
}

# within SECONDS NAME EXPECTED_EXIT PATTERN -- COMMAND...: expect, and the command must also end
# within SECONDS of wall-clock time (measured around the whole process, start-up included).
within() {
    local limit="$1"
    shift
    local before after
    before=$(date +%s.%N)
    expect "$@"
    after=$(date +%s.%N)
    if awk -v a="$before" -v b="$after" -v l="$limit" 'BEGIN { exit !(b - a > l) }'; then
        fail "$1: took $(awk -v a="$before" -v b="$after" 'BEGIN { printf "%.2f", b - a }') s, limit $limit s"
        passes=$((passes - 1))
    fi
}

summary() {
    echo "$passes passed, $failures failed"
    [[ $failures -eq 0 ]]
}
