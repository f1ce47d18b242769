#!/usr/bin/env bash
# Point clouds as inputs of compare (issue 11): a cloud of known points
# against a unit square, the vertices of a mesh as a cloud against the mesh,
# cloud against cloud against brute force; a faceless file elsewhere is a clear
# error; distance maps, --samples-out, batch and batch-summary with a cloud.
# Usage: cli_cloud_test.sh MESHDIFF_BINARY DATA_DIR
bin="$1"
data=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/cli_lib.sh"

python3 - "$tmp" "$data/sphere_ico_2562.ply" <<'PY' && pass || fail "writing the test clouds"
import random, struct, sys
tmp = sys.argv[1]
def cloud(path, pts):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\n"
                "property double z\nend_header\n" % len(pts))
        for p in pts:
            f.write("%r %r %r\n" % p)
# The unit square z = 0 and five points at distances 0.5, 0.25, 0, 1, 0.5 from it.
with open(tmp + "/square.off", "w") as f:
    f.write("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
cloud(tmp + "/five.ply", [(0.25, 0.25, 0.5), (0.75, 0.5, -0.25), (0.5, 0.5, 0.0), (2.0, 0.5, 0.0), (1.3, 1.4, 0.0)])
# The same points as an OBJ and an OFF (no faces).
with open(tmp + "/five.obj", "w") as f:
    f.write("v 0.25 0.25 0.5\nv 0.75 0.5 -0.25\nv 0.5 0.5 0\nv 2 0.5 0\nv 1.3 1.4 0\n")
with open(tmp + "/five.off", "w") as f:
    f.write("OFF\n5 0 0\n0.25 0.25 0.5\n0.75 0.5 -0.25\n0.5 0.5 0\n2 0.5 0\n1.3 1.4 0\n")
# Two random clouds for point-to-point, and the vertices of the sphere (binary PLY) as a cloud.
random.seed(5)
cloud(tmp + "/ra.ply", [tuple(random.uniform(-1, 1) for _ in range(3)) for _ in range(300)])
cloud(tmp + "/rb.ply", [tuple(random.uniform(-1.2, 1.2) for _ in range(3)) for _ in range(200)])
data = open(sys.argv[2], "rb").read()
head, body = data.split(b"end_header\n", 1)
lines = head.decode().split("\n")
nv = int([l for l in lines if l.startswith("element vertex")][0].split()[2])
props = [l.split()[1:] for l in lines if l.startswith("property") and not l.startswith("property list")]
assert "binary_little_endian" in head.decode() and [p[1] for p in props[:3]] == ["x", "y", "z"], props
fmt = {"float": "f", "double": "d"}
assert len(props) == 3, props  # x y z only
vfmt = "<" + "".join(fmt[p[0]] for p in props)
size = struct.calcsize(vfmt)
pts = [struct.unpack_from(vfmt, body, i * size) for i in range(nv)]
cloud(tmp + "/sphere_vertices.ply", pts)
with open(tmp + "/nan.ply", "w") as f:
    f.write("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
            "end_header\n0 0 0\n1 nan 0\n")
with open(tmp + "/empty.ply", "w") as f:
    f.write("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
            "end_header\n")
PY

# --- a faceless file to any other command: a clear error, exit 4
expect 4 profile "$tmp/five.ply" &&
    grep -q "five.ply: mesh has no faces: a point cloud (5 vertices); only compare accepts point clouds" "$tmp/stderr" &&
    pass || fail "profile of a cloud: $(cat "$tmp/stderr")"
expect 4 smooth "$tmp/five.off" "$tmp/out.ply" && grep -q "only compare accepts point clouds" "$tmp/stderr" && pass ||
    fail "smooth of a cloud: $(cat "$tmp/stderr")"
# NaN coordinates and an empty cloud stay errors in compare
expect 4 compare "$tmp/nan.ply" "$tmp/square.off" && grep -q "nan.ply: vertex 1 has a non-finite coordinate" "$tmp/stderr" &&
    pass || fail "NaN cloud: $(cat "$tmp/stderr")"
expect 4 compare "$tmp/square.off" "$tmp/empty.ply" && grep -q "empty.ply" "$tmp/stderr" && pass ||
    fail "empty cloud: $(cat "$tmp/stderr")"

# --- cloud -> mesh: point-to-surface, the five closed-form distances (OBJ and OFF coordinates are rounded to float)
for f in five.ply five.obj five.off; do
    tol=1e-15
    [ "$f" = five.ply ] || tol=1e-7
    expect 0 compare "$tmp/$f" "$tmp/square.off" --json "$tmp/five.json" || continue
    grep -q "point cloud: 5 points, no faces" "$tmp/stdout" && grep -q "Roughness: skipped: the original is a point cloud" "$tmp/stdout" &&
        grep -q "Forward distance (M1 -> M2, point-to-surface):" "$tmp/stdout" &&
        grep -q "Backward distance (M2 -> M1, surface-to-point):" "$tmp/stdout" &&
        grep -q "forward  (M1 -> M2): 1, exact over the points (at point 3 (2, 0.5, 0))" "$tmp/stdout" && pass ||
        fail "$f: text report: $(cat "$tmp/stdout")"
    json_check "$tmp/five.json" 'j["surface_distance"]["forward"]["distance_kind"] == "point-to-surface" and j["surface_distance"]["backward"]["distance_kind"] == "surface-to-point" and j["surface_distance"]["forward"]["samples_by_kind"] == {"vertex": 0, "edge": 0, "face": 0, "point": 5} and j["surface_distance"]["forward"]["max"] == 1.0 and abs(j["surface_distance"]["forward"]["mean"] - 0.45) < '$tol' and j["surface_distance"]["forward"]["min"] == 0 and j["surface_distance"]["forward"]["hausdorff"]["exact_over_points"] and j["surface_distance"]["forward"]["hausdorff"]["upper"] == 1.0 and j["surface_distance"]["backward"]["hausdorff"] is None and "hausdorff_unavailable" in j["surface_distance"]["backward"] and j["roughness_distance"] is None and "point cloud" in j["roughness_unavailable"] and j["original"]["mesh"]["point_cloud"] and not j["processed"]["mesh"]["point_cloud"] and j["same_connectivity"] is None and abs(j["surface_distance"]["forward"]["area_weighted"]["mean"] - 0.45) < '$tol' and finite(j)'
done

# --- the vertices of a mesh as a cloud against the mesh itself: 0 exactly, both ways round
expect 0 compare "$tmp/sphere_vertices.ply" "$data/sphere_ico_2562.ply" --json "$tmp/sv.json" &&
    json_check "$tmp/sv.json" 'j["surface_distance"]["forward"]["max"] == 0 and j["surface_distance"]["forward"]["samples"] == 2562 and j["surface_distance"]["backward"]["min"] == 0'
expect 0 compare "$data/sphere_ico_2562.ply" "$tmp/sphere_vertices.ply" --json "$tmp/vs.json" &&
    json_check "$tmp/vs.json" 'j["surface_distance"]["backward"]["max"] == 0 and j["surface_distance"]["backward"]["distance_kind"] == "point-to-surface" and j["surface_distance"]["forward"]["distance_kind"] == "surface-to-point"'

# --- cloud against cloud: point-to-point, against brute force; both maxima exact
expect 0 compare "$tmp/ra.ply" "$tmp/rb.ply" --json "$tmp/rr.json" --fscore 0.05 &&
    grep -q "Hausdorff distance: .*, exact$" "$tmp/stdout" && pass || fail "cloud-cloud text: $(cat "$tmp/stdout")"
python3 - "$tmp" <<'PY' && pass || fail "cloud-cloud distances differ from brute force"
import json, math, sys
t = sys.argv[1]
def read(p):
    lines = open(p).read().split("end_header\n")[1].split("\n")
    return [tuple(map(float, l.split())) for l in lines if l.strip()]
a, b = read(t + "/ra.ply"), read(t + "/rb.ply")
def nn(p, c): return min(math.dist(p, q) for q in c)
fw = [nn(p, b) for p in a]; bw = [nn(p, a) for p in b]
j = json.load(open(t + "/rr.json"))["surface_distance"]
assert j["forward"]["distance_kind"] == j["backward"]["distance_kind"] == "point-to-point"
assert abs(j["forward"]["max"] - max(fw)) < 1e-15 and abs(j["backward"]["max"] - max(bw)) < 1e-15, (j["forward"]["max"], max(fw))
assert abs(j["forward"]["mean"] - sum(fw) / len(fw)) < 1e-14 and abs(j["backward"]["mean"] - sum(bw) / len(bw)) < 1e-14
assert j["hausdorff"]["method"] == "certified" and j["hausdorff"]["certified"] and j["hausdorff"]["lower"] == j["hausdorff"]["upper"]
assert abs(j["chamfer"]["l1"] - (sum(fw) / len(fw) + sum(bw) / len(bw))) < 1e-14
diag = j["diagonal"]
rec = sum(d < 0.05 * diag for d in fw) / len(fw); pre = sum(d < 0.05 * diag for d in bw) / len(bw)
assert abs(j["fscore"][0]["recall"] - rec) < 1e-15 and abs(j["fscore"][0]["precision"] - pre) < 1e-15, (j["fscore"], rec, pre)
PY

# --- distance maps and --samples-out with a cloud side
expect 0 compare "$tmp/square.off" "$tmp/five.ply" --distance-maps "$tmp/map" --samples-out "$tmp/samples.ply" &&
    [ -s "$tmp/map_processed.ply" ] && [ -s "$tmp/map_original.ply" ] && grep -a -q "element face 0" "$tmp/map_processed.ply" &&
    grep -a -q "comment kind 3 = point" "$tmp/samples.ply" && pass || fail "maps or samples of a cloud"
python3 - "$tmp/samples.ply" <<'PY' && pass || fail "--samples-out of a cloud: the points are not kind 3 with their distances"
import struct, sys
d = open(sys.argv[1], "rb").read()
head, body = d.split(b"end_header\n", 1)
n = int([l for l in head.decode().split("\n") if l.startswith("element vertex")][0].split()[2])
# x y z distance signed_distance kind direction face
rows = [struct.unpack_from("<dddddBBi", body, i * 46) for i in range(n)]
pts = [r for r in rows if r[6] == 1]  # backward: the cloud's points
assert [r[5] for r in pts] == [3] * 5 and [r[7] for r in pts] == [-1] * 5
assert all(r[4] != r[4] for r in pts)  # a cloud's points are not signed: NaN
want = [0.5, 0.25, 0.0, 1.0, 0.5]
assert all(abs(r[3] - w) < 1e-15 for r, w in zip(pts, want)), pts
PY

# --- batch and batch-summary carry clouds; their roughness columns are empty
cat > "$tmp/pairs.csv" <<CSV
original,processed,id
$tmp/five.ply,$tmp/square.off,cloud
$data/sphere_ico_2562.ply,$data/sphere_irregular_3072.ply,mesh
CSV
expect 0 batch "$tmp/pairs.csv" --out "$tmp/b.jsonl" --levels 1 -n 20000 -q &&
    expect 0 batch-summary "$tmp/b.jsonl" --csv "$tmp/b.csv" &&
    python3 - "$tmp/b.csv" <<'PY' && pass || fail "batch-summary of a cloud pair: $(cat "$tmp/b.csv")"
import csv, sys
rows = {r["id"]: r for r in csv.DictReader(open(sys.argv[1]))}
c, m = rows["cloud"], rows["mesh"]
assert c["status"] == "ok" and m["status"] == "ok"
assert float(c["forward_max"]) == 1.0 and c["forward_distance_kind"] == "point-to-surface", c
rough = [k for k in m if k.startswith("d_")]
assert rough and all(m[k] != "" for k in rough) and all(c[k] == "" for k in rough), (rough, c)
assert c["original_faces"] == "0" and c["original_vertices"] == "5"
PY

finish
