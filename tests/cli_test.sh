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
# compare reads both files at once (with 2 threads): the original's error still comes first, and a bad processed
# file is named, at 1 and 2 threads alike
for t in 1 2; do
    expect 3 "$tmp/missing.ply" "$tmp/empty.ply" --threads $t && grep -q "missing.ply: no such file" "$tmp/stderr" &&
        [ "$(wc -l < "$tmp/stderr")" -eq 1 ] && pass || fail "compare, both inputs bad, --threads $t: $(cat "$tmp/stderr")"
    expect 4 "$data/fandisk.ply" "$tmp/nan.off" --threads $t && grep -q "nan.off" "$tmp/stderr" && pass ||
        fail "compare, processed input bad, --threads $t: $(cat "$tmp/stderr")"
done

# --- hostile input (issue 13, tests/data/hostile/README.md): the exit code within 10 s (several files hung or
# crashed the OpenMesh readers), and an error is one printable line naming the file
while read -r code file; do
    expect_within 10 "$code" profile "$data/hostile/$file" --levels 1 || continue
    [ "$code" -eq 0 ] && continue
    grep -q "$file" "$tmp/stderr" && [ "$(wc -l < "$tmp/stderr")" -eq 1 ] && ! LC_ALL=C grep -q '[^[:print:]]' "$tmp/stderr" &&
        pass || fail "$file: the error is not one printable line naming the file: $(head -c 300 "$tmp/stderr")"
done <<'LIST'
3 off_header_only.off
3 off_negative_corner_count.off
3 off_count_beyond_body.off
4 off_inf.off
4 off_overflow.off
3 off_truncated.off
3 off_trailing_face.off
3 off_4off.off
4 off_negative_index.off
0 off_glued_counts.off
0 off_colours_comments.off
3 obj_empty_vertex_index.obj
4 obj_two_corners.obj
4 obj_zero_index.obj
4 obj_relative_before_first.obj
4 obj_lines_and_points.obj
4 obj_beyond_limit.obj
0 obj_all_corner_forms.obj
4 stl_nan.stl
4 stl_1e308.stl
4 stl_nan_binary.stl
3 stl_count_mismatch.stl
3 stl_truncated.stl
0 stl_two_solids.stl
0 ply_no_property_huge_count.ply
3 ply_count_beyond_body.ply
3 ply_duplicate_element.ply
3 ply_trailing_face.ply
3 ply_control_bytes.ply
4 ply_beyond_limit.ply
0 ply_at_limit.ply
LIST
mkfifo "$tmp/fifo.ply"
expect_within 10 3 profile "$tmp/fifo.ply" && grep -q "fifo.ply: not a regular file (a FIFO)" "$tmp/stderr" && pass ||
    fail "FIFO message"
expect_within 10 3 profile /dev/null && grep -q "not a regular file (a character device)" "$tmp/stderr" && pass ||
    fail "device message"
mkdir "$tmp/dir.ply"
expect_within 10 3 profile "$tmp/dir.ply" && grep -q "not a regular file (a directory)" "$tmp/stderr" && pass ||
    fail "directory message"
mkfifo "$tmp/blocks.mtl"
printf 'mtllib blocks.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n' > "$tmp/mtl.obj"
expect_within 10 0 profile "$tmp/mtl.obj" --levels 1

# --- the coordinate limit (io.h max_coordinate = 1e30) at both ends: just inside it, a comparison computes a
# finite report; beyond it, exit 4 naming the vertex and the limit
expect 0 generate sphere "$tmp/s.ply" --subdivisions 3
expect 0 generate noisy-sphere "$tmp/ns.ply" --subdivisions 3
# scale_ply IN OUT M: IN (binary PLY of `generate`) as ASCII PLY scaled to the largest coordinate magnitude M
scale_ply() {
    python3 - "$@" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read()
end = data.index(b"end_header\n") + len(b"end_header\n")
counts, nprop, element = {}, 0, None
for line in data[:end].decode().split("\n"):
    t = line.split()
    if t[:1] == ["element"]:
        element = t[1]
        counts[element] = int(t[2])
    elif t[:1] == ["property"] and element == "vertex":
        nprop += 1
pos, points, faces = end, [], []
for _ in range(counts["vertex"]):
    points.append(struct.unpack_from("<%dd" % nprop, data, pos)[:3])
    pos += 8 * nprop
for _ in range(counts["face"]):
    faces.append(struct.unpack_from("<B3i", data, pos)[1:])
    pos += 13
k = float(sys.argv[3]) / max(abs(c) for p in points for c in p)
with open(sys.argv[2], "w") as out:
    out.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(points), len(faces)))
    out.writelines("%r %r %r\n" % tuple(c * k for c in p) for p in points)
    out.writelines("3 %d %d %d\n" % f for f in faces)
