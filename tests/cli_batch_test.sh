#!/usr/bin/env bash
# batch for thousands of pairs: a crash or a hang of one pair is that pair's
# error line; torn and foreign lines in --out; one writer per --out; the pair
# list's byte-order mark and duplicate ids.
# Usage: cli_batch_test.sh MESHDIFF_BINARY DATA_DIR
bin="$1"
data=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/cli_lib.sh"

h="$data/hemisphere.ply"
b3="$data/bunny_res3.ply"
b4="$data/bunny_res4_ascii.ply"
"$bin" generate sphere "$tmp/slow.ply" --subdivisions 8 > /dev/null  # 655,362 vertices: many seconds
lines() { wc -l < "$1" | tr -d ' '; }
valid_records() { python3 -c "import json,sys; [json.loads(l) for l in open(sys.argv[1])]" "$1"; }

# --- a pair that runs out of time is an error line (exit_code 124); the next pair still runs
printf 'original,processed,id\n%s,%s,slow\n%s,%s,fast\n' "$tmp/slow.ply" "$tmp/slow.ply" "$b3" "$b4" > "$tmp/p1.csv"
expect 6 batch "$tmp/p1.csv" --out "$tmp/r1.jsonl" --levels 1 -n 2000 --pair-timeout 3 -q
grep '"id":"slow"' "$tmp/r1.jsonl" | grep -q '"exit_code":124' && pass || fail "timeout line: $(cat "$tmp/r1.jsonl")"
grep '"id":"fast"' "$tmp/r1.jsonl" | grep -q '"status":"ok"' && pass || fail "the pair after a timeout did not run"

# --- a pair whose comparison crashes (SIGABRT sent to it) is an error line; the batch goes on
"$bin" batch "$tmp/p1.csv" --out "$tmp/r2.jsonl" --levels 1-20 -q > /dev/null 2>&1 &
batch_pid=$!
child=""
for _ in $(seq 100); do
    child=$(pgrep -f "compare .*-- $tmp/slow.ply" | head -1)
    [ -n "$child" ] && break
    sleep 0.05
done
[ -n "$child" ] && kill -ABRT "$child"
wait "$batch_pid"
code=$?
[ "$code" -eq 6 ] && pass || fail "batch with a crashed pair exited $code, want 6"
grep '"id":"slow"' "$tmp/r2.jsonl" | grep -q 'killed by signal 6' && pass || fail "crash line: $(cat "$tmp/r2.jsonl")"
grep '"id":"fast"' "$tmp/r2.jsonl" | grep -q '"status":"ok"' && pass || fail "the pair after a crash did not run"

# --- a torn last line (a killed run) is dropped on resume; the pair runs again
printf 'original,processed,id\n%s,%s,a\n%s,%s,b\n' "$b3" "$b4" "$h" "$h" > "$tmp/p2.csv"
expect 0 batch "$tmp/p2.csv" --out "$tmp/r3.jsonl" --levels 1 -n 2000 -q
head -1 "$tmp/r3.jsonl" > "$tmp/r4.jsonl"
head -c 100 < <(sed -n 2p "$tmp/r3.jsonl") >> "$tmp/r4.jsonl"  # record b torn after 100 bytes
expect 0 batch "$tmp/p2.csv" --out "$tmp/r4.jsonl" --levels 1 -n 2000
grep -q "dropped a torn last line" "$tmp/stderr" && pass || fail "no word about the torn line: $(cat "$tmp/stderr")"
grep -q "1 ok, 0 failed, 1 already done" "$tmp/stderr" && pass || fail "resume after a torn line: $(cat "$tmp/stderr")"
[ "$(lines "$tmp/r4.jsonl")" -eq 2 ] && valid_records "$tmp/r4.jsonl" && pass || fail "records after the resume"

# --- a line that is not a batch record: a clear error, the file untouched
{ head -1 "$tmp/r3.jsonl"; echo "hello"; } > "$tmp/r5.jsonl"
cp "$tmp/r5.jsonl" "$tmp/r5.before"
expect 3 batch "$tmp/p2.csv" --out "$tmp/r5.jsonl" --levels 1 -n 2000 -q
grep -q "r5.jsonl:2: not a meshdiff batch record" "$tmp/stderr" && pass || fail "foreign line: $(cat "$tmp/stderr")"
cmp -s "$tmp/r5.jsonl" "$tmp/r5.before" && pass || fail "a refused run changed --out"

# --- one writer per --out
if command -v flock > /dev/null; then
    touch "$tmp/r6.jsonl"
    flock "$tmp/r6.jsonl" "$bin" batch "$tmp/p2.csv" --out "$tmp/r6.jsonl" -q > /dev/null 2> "$tmp/stderr"
    code=$?
    [ "$code" -eq 3 ] && grep -q "another meshdiff batch is writing" "$tmp/stderr" && pass ||
        fail "a second writer: exit $code, $(cat "$tmp/stderr")"
fi

