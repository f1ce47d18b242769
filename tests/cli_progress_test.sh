#!/bin/sh
# End-to-end checks of the progress display, --quiet, Ctrl-C (SIGINT, SIGTERM)
# and --threads (issue 14, "Progress and control on long runs").
# Usage: cli_progress_test.sh MESHDIFF_BINARY DATA_DIR TEMP_DIR [LATENCY_LIMIT_S]
bin="$1"
data="$2"
tmp="$3"
limit="${4:-2}"  # seconds from the signal to the exit
if [ -z "$bin" ] || [ -z "$data" ] || [ -z "$tmp" ]; then
    echo "usage: $0 MESHDIFF_BINARY DATA_DIR TEMP_DIR [LATENCY_LIMIT_S]" >&2
    exit 2
fi
mkdir -p "$tmp" || exit 2
rm -rf "$tmp"/* "$tmp"/.[!.]*

. "$(dirname "$0")/cli_lib.sh"

# wait_for PATTERN FILE SECONDS: waits until a line of FILE matches PATTERN;
# returns 1 after SECONDS.
wait_for() {
    wait_n=$(($3 * 20))
    while [ "$wait_n" -gt 0 ]; do
        grep -q "$1" "$2" 2>/dev/null && return 0
        sleep 0.05
        wait_n=$((wait_n - 1))
    done
    return 1
}
now_ms() {
    echo $(($(date +%s%N) / 1000000))
}

a="$data/bunny_res3.ply"
b="$data/bunny_res4_ascii.ply"

# --- no display by default when stderr is not a terminal, none with --quiet
expect 0 "$a" "$b" --levels 1,5 --json "$tmp/plain.json" && cp "$tmp/stdout" "$tmp/plain.txt"
[ ! -s "$tmp/stderr" ] && pass || fail "stderr not empty without a terminal: $(head -c 300 "$tmp/stderr")"
expect 0 "$a" "$b" --levels 1,5 --quiet
[ ! -s "$tmp/stderr" ] && pass || fail "--quiet: stderr not empty: $(head -c 300 "$tmp/stderr")"
cmp -s "$tmp/stdout" "$tmp/plain.txt" && pass || fail "--quiet changed stdout"
expect 0 profile "$a" --levels 1,5 --quiet
[ ! -s "$tmp/stderr" ] && pass || fail "profile --quiet: stderr not empty"
expect 2 "$a" "$b" --progress --quiet && grep -q "excludes" "$tmp/stderr" && pass || fail "--progress --quiet accepted"

# --- --progress to a file (a log): plain lines per stage; stdout and JSON unchanged
expect 0 "$a" "$b" --levels 1,5 --radii 0.1 --json "$tmp/noprogress.json" && cp "$tmp/stdout" "$tmp/radii.txt"
expect 0 "$a" "$b" --levels 1,5 --radii 0.1 --json "$tmp/progress.json" --progress
cmp -s "$tmp/stdout" "$tmp/radii.txt" && pass || fail "--progress changed stdout"
cp "$tmp/stderr" "$tmp/progress.log"
for stage in "reading 100%" "curvature 100%" "rings 100%" "metric levels 100%" "index 100%" "sampling 100%" \
    "distances 100%" "certification [0-9]"; do
    grep -q "^$stage" "$tmp/progress.log" && pass || fail "--progress: no line '$stage': $(cat "$tmp/progress.log")"
done
[ "$(grep -c '^curvature 100%' "$tmp/progress.log")" -eq 2 ] && pass || fail "--progress: curvature not twice"
[ "$(grep -c '^certification' "$tmp/progress.log")" -ge 2 ] && pass || fail "--progress: certification not twice"
# Only stage lines, at most 11 per stage (each tenth and the end): a log stays short.
if grep -v -E '^[a-z ]+ [0-9]+%? [0-9]+\.[0-9] s$' "$tmp/progress.log" | grep -q .; then
    fail "--progress: a line that is not a stage line: $(grep -v -E '^[a-z ]+ [0-9]+%? [0-9]+\.[0-9] s$' "$tmp/progress.log" | head -3)"
else pass; fi
[ "$(wc -l <"$tmp/progress.log")" -le 170 ] && pass || fail "--progress: $(wc -l <"$tmp/progress.log") lines"
cmp -s "$tmp/progress.json" "$tmp/noprogress.json" && pass || fail "--progress changed the JSON"
expect 0 "$a" "$b" --levels 1,5 --json - --progress && cmp -s "$tmp/stdout" "$tmp/plain.json" && pass ||
    fail "--progress changed the JSON on stdout"
expect 0 profile "$a" --levels 1,5 --progress
grep -q "^curvature 100%" "$tmp/stderr" && grep -q "^rings 100%" "$tmp/stderr" && pass || fail "profile --progress"

# --- on a terminal (when `script` can give one): the line redrawn in place
if command -v script >/dev/null 2>&1; then
    script -qec "\"$bin\" \"$a\" \"$b\" --levels 1,5 --progress --json $tmp/tty.json" /dev/null >"$tmp/tty.txt" 2>&1
    if [ -s "$tmp/tty.json" ]; then
        grep -q "$(printf '\r\033\\[K')curvature" "$tmp/tty.txt" && pass || fail "terminal: no redrawn line"
        cmp -s "$tmp/tty.json" "$tmp/plain.json" && pass || fail "terminal: the JSON changed"
    fi
    # Without --progress a terminal shows nothing during the first 2 s (a small profile takes less).
    script -qec "\"$bin\" profile \"$a\" --levels 1,5" /dev/null >"$tmp/tty2.txt" 2>&1
    if grep -q "sigma" "$tmp/tty2.txt"; then
        grep -q "$(printf '\033')" "$tmp/tty2.txt" && fail "terminal: progress shown on a short run" || pass
    fi
fi

# --- --threads 1 and 2 give the same bytes (profile, compare with radii, batch)
expect 0 profile "$a" --levels 1,5 --radii 0.1 --json "$tmp/p1.json" --threads 1 && cp "$tmp/stdout" "$tmp/p1.txt"
expect 0 profile "$a" --levels 1,5 --radii 0.1 --json "$tmp/p2.json" --threads 2
cmp -s "$tmp/p1.json" "$tmp/p2.json" && cmp -s "$tmp/p1.txt" "$tmp/stdout" && pass ||
    fail "profile differs between 1 and 2 threads"
expect 0 "$a" "$b" --levels 1,5 --radii 0.1 --json "$tmp/c1.json" --threads 1
expect 0 "$a" "$b" --levels 1,5 --radii 0.1 --json "$tmp/c2.json" --threads 2
cmp -s "$tmp/c1.json" "$tmp/c2.json" && pass || fail "compare with radii differs between 1 and 2 threads"
printf 'original,processed,id\n%s,%s,one\n%s,%s,two\n' "$a" "$b" "$b" "$a" >"$tmp/pairs.csv"
for t in 1 2; do
    expect 0 batch "$tmp/pairs.csv" --out "$tmp/b$t.jsonl" --levels 1,5 --threads $t
    sed 's/"elapsed_seconds":[0-9.e+-]*,//' "$tmp/b$t.jsonl" >"$tmp/b$t.cut"
done
cmp -s "$tmp/b1.cut" "$tmp/b2.cut" && [ "$(wc -l <"$tmp/b1.cut")" -eq 2 ] && pass ||
    fail "batch differs between 1 and 2 threads"

# --- Ctrl-C: exit 130 within the limit, one line, no output file
expect 0 generate torus-irregular "$tmp/big1.ply" --vertices 300000 --seed 1
expect 0 generate torus-irregular "$tmp/big2.ply" --vertices 300000 --seed 2
# interrupt SIGNAL AFTER_LINE: a compare with every output, stopped by SIGNAL
# once its progress log shows AFTER_LINE (so that the stage stopped is known).
interrupt() {
    rm -f "$tmp/run.err" "$tmp/run.out"
    "$bin" "$tmp/big1.ply" "$tmp/big2.ply" --json "$tmp/out.json" --distance-maps "$tmp/maps" \
        --samples-out "$tmp/samples.ply" --progress >"$tmp/run.out" 2>"$tmp/run.err" &
    pid=$!
    if ! wait_for "$2" "$tmp/run.err" 300; then
        kill -KILL "$pid" 2>/dev/null
        wait "$pid"
        fail "interrupt $1: '$2' never came: $(tail -3 "$tmp/run.err")"
        return
    fi
    t0=$(now_ms)
    kill -"$1" "$pid"
    wait "$pid"
    rc=$?
    ms=$(($(now_ms) - t0))
    echo "interrupt $1 after '$2': exit $rc after $ms ms ($(grep -v '%\|^certification' "$tmp/run.err" | tail -1))"
    [ "$rc" -eq 130 ] && pass || fail "interrupt $1 after '$2': exit $rc, expected 130: $(tail -3 "$tmp/run.err")"
    [ "$ms" -lt $((limit * 1000)) ] && pass || fail "interrupt $1 after '$2': $ms ms to stop (limit $limit s)"
    grep -q "^meshdiff: interrupted by SIG$1: stopped, no output file written$" "$tmp/run.err" && pass ||
        fail "interrupt $1: message: $(tail -2 "$tmp/run.err")"
    [ "$(grep -c '^meshdiff:' "$tmp/run.err")" -eq 1 ] && pass || fail "interrupt $1: not one message line"
    [ ! -s "$tmp/run.out" ] && pass || fail "interrupt $1: a report on stdout"
    leftover=$(ls -A "$tmp" | grep -E 'out\.json|maps|samples|meshdiff-')
    [ -z "$leftover" ] && pass || fail "interrupt $1 after '$2': files left: $leftover"
}
interrupt INT "^reading 100%"  # in the first curvature
interrupt TERM "^index 100%"   # in the first distances
interrupt INT "^certification" # in the first certification

# --- batch: Ctrl-C stops the pair's process too; the lines written stay; the same command resumes
printf 'original,processed,id\n%s,%s,small1\nbig1.ply,big2.ply,big\n%s,%s,small2\n' "$a" "$b" "$b" "$a" \
    >"$tmp/bpairs.csv"
# setsid: the batch in a group of its own, signalled as a whole as Ctrl-C does it
setsid "$bin" batch "$tmp/bpairs.csv" --out "$tmp/res.jsonl" --levels 1,5 >"$tmp/batch.out" 2>"$tmp/batch.err" &
pid=$!
if wait_for "ok    small1" "$tmp/batch.err" 300; then
    sleep 1  # well into the big pair
    t0=$(now_ms)
    env kill -INT -- -"$pid"  # procps kill: the whole group
    wait "$pid"
    rc=$?
    ms=$(($(now_ms) - t0))
    echo "batch interrupted (group): exit $rc after $ms ms"
    [ "$rc" -eq 130 ] && pass || fail "batch interrupt: exit $rc: $(cat "$tmp/batch.err")"
    [ "$ms" -lt $((limit * 1000)) ] && pass || fail "batch interrupt: $ms ms to stop (limit $limit s)"
    grep -q "^meshdiff: batch interrupted by SIGINT: 1 ok, 0 failed recorded in .*the same command resumes$" \
        "$tmp/batch.err" && pass || fail "batch interrupt: message: $(tail -2 "$tmp/batch.err")"
    [ "$(wc -l <"$tmp/res.jsonl")" -eq 1 ] && grep -q '"id":"small1"' "$tmp/res.jsonl" && pass ||
        fail "batch interrupt: $(wc -l <"$tmp/res.jsonl") lines"
else
    env kill -KILL -- -"$pid" 2>/dev/null
    fail "batch: the first pair never finished: $(cat "$tmp/batch.err")"
fi
sleep 0.2
ps -eo args | grep -v grep | grep -q "$tmp/big1.ply" && fail "batch interrupt: a pair's process still runs" || pass
# SIGTERM to the batch process alone is passed on to the pair's process.
"$bin" batch "$tmp/bpairs.csv" --out "$tmp/res.jsonl" --levels 1,5 >"$tmp/batch.out" 2>"$tmp/batch.err" &
pid=$!
sleep 1.5
t0=$(now_ms)
kill -TERM "$pid"
wait "$pid"
rc=$?
ms=$(($(now_ms) - t0))
echo "batch interrupted (SIGTERM to the batch alone): exit $rc after $ms ms"
[ "$rc" -eq 130 ] && pass || fail "batch SIGTERM: exit $rc: $(cat "$tmp/batch.err")"
[ "$ms" -lt $((limit * 1000)) ] && pass || fail "batch SIGTERM: $ms ms to stop (limit $limit s)"
grep -q "batch interrupted by SIGTERM: 0 ok" "$tmp/batch.err" && pass || fail "batch SIGTERM: $(cat "$tmp/batch.err")"
sleep 0.2
ps -eo args | grep -v grep | grep -q "$tmp/big1.ply" && fail "batch SIGTERM: a pair's process still runs" || pass
# Resume (the big pair made small, so that it is quick): every id once, all ok.
printf 'original,processed,id\n%s,%s,small1\n%s,%s,big\n%s,%s,small2\n' "$a" "$b" "$a" "$b" "$b" "$a" \
    >"$tmp/bpairs.csv"
expect 0 batch "$tmp/bpairs.csv" --out "$tmp/res.jsonl" --levels 1,5 &&
    grep -q "batch: 2 ok, 0 failed, 1 already done" "$tmp/stderr" && pass || fail "batch resume: $(cat "$tmp/stderr")"
python3 -c "
import json, sys
ids = [json.loads(l)['id'] for l in open(sys.argv[1])]
sys.exit(0 if sorted(ids) == ['big', 'small1', 'small2'] else 1)" "$tmp/res.jsonl" && pass ||
    fail "batch resume: $(cat "$tmp/res.jsonl" | cut -c1-80)"

finish
