#!/usr/bin/env bash
# Option ranges (exit 2 with the range in the message), outputs that never
# overwrite an input, and outputs that are never torn.
# Usage: cli_options_test.sh MESHDIFF_BINARY DATA_DIR
bin="$1"
data=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/cli_lib.sh"

h="$data/hemisphere.ply"

# expect_range MESSAGE_PART ARGS...: exit 2 within 10 s, the message names MESSAGE_PART.
expect_range() {
    part="$1"
    shift
    timeout 10 "$bin" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
    got=$?
    if [ "$got" -eq 2 ] && grep -q -- "$part" "$tmp/stderr"; then
        pass
    else
        fail "meshdiff $* exited $got (want 2 naming '$part'): $(head -c 300 "$tmp/stderr")"
    fi
}

# --- every numeric option has a range
expect_range "--samples" "$h" "$h" --no-roughness --samples -1
expect_range "--samples" "$h" "$h" --no-roughness --samples 0
expect_range "250000000" "$h" "$h" --no-roughness --samples 300000000
expect_range "--density" "$h" "$h" --no-roughness --density 0
expect_range "--density" "$h" "$h" --no-roughness --density nan
expect_range "above the limit" "$h" "$h" --no-roughness --density 1e12
expect_range "--threads" "$h" "$h" --no-roughness --threads 2147483647
expect_range "--threads" profile "$h" --threads -1
expect_range "--seed" "$h" "$h" --no-roughness --seed -5
expect_range "--k" "$h" "$h" --no-distance -k nan
expect_range "limit of 200" profile "$h" --levels 1-300
expect_range "--radii" profile "$h" --radii 0
expect_range "--radii" profile "$h" --radii 0.1,-0.2
expect_range "--radii" profile "$h" --radii nan
# --paper fixes the estimator, the weighting, the normalisation and the trim: a flag that contradicts it is refused
expect_range "--curvature jet contradicts" profile "$h" --paper --curvature jet
expect_range "--trim 0.1 contradicts" "$h" "$h" --no-distance --paper --trim 0.1
expect_range "--paper" "$h" "$h" --no-distance --paper --normalize area
"$bin" profile "$h" --paper --levels 1 --json - | grep -q '"method": *"goldfeather"' && pass || fail "--paper is not the goldfeather fit"
expect_range "--radii" profile "$h" --radii inf
expect_range "--radii" profile "$h" --radii 1e9
expect_range "--radii" profile "$h" --radii 0.1,,0.2
expect_range "--radii" profile "$h" --radii abc
expect_range "--fscore" "$h" "$h" --no-roughness -n 2000 --fscore 0
expect_range "--fscore" "$h" "$h" --no-roughness -n 2000 --fscore 0.001,-0.2
expect_range "--fscore" "$h" "$h" --no-roughness -n 2000 --fscore nan
expect_range "--fscore" "$h" "$h" --no-roughness -n 2000 --fscore abc
# --histogram 0 is no histogram, as the library's default (and Python's histogram=0)
if "$bin" "$h" "$h" --no-roughness -n 2000 --histogram 0 --json "$tmp/h0.json" >/dev/null 2>&1 &&
    ! grep -q '"histogram"' "$tmp/h0.json"; then pass; else fail "--histogram 0: want exit 0 and no histogram"; fi
expect_range "--histogram" "$h" "$h" --no-roughness -n 2000 --histogram 1e9
expect_range "limit of 64" profile "$h" --radii "$(seq -s, 1 70)"
expect_range "--color-range" "$h" "$h" --no-roughness --distance-map "$tmp/m.ply" --color-range 0 inf
expect_range "--color-range" profile "$h" --vertex-data "$tmp/v.ply" --color-range nan
expect_range "--shard" batch "$tmp/none.csv" --out "$tmp/x.jsonl" --shard 0/-1
expect_range "--shard" batch "$tmp/none.csv" --out "$tmp/x.jsonl" --shard 0/0
expect_range "--n" generate plane "$tmp/p.ply" --n 100000
expect_range "--vertices" generate torus-irregular "$tmp/p.ply" --vertices 1000000000
expect_range "--subdivisions" generate sphere "$tmp/p.ply" --subdivisions 9
expect_range "--iterations" smooth "$h" "$tmp/s.ply" --iterations -1
expect_range "--iterations" smooth "$h" "$tmp/s.ply" --iterations 2000000
expect_range "--distance-samples" smooth "$h" "$tmp/s.ply" --json "$tmp/s.json" --distance-samples 0
expect_range "--profile-every" smooth "$h" "$tmp/s.ply" --json "$tmp/s.json" --profile-every -2
expect_range "--seed" noise "$h" "$tmp/n.ply" --amplitude 0.1 --seed -1
expect_range "--method" smooth "$h" "$tmp/s.ply" --method gauss
[ ! -e "$tmp/s.ply" ] && [ ! -e "$tmp/p.ply" ] && pass || fail "a refused command wrote its output"

