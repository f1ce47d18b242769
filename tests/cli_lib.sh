# Shared helpers of the CLI test scripts (sourced; POSIX sh). The sourcing
# script sets $bin (the meshdiff binary) and $tmp (its scratch directory).

fail() {
    echo "FAIL: $*" >&2
    exit 1
}

# Runs the tool, expects exit code $1 (the rest are the arguments); stdout and
# stderr are kept in $tmp/stdout and $tmp/stderr.
expect_exit() {
    want="$1"
    shift
    set +e
    "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
    got=$?
    set -e
    [ "$got" -eq "$want" ] || fail "meshdiff $* exited $got, expected $want: $(cat "$tmp/stderr")"
}