# --- the pair list: a UTF-8 byte-order mark is ignored; duplicate ids are an error
printf '\357\273\277original,processed,id\n%s,%s,x\n' "$b3" "$b4" > "$tmp/bom.csv"
expect 0 batch "$tmp/bom.csv" --out "$tmp/r7.jsonl" --levels 1 -n 2000 -q
[ "$(lines "$tmp/r7.jsonl")" -eq 1 ] && pass || fail "BOM header was taken for a pair"
printf '%s,%s,same\n%s,%s,same\n' "$b3" "$b4" "$h" "$h" > "$tmp/dup.csv"
expect 2 batch "$tmp/dup.csv" --out "$tmp/r8.jsonl" -q
grep -q "dup.csv:2: the id 'same' is already used on line 1" "$tmp/stderr" && pass || fail "duplicate ids: $(cat "$tmp/stderr")"

# --- a batch killed outright and run again finishes every pair once
printf 'original,processed,id\n' > "$tmp/p3.csv"
for i in 1 2 3 4 5 6; do printf '%s,%s,p%s\n' "$b3" "$b4" "$i" >> "$tmp/p3.csv"; done
"$bin" batch "$tmp/p3.csv" --out "$tmp/r9.jsonl" --levels 1-20 -q > /dev/null 2>&1 &
batch_pid=$!
sleep 0.5
kill -9 "$batch_pid"
wait "$batch_pid" 2> /dev/null
expect 0 batch "$tmp/p3.csv" --out "$tmp/r9.jsonl" --levels 1-20 -q
[ "$(grep -c '"status":"ok"' "$tmp/r9.jsonl")" -eq 6 ] && valid_records "$tmp/r9.jsonl" && pass ||
    fail "after kill + resume: $(lines "$tmp/r9.jsonl") lines"

# --- the summary metrics and histograms reach every record
# (-n 50000: at 2000 the vertex and edge samples of these small meshes take the whole budget)
expect 0 batch "$tmp/p2.csv" --out "$tmp/r11.jsonl" --levels 1 -n 50000 --fscore 0.01 --histogram 5 -q
python3 - "$tmp/r11.jsonl" <<'PY' && pass || fail "batch records lack the summary metrics"
import json, sys
recs = [json.loads(l) for l in open(sys.argv[1])]
assert len(recs) == 2 and all(r["status"] == "ok" for r in recs)
for r in recs:
    sd = r["result"]["surface_distance"]
    assert sd["chamfer"]["l1"] > 0 and sd["psnr"]["mse_db"] > 0 and len(sd["fscore"]) == 1
    assert sd["forward"]["area_weighted"]["mean"] > 0 and len(sd["backward"]["histogram"]["counts"]) == 5
    assert "same_connectivity" in r["result"]
PY

# --- metric levels reach every record (roughness_distance.radii, distance_radii, relative_change_radii)
expect 0 batch "$tmp/p2.csv" --out "$tmp/r10.jsonl" --levels 1 --radii 0.1,0.2 -n 2000 -q
python3 - "$tmp/r10.jsonl" <<'PY' && pass || fail "batch records lack the radii"
import json, sys
recs = [json.loads(l) for l in open(sys.argv[1])]
assert len(recs) == 2 and all(r["status"] == "ok" for r in recs)
for r in recs:
    d = r["result"]["roughness_distance"]
    assert d["radii"] == [0.1, 0.2] and len(d["distance_radii"]) == 2 and len(d["relative_change_radii"]) == 2
    assert r["result"]["original"]["radii"] == [0.1, 0.2]
PY
# the summary CSV of reference/json2csv.py carries them
python3 "$(dirname "$0")/../reference/json2csv.py" batch "$tmp/r10.csv" "$tmp/r10.jsonl" &&
    head -1 "$tmp/r10.csv" | grep -q "d_L1,d_global,change_L1,change_global,d_r0.1,d_r0.2,change_r0.1,change_r0.2" &&
    [ "$(wc -l < "$tmp/r10.csv")" -eq 3 ] && pass || fail "summary CSV lacks the radii: $(head -2 "$tmp/r10.csv")"
# ... and the area-weighted means, Chamfer and PSNR, each a number
python3 "$(dirname "$0")/../reference/json2csv.py" batch "$tmp/r11.csv" "$tmp/r11.jsonl" && pass || fail "json2csv on r11"
python3 - "$tmp/r11.csv" <<'PY' && pass || fail "summary CSV lacks the summary metrics: $(head -2 "$tmp/r11.csv")"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
keys = ("aw_mean_forward", "aw_mean_backward", "chamfer_l1", "chamfer_l2", "psnr_mse_db", "psnr_hausdorff_db")
assert len(rows) == 2 and all(float(r[k]) > 0 for r in rows for k in keys)
assert all(abs(float(r["chamfer_l1"]) - float(r["aw_mean_forward"]) - float(r["aw_mean_backward"])) < 1e-12 for r in rows)
PY

# --- --html-dir: the HTML report of every pair that succeeds, named in its record
printf '%s,%s,bunny pair\n%s,%s,bad\n' "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" "$data/bunny_res3.ply" \
    "$data/missing.ply" > "$tmp/html_pairs.csv"