PY
}
scale_ply "$tmp/s.ply" "$tmp/big_a.ply" 0.999e30 && scale_ply "$tmp/ns.ply" "$tmp/big_b.ply" 0.999e30 &&
    scale_ply "$tmp/ns.ply" "$tmp/over.ply" 1.001e30 && pass || fail "scale_ply"
expect_within 60 0 "$tmp/big_a.ply" "$tmp/big_b.ply" --levels 1,2 --json "$tmp/big.json"
json_check "$tmp/big.json" 'finite(j) and [p for p in nulls(j) if p.split(".")[-1] not in ("cutoff", "density_requested", "samples_requested", "summary_unavailable", "same_connectivity_unavailable", "roughness_unavailable", "signed_unavailable")] == [] and j["surface_distance"]["forward"]["signed"]["max"] > 1e26 and j["surface_distance"]["hausdorff"]["lower"] > 1e26 and j["surface_distance"]["psnr"]["mse_db"] > 0 and j["same_connectivity"]["displacement"]["max"] > 1e26 and j["surface_distance"]["hausdorff"]["certified"] and j["roughness_distance"]["global"]["distance"] > 0'
expect_within 10 4 profile "$tmp/over.ply" && grep -q "over.ply: vertex [0-9]* has the coordinate .* beyond meshdiff's limit of +-1e+30" "$tmp/stderr" &&
    pass || fail "coordinate limit message"

# --- profile: text, JSON keys, vertex data
expect 0 profile "$data/fandisk.ply" --levels 1,2,5 --json "$tmp/p.json" --vertex-data "$tmp/v.ply" &&
    grep -q "global" "$tmp/stdout" && pass || fail "profile text"
json_check "$tmp/p.json" 'j["schema"] == "meshdiff.profile/1" and j["levels"] == [1, 2, 5] and len(j["sigma"]) == 3 and j["sigma_global"] > 0 and "vertices" in j["mesh"] and j["curvature"]["method"] == "jet" and "undefined_vertices" in j["curvature"] and finite(j)'
head -c 2000 "$tmp/v.ply" | grep -q "property double D_5" && pass || fail "vertex-data PLY lacks D_5"
head -c 2000 "$tmp/v.ply" | grep -q "property uchar red" && pass || fail "vertex-data PLY lacks colours"
expect 0 profile "$tmp/v.ply" --levels 1 || fail "vertex-data PLY does not read back"
expect 0 profile "$data/fandisk.ply" --json - --no-global --curvature meyer
json_check "$tmp/stdout" 'j["sigma_global"] is None and j["curvature"]["method"] == "meyer" and len(j["levels"]) == 20'

# --- Corsini et al.'s roughness (--measure corsini): profile and compare, JSON, text, refused options
json_check "$tmp/p.json" '"steep_fits" in j["curvature"] and "normal_rows_dropped" not in j["curvature"] and "corsini" not in j'
expect 0 profile "$data/fandisk.ply" --measure corsini --levels 1,2 --json "$tmp/pc.json" &&
    grep -q "multi-scale roughness" "$tmp/stdout" && pass || fail "corsini profile text"
json_check "$tmp/pc.json" 'j["schema"] == "meshdiff.corsini/1" and j["corsini"]["levels"] == [1, 2] and all(r > 0 for r in j["corsini"]["roughness"]) and j["corsini"]["roughness_global"] > 0 and abs(j["corsini"]["multiscale"] - sum(j["corsini"]["roughness"]) / 2) < 1e-12 and finite(j)'
expect 0 "$data/fandisk.ply" "$data/fandisk.ply" --measure corsini --levels 1,3 --no-distance --json "$tmp/cc.json" &&
    grep -q "Corsini roughness" "$tmp/stdout" && pass || fail "corsini compare text"
