#!/usr/bin/env bash
# batch for thousands of pairs on a cluster: a 200-pair batch in 4 shards (GNU
# parallel through --sshloginfile on this host when it is installed), one shard
# killed and resumed, merged by batch-summary into a CSV of 200 rows; missing and
# failed pairs (exit 6); --shard auto from Slurm and GNU parallel variables;
# elapsed time and version in every record.
# Usage: cli_batch_cluster_test.sh MESHDIFF_BINARY
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/cli_lib.sh"

"$bin" generate sphere "$tmp/a.ply" --subdivisions 1 > /dev/null
"$bin" generate noisy-sphere "$tmp/b.ply" --subdivisions 1 --noise 0.02 --seed 4 > /dev/null
printf 'original,processed,id\n' > "$tmp/pairs.csv"
for i in $(seq 0 199); do printf 'a.ply,b.ply,p%s\n' "$i" >> "$tmp/pairs.csv"; done
opts=(--levels 1,2 -n 500 -q)
rows() { python3 -c "import csv,sys; print(len(list(csv.DictReader(open(sys.argv[1])))))" "$1"; }

# --- shard 2 of 4 (its records in s3.jsonl: GNU parallel's job 3 below) killed outright after a few records
"$bin" batch "$tmp/pairs.csv" --out "$tmp/s3.jsonl" --shard 2/4 "${opts[@]}" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 400); do
    [ -f "$tmp/s3.jsonl" ] && [ "$(wc -l < "$tmp/s3.jsonl")" -ge 5 ] && break
    sleep 0.05
done
kill -9 "$pid" 2> /dev/null
wait "$pid" 2> /dev/null
killed_at=$(wc -l < "$tmp/s3.jsonl")
[ "$killed_at" -ge 1 ] && [ "$killed_at" -lt 50 ] && pass || fail "shard 2 was not killed midway ($killed_at records)"

# --- all four shards: through GNU parallel on this host (--sshloginfile with ':' is the local machine), each
# job's shard index from its $PARALLEL_SEQ (--shard auto/4: job k is shard k - 1); job 3 resumes the killed shard
if command -v parallel > /dev/null; then
    echo ":" > "$tmp/hosts"
    (cd "$tmp" && parallel --will-cite --sshloginfile hosts -j 2 \
        "$bin" batch pairs.csv --out "s{#}.jsonl" --shard auto/4 "${opts[@]}" ::: a b c d) 2> "$tmp/par.err"
    [ $? -eq 0 ] && pass || fail "GNU parallel: $(head -c 400 "$tmp/par.err")"
else
    echo "note: GNU parallel is not installed (scripts/install-deps.sh installs it); shards run one by one" >&2
    for s in 0 1 2 3; do
        "$bin" batch "$tmp/pairs.csv" --out "$tmp/s$((s + 1)).jsonl" --shard "$s/4" "${opts[@]}" 2> /dev/null
    done
fi
for s in 0 1 2 3; do
    python3 - "$tmp/s$((s + 1)).jsonl" "$s" <<'PY' && pass || fail "shard $s holds the wrong pairs"
import json, sys
ids = sorted(int(json.loads(l)["id"][1:]) for l in open(sys.argv[1]) if json.loads(l)["status"] == "ok")
assert ids == [k for k in range(200) if k % 4 == int(sys.argv[2])], ids[:10]
PY
done
[ "$(wc -l < "$tmp/s3.jsonl")" -eq 50 ] && pass || fail "the resumed shard has $(wc -l < "$tmp/s3.jsonl") lines, not 50"

# --- merged: 200 rows, every cell a scalar, rows in the pair list's order, the records' time and version
expect 0 batch-summary "$tmp"/s?.jsonl --csv "$tmp/all.csv" --pairs "$tmp/pairs.csv" &&
    grep -q "200 pairs: 200 ok, 0 failed, 0 missing" "$tmp/stderr" && pass || fail "summary: $(cat "$tmp/stderr")"
python3 - "$tmp/all.csv" "$bin" <<'PY' && pass || fail "the CSV is not one flat row per pair"
import csv, subprocess, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 200 and [r["id"] for r in rows] == ["p%d" % k for k in range(200)]
version = subprocess.run([sys.argv[2], "--version"], capture_output=True, text=True).stdout.split()[-1]
for r in rows:
    assert r["status"] == "ok" and r["meshdiff_version"] == version
    assert float(r["elapsed_seconds"]) > 0
    for k in ("hausdorff", "forward_mean", "backward_rms", "d_L1", "d_L2", "d_global", "relative_change_L1",
              "original_faces", "processed_faces"):
        float(r[k])
    assert all(not v.startswith(("[", "{")) for v in r.values())