# --- no output onto an input, also through a link
cp "$h" "$tmp/in.ply"
ln -s "$tmp/in.ply" "$tmp/link.ply"
before=$(cksum < "$tmp/in.ply")
expect_range "does not overwrite its inputs" smooth "$tmp/in.ply" "$tmp/in.ply"
expect_range "does not overwrite its inputs" smooth "$tmp/in.ply" "$tmp/out.ply" --json "$tmp/link.ply"
expect_range "does not overwrite its inputs" noise "$tmp/in.ply" "$tmp/link.ply" --amplitude 0.1
expect_range "does not overwrite its inputs" profile "$tmp/in.ply" --json "$tmp/in.ply"
expect_range "does not overwrite its inputs" profile "$tmp/in.ply" --vertex-data "$tmp/link.ply"
expect_range "does not overwrite its inputs" "$tmp/in.ply" "$h" --json "$tmp/link.ply"
expect_range "does not overwrite its inputs" "$h" "$tmp/in.ply" --distance-map "$tmp/in.ply"
printf 'original,processed\n%s,%s\n' "$h" "$h" > "$tmp/pairs.csv"
expect_range "does not overwrite its inputs" batch "$tmp/pairs.csv" --out "$tmp/pairs.csv"
[ "$(cksum < "$tmp/in.ply")" = "$before" ] && pass || fail "an input file was changed"
[ "$(head -1 "$tmp/pairs.csv")" = "original,processed" ] && pass || fail "the pair list was changed"
expect 3 batch "$tmp" --out "$tmp/r.jsonl"
grep -q "is a directory" "$tmp/stderr" && pass || fail "batch on a directory: $(cat "$tmp/stderr")"

# --- outputs are written whole or not at all
# A write that fails half way (a file-size limit) is an error (exit 3) and leaves the old file as it was.
echo "old content" > "$tmp/target.ply"
(ulimit -f 8 && exec "$bin" smooth "$data/fandisk.ply" "$tmp/target.ply" --iterations 1) > /dev/null 2>"$tmp/stderr"
code=$?
[ "$code" -eq 3 ] && grep -q "target.ply" "$tmp/stderr" && pass || fail "write past the size limit: exit $code"
[ "$(cat "$tmp/target.ply")" = "old content" ] && pass || fail "a failed write destroyed the old output file"
(ulimit -f 8 && exec "$bin" profile "$data/fandisk.ply" --json "$tmp/target.ply" --levels 1-20) > /dev/null 2>&1
[ "$(cat "$tmp/target.ply")" = "old content" ] && pass || fail "a failed JSON write destroyed the old file"
# A failing run creates no output file.
expect 3 profile "$tmp/missing.ply" --json "$tmp/new.json"
[ ! -e "$tmp/new.json" ] && pass || fail "a failing run created its JSON output"
# A successful one replaces the file whole.
expect 0 smooth "$h" "$tmp/target.ply" --iterations 1
expect 0 profile "$tmp/target.ply" --levels 1
[ -z "$(find "$tmp" -name '.*meshdiff-*')" ] && pass || fail "temporary files left behind: $(find "$tmp" -name '.*meshdiff-*')"

# --- a file name that is not UTF-8 still gives valid JSON (U+FFFD), never exit 70
bad="$tmp/$(printf 'bad\377name').ply"
cp "$h" "$bad"
expect 0 profile "$bad" --levels 1 --json "$tmp/bad.json"
json_check "$tmp/bad.json" "'\ufffd' in j['mesh']['path']"
printf 'original,processed,id\n%s,%s,%s\n' "$bad" "$h" "$(printf 'id\377')" > "$tmp/badpairs.csv"
expect 0 batch "$tmp/badpairs.csv" --out "$tmp/bad.jsonl" --levels 1 -n 2000 -q
python3 -c "import json,sys; [json.loads(l) for l in open(sys.argv[1], encoding='utf-8')]" "$tmp/bad.jsonl" && pass ||
    fail "batch wrote a line that is not UTF-8 JSON"

finish