json_check "$tmp/cc.json" 'j["measure"] == "corsini" and j["roughness_distance"] is None and j["corsini_distance"]["levels"] == [1, 3] and j["corsini_distance"]["distance"] == [0, 0] and j["corsini_distance"]["multiscale"]["distance"] == 0 and j["original"]["corsini"]["levels"] == [1, 3] and finite(j)'
expect 2 profile "$data/fandisk.ply" --measure corsini --radii 0.1
expect 2 profile "$data/fandisk.ply" --measure corsini --exact
expect 2 profile "$data/fandisk.ply" --unbiased-variance
expect 2 profile "$data/fandisk.ply" --measure nope
expect 2 "$data/fandisk.ply" "$data/fandisk.ply" --measure corsini --radii 0.1

# --- metric levels (--radii): only when asked for; JSON, text, compare
json_check "$tmp/p.json" '"radii" not in j and "sigma_radii" not in j and "radius_details" not in j'
expect 0 profile "$data/fandisk.ply" --levels 1 --radii 0.05,0.1 --json "$tmp/pr.json" &&
    grep -q "metric levels" "$tmp/stdout" && pass || fail "profile text with radii"
json_check "$tmp/pr.json" 'j["radii"] == [0.05, 0.1] and len(j["sigma_radii"]) == 2 and all(s > 0 for s in j["sigma_radii"]) and j["radius_details"][1]["radius"] == 0.1 and j["levels"] == [1] and finite(j)'
expect 0 profile "$data/fandisk.ply" --levels '' --no-global --radii default --json "$tmp/prd.json"
json_check "$tmp/prd.json" 'j["radii"] == [0.0125 * 2 ** (k / 2) for k in range(9)] and j["levels"] == [] and j["sigma_global"] is None and finite(j)'
expect 0 profile "$data/fandisk.ply" --levels 1 --radii 0.05,0.1 --vertex-data "$tmp/vr.ply" &&
    head -c 2000 "$tmp/vr.ply" | grep -q "property double D_r0p05" && pass || fail "vertex-data PLY lacks D_r0p05"
expect 0 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-distance --levels 1 --radii 0.1,0.2 --json "$tmp/cr.json" &&
    grep -q "d_r" "$tmp/stdout" && pass || fail "compare text with radii"
json_check "$tmp/cr.json" 'j["roughness_distance"]["radii"] == [0.1, 0.2] and len(j["roughness_distance"]["distance_radii"]) == 2 and len(j["roughness_distance"]["relative_change_radii"]) == 2 and j["original"]["radii"] == [0.1, 0.2] and finite(j)'

# --- the exact profile of a generated surface beside the estimated one
expect 0 generate torus "$tmp/torus.ply" --n 256
expect 0 profile "$tmp/torus.ply" --exact --levels 1,5 --json "$tmp/t.json"
json_check "$tmp/t.json" 'j["exact"]["property"] == "exact_H" and len(j["exact"]["sigma"]) == 2 and j["exact"]["h_error"]["rms"] < 0.1 and finite(j)'
expect 2 profile "$data/fandisk.ply" --exact
# with --radii: the exact table lists the radii too, each row matching the JSON (estimated and exact sigma_r)
expect 0 profile "$tmp/torus.ply" --exact --levels 1 --radii 0.2,0.4 --json "$tmp/tr.json" &&
    python3 - "$tmp/stdout" "$tmp/tr.json" <<'PY' && pass || fail "profile --exact text lacks the radii"
