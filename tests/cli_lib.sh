# Shared helpers of the CLI test scripts (sourced; POSIX sh). The sourcing
# script sets $bin (the meshdiff binary) and $tmp (its scratch directory),
# does not use `set -e`, and ends with `finish`.
#
# Every check counts: a failed one is reported and the script goes on, so one
# run lists every broken check; `finish` prints the totals and exits 1 if any
# check failed. A check is an `expect`, a `json_check`, or a condition written
#     CONDITION && pass || fail "what is wrong"

passed=0
failed=0

pass() {
    passed=$((passed + 1))
}

fail() {
    echo "FAIL: $*" >&2
    failed=$((failed + 1))
}

# expect CODE ARGS...: runs the tool with ARGS, checks that it exits with CODE;
# stdout and stderr are kept in $tmp/stdout and $tmp/stderr. Returns 1 if the
# exit code is wrong, so that `expect ... && more checks` skips the rest.
expect() {
    expect_want="$1"
    shift
    "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
    expect_got=$?
    if [ "$expect_got" -ne "$expect_want" ]; then
        fail "meshdiff $* exited $expect_got, expected $expect_want: $(head -c 400 "$tmp/stderr")"
        return 1
    fi
    pass
}

# expect_within SECONDS CODE ARGS...: as expect, but the run is killed after
# SECONDS (exit code 124 then), so that a hang fails the check instead of
# blocking the test run.
expect_within() {
    within_s="$1"
    within_want="$2"
    shift 2
    timeout "$within_s" "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
    within_got=$?
    if [ "$within_got" -ne "$within_want" ]; then
        [ "$within_got" -eq 124 ] && within_got="124 (killed after $within_s s)"
        fail "meshdiff $* exited $within_got, expected $within_want: $(head -c 400 "$tmp/stderr")"
        return 1
    fi
    pass
}

# json_check FILE PYTHON_EXPR: the expression over the parsed JSON `j` must be
# true; finite(x) tells whether every number in x is finite, nulls(x) lists
# the paths (e.g. "a.b[2]") of its null values.
json_check() {
    if python3 - "$1" "$2" <<'PY'; then
import json, math, sys
j = json.load(open(sys.argv[1]))
def finite(x):
    if isinstance(x, dict): return all(finite(v) for v in x.values())
    if isinstance(x, list): return all(finite(v) for v in x)
    if isinstance(x, float): return math.isfinite(x)
    return True
def nulls(x, at=""):
    if isinstance(x, dict): return [p for k, v in x.items() for p in nulls(v, at + "." + k if at else k)]
    if isinstance(x, list): return [p for i, v in enumerate(x) for p in nulls(v, "%s[%d]" % (at, i))]
    return [at] if x is None else []
ok = eval(sys.argv[2])
sys.exit(0 if ok else 1)
PY
        pass
    else
        fail "json check '$2' on $1"
    fi
}

# Prints the closing line and exits: 0 if every check passed, 1 otherwise.
finish() {
    echo "cli: $passed passed, $failed failed"
    [ "$failed" -eq 0 ] || exit 1
    exit 0
}
