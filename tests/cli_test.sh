#!/usr/bin/env bash
# End-to-end checks of the meshdiff tool: exit codes, reports, JSON keys,
# output files, resumable batch, thread-count independence.
# Usage: cli_test.sh MESHDIFF_BINARY DATA_DIR
set -u
bin="$1"
data=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/cli_lib.sh"

# --- usage and exit codes
expect 0 --help
expect 0 --version && grep -q "meshdiff" "$tmp/stdout" && pass || fail "--version output"
expect 2 profile
expect 2 profile "$data/fandisk.ply" --levels 0
expect 2 profile "$data/fandisk.ply" --levels abc
expect 2 profile "$data/fandisk.ply" --curvature nope
expect 2 "$data/fandisk.ply" "$data/fandisk.ply" --no-roughness --no-distance
expect 2 "$data/fandisk.ply" "$data/fandisk.ply" -k 0
expect 3 profile "$tmp/missing.ply" && grep -q "missing.ply: no such file" "$tmp/stderr" && pass || fail "missing file message"
: > "$tmp/empty.ply"
expect 3 profile "$tmp/empty.ply" && grep -q "empty.ply: file is empty" "$tmp/stderr" && pass || fail "empty file message"
head -c 40000 "$data/sphere_ico_2562.ply" > "$tmp/cut.ply"
expect 3 profile "$tmp/cut.ply" && grep -q "cut.ply" "$tmp/stderr" && pass || fail "truncated file message"
printf 'OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n' > "$tmp/nan.off"
expect 4 profile "$tmp/nan.off" && grep -q "non-finite" "$tmp/stderr" && pass || fail "nan message"
[ "$(wc -l < "$tmp/stderr")" -eq 1 ] && pass || fail "errors must be one line"

# --- profile: text, JSON keys, vertex data
expect 0 profile "$data/fandisk.ply" --levels 1,2,5 --json "$tmp/p.json" --vertex-data "$tmp/v.ply" &&
    grep -q "global" "$tmp/stdout" && pass || fail "profile text"
json_check "$tmp/p.json" 'j["schema"] == "meshdiff.profile/1" and j["levels"] == [1, 2, 5] and len(j["sigma"]) == 3 and j["sigma_global"] > 0 and "vertices" in j["mesh"] and j["curvature"]["method"] == "goldfeather" and "undefined_vertices" in j["curvature"] and finite(j)'
head -c 2000 "$tmp/v.ply" | grep -q "property double D_5" && pass || fail "vertex-data PLY lacks D_5"
head -c 2000 "$tmp/v.ply" | grep -q "property uchar red" && pass || fail "vertex-data PLY lacks colours"
expect 0 profile "$tmp/v.ply" --levels 1 || fail "vertex-data PLY does not read back"
expect 0 profile "$data/fandisk.ply" --json - --no-global --curvature meyer
json_check "$tmp/stdout" 'j["sigma_global"] is None and j["curvature"]["method"] == "meyer" and len(j["levels"]) == 20'

# --- the exact profile of a generated surface beside the estimated one
expect 0 generate torus "$tmp/torus.ply" --n 256
expect 0 profile "$tmp/torus.ply" --exact --levels 1,5 --json "$tmp/t.json"
json_check "$tmp/t.json" 'j["exact"]["property"] == "exact_H" and len(j["exact"]["sigma"]) == 2 and j["exact"]["h_error"]["rms"] < 0.1 and finite(j)'
expect 2 profile "$data/fandisk.ply" --exact

# --- smoothing records profiles and the distance to the input
expect 0 generate noisy-sphere "$tmp/ns.ply" --subdivisions 3
expect 0 smooth "$tmp/ns.ply" "$tmp/ns_s.ply" --method laplacian --iterations 6 --profile-every 3 --json "$tmp/sm.json"
json_check "$tmp/sm.json" 'j["iterations"] == [0, 3, 6] and len(j["distance_to_input"]) == 3 and j["distance_to_input"][0]["hausdorff_relative"] < 1e-12 and j["distance_to_input"][2]["hausdorff"] > 0 and j["sigma"][2][0] < j["sigma"][0][0] and finite(j)'

# --- dirty and open meshes run to a report with their defects counted
for m in teapot.obj bunny_res3.ply bunny_res4_ascii.ply hemisphere.ply; do
    expect 0 profile "$data/$m" --json "$tmp/d.json" || continue
    json_check "$tmp/d.json" 'finite(j) and all(s is not None for s in j["sigma"])'