import json, sys
parts = open(sys.argv[1]).read().split("sigma exact")
j = json.load(open(sys.argv[2]))
rows = [l.split() for l in parts[2].splitlines()[1:] if l.strip()][:len(j["radii"])] if len(parts) == 3 else []
want = [["%g" % r, "%.6g" % s, "%.6g" % e] for r, s, e in zip(j["radii"], j["sigma_radii"], j["exact"]["sigma_radii"])]
sys.exit(0 if len(want) == 2 and rows == want and "metric levels" in parts[2].splitlines()[0] else 1)
PY

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
json_check "$tmp/c1.json" 'j["schema"] == "meshdiff.compare/2" and j["original"]["schema"] == "meshdiff.profile/1" and j["roughness_distance"]["k"] == 1e-4 and len(j["roughness_distance"]["distance"]) == 2 and "global" in j["roughness_distance"] and all(k in j["surface_distance"]["forward"] for k in ("min","max","mean","rms","samples")) and j["surface_distance"]["sampled_hausdorff"] == max(j["surface_distance"]["forward"]["max"], j["surface_distance"]["backward"]["max"]) and j["surface_distance"]["hausdorff"]["lower"] >= j["surface_distance"]["sampled_hausdorff"] and j["surface_distance"]["hausdorff"]["certified"] and j["surface_distance"]["diagonal"] > 0 and finite(j)'
head -c 2000 "$tmp/dm.ply" | grep -q "property double distance" && pass || fail "distance map lacks distance"
expect 0 compare "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --levels 1,5 --json "$tmp/c2.json" --threads 2
python3 -c "import json,sys; a=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2])); sys.exit(0 if a==b else 1)" \
    "$tmp/c1.json" "$tmp/c2.json" && pass || fail "compare JSON differs between 1 and 2 threads"
expect 0 "$data/hemisphere.ply" "$data/hemisphere.ply" --no-roughness --json "$tmp/self.json"
json_check "$tmp/self.json" 'j["surface_distance"]["hausdorff"]["upper"] < 1e-12 * j["surface_distance"]["diagonal"] and j["surface_distance"]["hausdorff"]["certified"] and j["roughness_distance"] is None'
# --- certified Hausdorff distance (issue 10): the options, the text, and --hausdorff sampled
expect 0 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-roughness &&
    grep -Eq "^Hausdorff distance: [0-9.e-]+ \.\. [0-9.e-]+ \(.*\), certified$" "$tmp/stdout" &&
    grep -Eq "^  forward  \(M1 -> M2\): [0-9.e-]+ \.\. [0-9.e-]+, at \(.*\) on face [0-9]+ of M1, closest point" "$tmp/stdout" &&
    grep -Eq "^Sampled maximum: " "$tmp/stdout" && pass || fail "certified Hausdorff text: $(grep -i hausdorff "$tmp/stdout")"
expect 0 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-roughness --hausdorff sampled &&
    grep -Eq "^Hausdorff distance: [0-9.e-]+ \([0-9.e-]+ wrt bounding box diagonal" "$tmp/stdout" &&
    ! grep -q "Sampled maximum\|certified" "$tmp/stdout" && pass || fail "--hausdorff sampled text"
expect 0 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-roughness --hausdorff-tolerance 1e-9 --json "$tmp/h9.json"
json_check "$tmp/h9.json" 'all(j["surface_distance"][d]["hausdorff"]["upper"] - j["surface_distance"][d]["hausdorff"]["lower"] <= 1e-9 * j["surface_distance"][d]["hausdorff"]["lower"] and j["surface_distance"][d]["hausdorff"]["certified"] for d in ("forward", "backward"))'
expect 0 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-roughness --hausdorff-abs-tolerance 2e-7 --json "$tmp/ha.json"
json_check "$tmp/ha.json" 'all(j["surface_distance"][d]["hausdorff"]["tolerance"] == 2e-7 and j["surface_distance"][d]["hausdorff"]["upper"] - j["surface_distance"][d]["hausdorff"]["lower"] <= 2e-7 for d in ("forward", "backward"))'
expect 0 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-roughness --hausdorff-tolerance 1e-12 --hausdorff-budget 5 --json "$tmp/hb.json" &&
    grep -q "NOT certified: the evaluation budget ran out" "$tmp/stdout" && pass || fail "budget text"
json_check "$tmp/hb.json" 'not j["surface_distance"]["hausdorff"]["certified"] and j["surface_distance"]["backward"]["hausdorff"]["budget_exhausted"] and j["surface_distance"]["hausdorff"]["upper"] >= j["surface_distance"]["hausdorff"]["lower"] and finite(j)'
for bad in "--hausdorff exact" "--hausdorff-tolerance 0" "--hausdorff-tolerance 1" "--hausdorff-tolerance nan" \
    "--hausdorff-abs-tolerance -1" "--hausdorff-abs-tolerance inf" "--hausdorff-budget 0" "--hausdorff-budget 2.5"; do
    # shellcheck disable=SC2086
    expect 2 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" $bad
done
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