# the same numbers as the records
import json, glob, os
rec = {}
for f in glob.glob(os.path.join(os.path.dirname(sys.argv[1]), "s?.jsonl")):
    for l in open(f):
        j = json.loads(l)
        rec[j["id"]] = j
for r in rows[:20]:
    res = rec[r["id"]]["result"]
    assert float(r["hausdorff"]) == res["surface_distance"]["hausdorff"]["upper"]
    assert float(r["d_L2"]) == res["roughness_distance"]["distance"][1]
    assert float(r["forward_mean"]) == res["surface_distance"]["forward"]["mean"]
PY
if python3 -c "import pandas" 2> /dev/null; then
    python3 -c "import pandas,sys; d=pandas.read_csv(sys.argv[1]); assert len(d)==200 and d['hausdorff'].dtype.kind=='f'" \
        "$tmp/all.csv" && pass || fail "pandas does not read the CSV as it is"
fi

# --- a shard left out: its 50 pairs are missing (exit 6, listed), and still rows
expect 6 batch-summary "$tmp/s1.jsonl" "$tmp/s2.jsonl" "$tmp/s3.jsonl" --csv "$tmp/part.csv" \
    --pairs "$tmp/pairs.csv" && grep -q "missing: p3$" "$tmp/stderr" && grep -q "150 ok, 0 failed, 50 missing" "$tmp/stderr" &&
    [ "$(rows "$tmp/part.csv")" -eq 200 ] && [ "$(grep -c ',missing,' "$tmp/part.csv")" -eq 50 ] && pass ||
    fail "missing shard: $(tail -2 "$tmp/stderr")"
# without --pairs: the ids recorded
expect 0 batch-summary "$tmp/s1.jsonl" --csv "$tmp/one.csv" && [ "$(rows "$tmp/one.csv")" -eq 50 ] && pass ||
    fail "summary without a pair list"

# --- a failed pair is listed and exits 6; a later ok record of the same id wins
printf 'original,processed,id\na.ply,nothere.ply,bad\na.ply,b.ply,good\n' > "$tmp/p2.csv"
expect 6 batch "$tmp/p2.csv" --out "$tmp/f.jsonl" "${opts[@]}"
expect 6 batch-summary "$tmp/f.jsonl" --csv "$tmp/f.csv" --pairs "$tmp/p2.csv" &&
    grep -q "failed: bad: .*nothere.ply" "$tmp/stderr" && grep -q "^bad,error," "$tmp/f.csv" && pass ||
    fail "failed pair: $(cat "$tmp/stderr")"
cp "$tmp/b.ply" "$tmp/nothere.ply"
expect 0 batch "$tmp/p2.csv" --out "$tmp/f.jsonl" "${opts[@]}"
expect 0 batch-summary "$tmp/f.jsonl" --csv "$tmp/f.csv" --pairs "$tmp/p2.csv" && grep -q "^bad,ok," "$tmp/f.csv" &&
    pass || fail "the retried pair's ok record did not win"

# --- torn last line skipped with a warning; a foreign line is an error naming file and line (exit 3)
head -c 100 "$tmp/s1.jsonl" > "$tmp/torn.jsonl"
expect 6 batch-summary "$tmp/s2.jsonl" "$tmp/torn.jsonl" --csv "$tmp/t.csv" --pairs "$tmp/pairs.csv" &&
    grep -q "torn.jsonl: skipped a torn last line" "$tmp/stderr" && pass || fail "torn line: $(cat "$tmp/stderr")"
printf '{"id":"p0","status":"ok","result":{}}\nnot json\n' > "$tmp/foreign.jsonl"
expect 3 batch-summary "$tmp/foreign.jsonl" --csv "$tmp/t.csv" && grep -q "foreign.jsonl:2: not a meshdiff batch record" "$tmp/stderr" &&
    pass || fail "foreign line: $(cat "$tmp/stderr")"
expect 3 batch-summary "$tmp/nothing.jsonl" --csv "$tmp/t.csv" && grep -q "nothing.jsonl: cannot open" "$tmp/stderr" &&
    pass || fail "missing input: $(cat "$tmp/stderr")"
expect 2 batch-summary "$tmp/s1.jsonl" --csv "$tmp/s1.jsonl"