done
json_check "$tmp/d.json" 'j["mesh"]["boundary_loops"] == 1'

# --- compare: text, JSON keys, distance map, thread independence
expect 0 "$data/sphere_ico_2562.ply" "$data/ellipsoid_150_100_100.ply" --levels 1,5 &&
    grep -q "Hausdorff distance" "$tmp/stdout" && pass || fail "compare text"
expect 0 compare "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --levels 1,5 --json "$tmp/c1.json" \
    --threads 1 --distance-map "$tmp/dm.ply" --color-range 0 0.01
json_check "$tmp/c1.json" 'j["schema"] == "meshdiff.compare/1" and j["original"]["schema"] == "meshdiff.profile/1" and j["roughness_distance"]["k"] == 1e-4 and len(j["roughness_distance"]["distance"]) == 2 and "global" in j["roughness_distance"] and all(k in j["surface_distance"]["forward"] for k in ("min","max","mean","rms","samples")) and j["surface_distance"]["hausdorff"] == max(j["surface_distance"]["forward"]["max"], j["surface_distance"]["backward"]["max"]) and j["surface_distance"]["diagonal"] > 0 and finite(j)'
head -c 2000 "$tmp/dm.ply" | grep -q "property double distance" && pass || fail "distance map lacks distance"
expect 0 compare "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --levels 1,5 --json "$tmp/c2.json" --threads 2
python3 -c "import json,sys; a=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2])); sys.exit(0 if a==b else 1)" \
    "$tmp/c1.json" "$tmp/c2.json" && pass || fail "compare JSON differs between 1 and 2 threads"
expect 0 "$data/hemisphere.ply" "$data/hemisphere.ply" --no-roughness --json "$tmp/self.json"
json_check "$tmp/self.json" 'j["surface_distance"]["hausdorff"] < 1e-12 * j["surface_distance"]["diagonal"] and j["roughness_distance"] is None'
expect 0 "$data/sphere_ico_2562.ply" "$data/sphere_ico_2562.ply" --no-distance --json "$tmp/same.json"
json_check "$tmp/same.json" 'all(d == 0 for d in j["roughness_distance"]["distance"]) and j["roughness_distance"]["global"]["distance"] == 0'
expect 0 "$data/torus_R1_r025.ply" "$data/hemisphere.ply" --face-sampling montecarlo --seed 7 --samples 5000 --json "$tmp/mc1.json" --no-roughness
expect 0 "$data/torus_R1_r025.ply" "$data/hemisphere.ply" --face-sampling montecarlo --seed 7 --samples 5000 --json "$tmp/mc2.json" --no-roughness
cmp -s "$tmp/mc1.json" "$tmp/mc2.json" && pass || fail "seeded Monte Carlo is not reproducible"

# --- batch: error lines, resume, shards
cat > "$tmp/pairs.csv" <<CSV
original,processed,id
$data/sphere_ico_2562.ply,$data/ellipsoid_150_100_100.ply,a
$data/fandisk.ply,$tmp/missing.ply,b
$data/bunny_res3.ply,$data/bunny_res4_ascii.ply,c
CSV
expect 6 batch "$tmp/pairs.csv" --out "$tmp/r.jsonl" --levels 1 -q
[ "$(wc -l < "$tmp/r.jsonl")" -eq 3 ] && pass || fail "batch wrote $(wc -l < "$tmp/r.jsonl") lines, want 3"
grep -q '"status":"error"' "$tmp/r.jsonl" && pass || fail "batch error line"
expect 6 batch "$tmp/pairs.csv" --out "$tmp/r.jsonl" --levels 1 -q
[ "$(wc -l < "$tmp/r.jsonl")" -eq 4 ] && pass || fail "resume re-ran finished pairs"
expect 0 batch "$tmp/pairs.csv" --out "$tmp/s0.jsonl" --levels 1 --shard 0/2 -q
expect 6 batch "$tmp/pairs.csv" --out "$tmp/s1.jsonl" --levels 1 --shard 1/2 -q --no-distance
grep -q "\"id\":\"b\"" "$tmp/s1.jsonl" && pass || fail "shard 1/2 should hold pair b"
grep -q '"id":"a"' "$tmp/s0.jsonl" && grep -q '"id":"c"' "$tmp/s0.jsonl" && pass || fail "shard 0/2 should hold pairs a and c"
expect 2 batch "$tmp/pairs.csv" --out "$tmp/x.jsonl" --shard 2/2

finish