# --- summary metrics (METHOD.md section 6), exact on a flat fan against a pyramid of height h
python3 - "$tmp" <<'PY' && pass || fail "writing the pyramids"
import sys
for name, h in (("fan", 0.0), ("pyr", 0.75)):
    with open("%s/%s.ply" % (sys.argv[1], name), "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
                "element face 4\nproperty list uchar int vertex_indices\nend_header\n")
        f.write("-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n0 0 %r\n" % h)
        f.write("3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n")
PY
expect 0 "$tmp/fan.ply" "$tmp/pyr.ply" --no-roughness -n 100000 --fscore 0.01,0.05 --histogram 8 --json "$tmp/sum.json" &&
    grep -q "Chamfer L1 (mean forward + mean backward)" "$tmp/stdout" && grep -q "F-score at 0.05 x diagonal" "$tmp/stdout" &&
    grep -q "PSNR (MPEG" "$tmp/stdout" && grep -q "face normal angle    RMS 36.8699 deg" "$tmp/stdout" && pass ||
    fail "compare text lacks the summary lines: $(tail -12 "$tmp/stdout")"
# Forward (fan -> pyramid) mean h/(3s), s = sqrt(1 + h^2); backward h/3; PSNR of the hand-computed case below;
# same connectivity: the apex moved by h (RMS h / sqrt(5)), every face normal turned by atan(h).
json_check "$tmp/sum.json" 'abs(j["surface_distance"]["forward"]["area_weighted"]["mean"] - 0.75/(3*1.25)) < 1e-12 and abs(j["surface_distance"]["backward"]["area_weighted"]["mean"] - 0.25) < 1e-12 and abs(j["surface_distance"]["chamfer"]["l1"] - 0.45) < 1e-12 and abs(j["surface_distance"]["psnr"]["mse_db"] - 10*math.log10(3*8/(0.75**2/6))) < 0.05 and abs(j["surface_distance"]["psnr"]["hausdorff_db"] - 10*math.log10(3*8/0.75**2)) < 1e-9 and j["surface_distance"]["psnr"]["factor"] == 3 and [f["threshold"] for f in j["surface_distance"]["fscore"]] == [0.01, 0.05] and abs(j["surface_distance"]["fscore"][1]["threshold_absolute"] - 0.05*8**0.5) < 1e-12 and len(j["surface_distance"]["forward"]["histogram"]["edges"]) == 9 and sum(j["surface_distance"]["backward"]["histogram"]["counts"]) == j["surface_distance"]["backward"]["samples"] and abs(j["same_connectivity"]["displacement"]["max"] - 0.75) < 1e-15 and abs(j["same_connectivity"]["displacement"]["rms"] - 0.75/5**0.5) < 1e-15 and abs(j["same_connectivity"]["normal_deviation_deg"]["max"] - math.degrees(math.atan(0.75))) < 1e-12 and j["same_connectivity_unavailable"] is None and finite(j)'
# A mesh against itself: F-score 1 at every threshold; different connectivity is said so.
expect 0 "$data/bunny_res3.ply" "$data/bunny_res3.ply" --no-roughness --fscore 0.001,0.005 --json "$tmp/selff.json"
json_check "$tmp/selff.json" 'all(f["fscore"] == 1 and f["precision"] == 1 and f["recall"] == 1 for f in j["surface_distance"]["fscore"]) and len(j["surface_distance"]["fscore"]) == 2 and j["same_connectivity"]["displacement"]["max"] == 0 and j["same_connectivity"]["normal_deviation_deg"]["max"] == 0'
expect 0 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-roughness -n 50000 --json "$tmp/diffc.json" &&
    grep -q "^Same connectivity: no (vertex counts differ" "$tmp/stdout" && pass || fail "no same-connectivity line"
json_check "$tmp/diffc.json" 'j["same_connectivity"] is None and j["same_connectivity_unavailable"].startswith("vertex counts differ") and j["surface_distance"]["fscore"] == [] and "histogram" not in j["surface_distance"]["forward"]'
# No face samples: the summary is null with its reason, never NaN.
expect 0 "$data/bunny_res3.ply" "$data/bunny_res4_ascii.ply" --no-roughness --no-face-samples --fscore 0.01 --json "$tmp/nof.json" &&
    grep -q "Summary metrics unavailable: no face sample" "$tmp/stdout" && pass || fail "no reason for the missing summary"