# --- --shard auto: Slurm array (index = task id - min), GNU parallel (auto/N); errors without them
SLURM_ARRAY_TASK_ID=7 SLURM_ARRAY_TASK_MIN=6 SLURM_ARRAY_TASK_COUNT=4 \
    "$bin" batch "$tmp/pairs.csv" --out "$tmp/slurm.jsonl" --shard auto "${opts[@]}" 2> "$tmp/stderr"
grep -q "shard 1/4" "$tmp/stderr" && [ "$(head -1 "$tmp/slurm.jsonl" | grep -c '"id":"p1"')" -eq 1 ] && pass ||
    fail "--shard auto under Slurm: $(cat "$tmp/stderr")"
PARALLEL_SEQ=3 "$bin" batch "$tmp/p2.csv" --out "$tmp/par.jsonl" --shard auto/4 "${opts[@]}" 2> "$tmp/stderr"
grep -q "shard 2/4" "$tmp/stderr" && pass || fail "--shard auto/4 under GNU parallel: $(cat "$tmp/stderr")"
unset SLURM_ARRAY_TASK_ID SLURM_ARRAY_TASK_MIN SLURM_ARRAY_TASK_COUNT PARALLEL_SEQ
expect 2 batch "$tmp/pairs.csv" --out "$tmp/x.jsonl" --shard auto && grep -q "neither a Slurm job array" "$tmp/stderr" &&
    pass || fail "--shard auto outside a job array: $(cat "$tmp/stderr")"
PARALLEL_SEQ=1 "$bin" batch "$tmp/pairs.csv" --out "$tmp/x.jsonl" --shard auto > /dev/null 2> "$tmp/stderr"
[ $? -eq 2 ] && grep -q "give it: --shard auto/N" "$tmp/stderr" && pass || fail "--shard auto under parallel without N"
SLURM_ARRAY_TASK_ID=x "$bin" batch "$tmp/pairs.csv" --out "$tmp/x.jsonl" --shard auto > /dev/null 2> "$tmp/stderr"
[ $? -eq 2 ] && grep -q "SLURM_ARRAY_TASK_ID='x' is not a non-negative integer" "$tmp/stderr" && pass ||
    fail "bad Slurm variable: $(cat "$tmp/stderr")"

# --- distance maps of both meshes: compare --distance-maps, and batch --maps-dir (one pair of files per id)
expect 0 compare "$tmp/a.ply" "$tmp/b.ply" --levels 1 --distance-maps "$tmp/m" &&
    grep -q "^Distance map of the original: $tmp/m_original.ply" "$tmp/stdout" &&
    grep -q "^Distance map of the processed: $tmp/m_processed.ply" "$tmp/stdout" && pass ||
    fail "compare --distance-maps: $(tail -3 "$tmp/stdout")"
python3 - "$tmp/m_original.ply" "$tmp/m_processed.ply" <<'PY' && pass || fail "the two maps do not share one colour range"
import sys
def header(p):
    lines = []
    with open(p, "rb") as f:
        for raw in f:
            line = raw.decode("ascii", "replace").strip()
            lines.append(line)
            if line == "end_header":
                return lines
a, b = header(sys.argv[1]), header(sys.argv[2])
ra = [l for l in a if l.startswith("comment colour:")]
rb = [l for l in b if l.startswith("comment colour:")]
assert ra and ra == rb, (ra, rb)
assert any("of " in l and "a.ply to the surface of" in l for l in a)
assert any("b.ply to the surface of" in l for l in b)
PY
expect 2 compare "$tmp/a.ply" "$tmp/b.ply" --distance-maps "$tmp/m" --distance-map "$tmp/x.ply"
printf 'original,processed,id
a.ply,b.ply,first pair
a.ply,b.ply,second
' > "$tmp/pm.csv"
expect 0 batch "$tmp/pm.csv" --out "$tmp/pm.jsonl" --maps-dir "$tmp/maps" "${opts[@]}" &&
    [ -f "$tmp/maps/second_original.ply" ] && [ -f "$tmp/maps/second_processed.ply" ] &&
    [ "$(ls "$tmp/maps" | grep -c '^first_pair-[0-9a-f]*_original.ply$')" -eq 1 ] &&
    grep -q '"distance_maps":{"original":"[^"]*maps/second_original.ply"' "$tmp/pm.jsonl" && pass ||
    fail "batch --maps-dir: $(ls "$tmp/maps" 2>&1) $(grep -o '"distance_maps":{[^}]*}' "$tmp/pm.jsonl")"

finish