expect 6 batch "$tmp/html_pairs.csv" --out "$tmp/html.jsonl" --html-dir "$tmp/reports" --levels 1 -q &&
    [ "$(ls "$tmp/reports" | wc -l)" -eq 1 ] && python3 - "$tmp/html.jsonl" <<'PY' && pass || fail "batch --html-dir"
import json, sys
ok, bad = [json.loads(l) for l in open(sys.argv[1])]
assert ok["status"] == "ok" and "html" not in bad, (ok, bad)
page = open(ok["html"]).read()
start = page.index('id="meshdiff-report">') + len('id="meshdiff-report">')
assert json.loads(page[start:page.index("</script>", start)]) == ok["result"]
PY
# --html-face-budget goes to every pair's page (bunny_res3 has 3,851 faces: drawn clustered under 1,000); without
# --html-dir it is refused before any pair runs
expect 6 batch "$tmp/html_pairs.csv" --out "$tmp/html3.jsonl" --html-dir "$tmp/reports3" --html-face-budget 1000 \
    --levels 1 -q && python3 - "$tmp/html3.jsonl" <<'PY' && pass || fail "batch --html-face-budget"
import json, re, sys
ok = json.loads(open(sys.argv[1]).readline())
page = open(ok["html"]).read()
assert '"face_budget":1000' in page, re.findall('"face_budget":[0-9]+', page)
assert '"reduced":true' in page
PY
expect 2 batch "$tmp/html_pairs.csv" --out "$tmp/html4.jsonl" --html-face-budget 1000 -q &&
    grep -q -- "--html-face-budget: needs --html" "$tmp/stderr" && [ ! -e "$tmp/html4.jsonl" ] &&
    pass || fail "batch --html-face-budget without --html-dir: $(cat "$tmp/stderr")"
expect 3 batch "$tmp/html_pairs.csv" --out "$tmp/html2.jsonl" --html-dir "$data/bunny_res3.ply" -q &&
    grep -q "bunny_res3.ply: cannot create the HTML reports folder" "$tmp/stderr" && [ ! -e "$tmp/html2.jsonl" ] &&
    pass || fail "batch --html-dir onto a file: $(cat "$tmp/stderr")"

# --- batch-summary --html: one page over the pairs, linking the --html-dir pages (checked in a browser:
# html_summary_browser_test.py); the CSV is unchanged by it; a bad path is exit 3 as compare's --html
expect 6 batch-summary "$tmp/html.jsonl" --csv "$tmp/s1.csv" -q && cp "$tmp/s1.csv" "$tmp/s1_before.csv" &&
    mkdir -p "$tmp/sum" && expect 6 batch-summary "$tmp/html.jsonl" --csv "$tmp/s1.csv" --html "$tmp/sum/s.html" -q &&
    cmp -s "$tmp/s1.csv" "$tmp/s1_before.csv" && grep -q "s1.csv and $tmp/sum/s.html written" "$tmp/stderr" &&
    python3 - "$tmp/sum/s.html" "$tmp/html.jsonl" <<'PY' && pass || fail "batch-summary --html: $(cat "$tmp/stderr")"
import json, os, re, sys
page, records = open(sys.argv[1]).read(), [json.loads(l) for l in open(sys.argv[2])]
start = page.index('id="meshdiff-summary">') + len('id="meshdiff-summary">')
assert json.loads(page[start:page.index("</script>", start)].replace("<\\/", "</")) == records
assert page.count("<tr data-index=") == len(records) and "<script src" not in page
links = re.findall(r'<a href="([^"]+)">', page)
assert len(links) == 1 and not links[0].startswith("/"), links
assert os.path.samefile(os.path.join(os.path.dirname(sys.argv[1]), links[0]), records[0]["html"])
PY
expect 6 batch-summary "$tmp/html.jsonl" --html "$tmp/sum/only.html" -q && [ -s "$tmp/sum/only.html" ] && pass ||
    fail "batch-summary --html without --csv"
expect 3 batch-summary "$tmp/html.jsonl" --html "$tmp/no-such-folder/s.html" --csv "$tmp/s2.csv" &&
    grep -q "no-such-folder/s.html" "$tmp/stderr" && [ ! -e "$tmp/s2.csv" ] && pass ||
    fail "batch-summary: an unwritable --html path: $(cat "$tmp/stderr")"
expect 2 batch-summary "$tmp/html.jsonl" --html - && grep -q -- "--html" "$tmp/stderr" && pass ||
    fail "batch-summary --html -"
expect 2 batch-summary "$tmp/html.jsonl" --html "$tmp/html.jsonl" && grep -q -- "--html" "$tmp/stderr" && pass ||
    fail "batch-summary --html onto an input"
expect 2 batch-summary "$tmp/html.jsonl" && grep -q -- "--csv or --html is required" "$tmp/stderr" && pass ||
    fail "batch-summary without --csv or --html"

finish