json_check "$tmp/nof.json" 'j["surface_distance"]["chamfer"] is None and j["surface_distance"]["psnr"] is None and j["surface_distance"]["fscore"] is None and j["surface_distance"]["forward"]["area_weighted"] is None and "no face sample" in j["surface_distance"]["summary_unavailable"] and finite(j)'

# --- --samples-out: both directions' samples as a binary PLY point cloud (numpy and brute force: python/tests/test_samples_out.py)
expect 0 "$tmp/fan.ply" "$tmp/pyr.ply" --no-roughness -n 4000 --samples-out "$tmp/samples.ply" --json "$tmp/so.json"
python3 - "$tmp/samples.ply" "$tmp/so.json" <<'PY' && pass || fail "--samples-out file does not match the report"
import json, struct, sys
data = open(sys.argv[1], "rb").read()
end = data.index(b"end_header\n") + len(b"end_header\n")
header = data[:end].decode().splitlines()
j = json.load(open(sys.argv[2]))["surface_distance"]
n = j["forward"]["samples"] + j["backward"]["samples"]
assert header[1] == "format binary_little_endian 1.0" and "element vertex %d" % n in header
assert len(data) - end == 46 * n
recs = [struct.unpack_from("<5dBBi", data, end + 46 * i) for i in range(n)]
for direction, side in ((0, "forward"), (1, "backward")):
    d = [r for r in recs if r[6] == direction]
    assert len(d) == j[side]["samples"] and max(r[3] for r in d) == j[side]["max"]
    assert [sum(r[5] == k for r in d) for k in range(3)] == [j[side]["samples_by_kind"][k] for k in ("vertex", "edge", "face")]
    # Both meshes are open: no sign, NaN in the signed column.
    assert j[side]["signed"] is None and all(r[4] != r[4] for r in d)
PY
expect 2 "$tmp/fan.ply" "$tmp/pyr.ply" --no-distance --samples-out "$tmp/x.ply" &&
    grep -q -- "--samples-out" "$tmp/stderr" && [ ! -e "$tmp/x.ply" ] && pass || fail "--samples-out with --no-distance"
expect 2 "$tmp/fan.ply" "$tmp/pyr.ply" --no-roughness --samples-out "$tmp/fan.ply"

# --- the HTML report (the page itself is checked in a browser: html_browser_test.py): written with the report,
# a distinct error naming the file when it cannot be, and no other output left then
b3="$data/bunny_res3.ply"
b4="$data/bunny_res4_ascii.ply"
expect 0 "$b3" "$b4" --levels 1,2 --html "$tmp/r.html" --json "$tmp/r.json" &&
    grep -q "^HTML report: $tmp/r.html" "$tmp/stdout" && grep -q '<script type="application/json" id="meshdiff-report">' "$tmp/r.html" &&
    [ "$(grep -c '<script src' "$tmp/r.html")" -eq 0 ] && pass || fail "--html writes the page"
json_check "$tmp/r.json" 'len(j["surface_distance"]["forward"]["histogram"]["counts"]) == 40'
expect 3 "$b3" "$b4" --levels 1 --html "$tmp/no-such-folder/r.html" --json "$tmp/r2.json" &&
    grep -q "no-such-folder/r.html" "$tmp/stderr" && [ ! -e "$tmp/r2.json" ] && pass ||
    fail "an unwritable --html path: $(cat "$tmp/stderr")"
expect 2 "$b3" "$b4" --html - && grep -q -- "--html" "$tmp/stderr" && pass || fail "--html -"
expect 2 "$b3" "$b4" --html "$b3" && grep -q -- "--html" "$tmp/stderr" && pass || fail "--html onto an input"
expect 0 profile "$b3" --levels 1,2 --html "$tmp/p.html" && grep -q "^HTML report: $tmp/p.html" "$tmp/stdout" &&
    grep -q '"schema":"meshdiff.profile/1"' "$tmp/p.html" && pass || fail "profile --html writes the page"
expect 2 profile "$b3" --measure corsini --html "$tmp/pc.html" && [ ! -e "$tmp/pc.html" ] && pass ||
    fail "profile --html with --measure corsini"
expect 3 profile "$b3" --html "$tmp/no-such-folder/p.html" && grep -q "no-such-folder/p.html" "$tmp/stderr" && pass ||
    fail "profile: an unwritable --html path"

finish
