"""`meshdiff compare --samples-out FILE.ply`: the samples of both directions as a binary PLY point
cloud that numpy reads; every distance checked against a brute-force point-to-triangle distance."""
import json
import subprocess

import numpy as np

DTYPE = np.dtype([("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("distance", "<f8"), ("signed_distance", "<f8"),
                  ("kind", "u1"), ("direction", "u1"), ("face", "<i4")])


def read_ply_cloud(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    assert header[1] == "format binary_little_endian 1.0"
    n = int(next(line for line in header if line.startswith("element vertex")).split()[2])
    props = [line.split()[1:] for line in header if line.startswith("property")]
    assert props == [["double", "x"], ["double", "y"], ["double", "z"], ["double", "distance"],
                     ["double", "signed_distance"], ["uchar", "kind"], ["uchar", "direction"], ["int", "face"]]
    body = np.frombuffer(data, dtype=DTYPE, offset=end)
    assert len(body) == n
    return body


def point_triangle_distance(p, a, b, c):
    """Distance from each row of p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5), vectorised."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = ap @ ab, ap @ ac
    bp = p - b
    d3, d4 = bp @ ab, bp @ ac
    cp = p - c
    d5, d6 = cp @ ab, cp @ ac
    va = d3 * d6 - d5 * d4
    vb = d5 * d2 - d1 * d6
    vc = d1 * d4 - d3 * d2
    denom = va + vb + vc
    with np.errstate(divide="ignore", invalid="ignore"):
        v = vb / denom
        w = vc / denom
        q = a + v[:, None] * ab + w[:, None] * ac  # interior
        t_ab = d1 / (d1 - d3)
        t_ac = d2 / (d2 - d6)
        t_bc = (d4 - d3) / ((d4 - d3) + (d5 - d6))
    cases = [
        ((d1 <= 0) & (d2 <= 0), np.broadcast_to(a, p.shape)),
        ((d3 >= 0) & (d4 <= d3), np.broadcast_to(b, p.shape)),
        ((d6 >= 0) & (d5 <= d6), np.broadcast_to(c, p.shape)),
        ((vc <= 0) & (d1 >= 0) & (d3 <= 0), a + t_ab[:, None] * ab),
        ((vb <= 0) & (d2 >= 0) & (d6 <= 0), a + t_ac[:, None] * ac),
        ((va <= 0) & ((d4 - d3) >= 0) & ((d5 - d6) >= 0), b + t_bc[:, None] * (c - b)),
    ]
    done = np.zeros(len(p), dtype=bool)
    for mask, point in cases:
        m = mask & ~done
        q[m] = point[m]
        done |= m
    return np.linalg.norm(p - q, axis=1)


def write_pyramid(path, h, n_side=3):
    """A square [-1, 1]^2 grid (n_side x n_side quads, two triangles each) with its centre raised to h."""
    xs = np.linspace(-1, 1, n_side + 1)
    V = np.array([[x, y, 0.0] for y in xs for x in xs])
    V[:, 2] = h * np.clip(1 - np.maximum(abs(V[:, 0]), abs(V[:, 1])), 0, None)
    F = []
    for j in range(n_side):
        for i in range(n_side):
            v0 = j * (n_side + 1) + i
            F += [(v0, v0 + 1, v0 + n_side + 2), (v0, v0 + n_side + 2, v0 + n_side + 1)]
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
                "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(V), len(F)))
        f.writelines("%r %r %r\n" % tuple(v) for v in V)
        f.writelines("3 %d %d %d\n" % t for t in F)
    return V, np.array(F)


def test_samples_out_holds_both_directions_with_exact_distances(cli, tmp_path):
    Va, Fa = write_pyramid(tmp_path / "a.ply", 0.0, 3)
    Vb, Fb = write_pyramid(tmp_path / "b.ply", 0.6, 4)
    out = tmp_path / "samples.ply"
    subprocess.run([cli, str(tmp_path / "a.ply"), str(tmp_path / "b.ply"), "--no-roughness", "-n", "3000",
                    "--samples-out", str(out), "--json", str(tmp_path / "c.json")], check=True,
                   stdout=subprocess.DEVNULL)
    j = json.load(open(tmp_path / "c.json"))["surface_distance"]
    s = read_ply_cloud(out)
    for direction, side, (V, F), (Vo, Fo) in ((0, "forward", (Va, Fa), (Vb, Fb)), (1, "backward", (Vb, Fb), (Va, Fa))):
        d = s[s["direction"] == direction]
        assert len(d) == j[side]["samples"]
        for kind, name in enumerate(("vertex", "edge", "face")):
            assert (d["kind"] == kind).sum() == j[side]["samples_by_kind"][name]
        assert d["distance"].max() == j[side]["max"]
        P = np.stack([d["x"], d["y"], d["z"]], axis=1)
        brute = np.min([point_triangle_distance(P, Vo[t[0]], Vo[t[1]], Vo[t[2]]) for t in Fo], axis=0)
        np.testing.assert_allclose(d["distance"], brute, rtol=1e-12, atol=1e-15)
        # The face of each sample holds it (its distance to that face of the sampled mesh is 0).
        on_face = np.array([point_triangle_distance(P[i:i + 1], *V[F[f]])[0] for i, f in enumerate(d["face"])])
        assert np.all(d["face"] >= 0) and np.all(on_face < 1e-12)
    assert len(s) == j["forward"]["samples"] + j["backward"]["samples"]


def write_cube(path, lo, hi):
    """The cube [lo, hi]^3 as 12 outward triangles."""
    V = np.array([[hi if i & 1 else lo, hi if i & 2 else lo, hi if i & 4 else lo] for i in range(8)])
    F = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4), (2, 6, 3), (3, 6, 7), (0, 4, 2),
         (2, 4, 6), (1, 3, 5), (3, 7, 5)]
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\n"
                "element face 12\nproperty list uchar int vertex_indices\nend_header\n")
        f.writelines("%r %r %r\n" % tuple(v) for v in V)
        f.writelines("3 %d %d %d\n" % t for t in F)


def test_samples_out_signed_distance_of_nested_cubes(cli, tmp_path):
    """The unit cube against the cube scaled by 1.1 about its centre: closed-form signed distances."""
    write_cube(tmp_path / "big.ply", -0.05, 1.05)
    write_cube(tmp_path / "small.ply", 0.0, 1.0)
    out = tmp_path / "samples.ply"
    subprocess.run([cli, str(tmp_path / "big.ply"), str(tmp_path / "small.ply"), "--no-roughness", "-n", "2000",
                    "--samples-out", str(out), "--json", str(tmp_path / "c.json")], check=True,
                   stdout=subprocess.DEVNULL)
    j = json.load(open(tmp_path / "c.json"))["surface_distance"]
    assert j["sign"] == "positive outside"
    s = read_ply_cloud(out)
    P = np.stack([s["x"], s["y"], s["z"]], axis=1)
    fwd = s["direction"] == 0
    # Forward: samples of the big cube, outside the small one: distance to the box [0, 1]^3.
    outside = np.linalg.norm(np.maximum(0, np.maximum(-P, P - 1)), axis=1)
    np.testing.assert_allclose(s["signed_distance"][fwd], outside[fwd], rtol=0, atol=1e-14)
    corners = fwd & (s["kind"] == 0)
    np.testing.assert_allclose(s["signed_distance"][corners], np.sqrt(3) * 0.05, rtol=0, atol=1e-15)
    # Backward: samples of the small cube, inside the big one: minus the distance to its faces.
    inside = np.minimum(P + 0.05, 1.05 - P).min(axis=1)
    np.testing.assert_allclose(s["signed_distance"][~fwd], -inside[~fwd], rtol=0, atol=1e-14)
    for side, m in (("forward", fwd), ("backward", ~fwd)):
        assert j[side]["signed_unavailable"] is None
        assert j[side]["signed"]["min"] == s["signed_distance"][m].min()
        assert j[side]["signed"]["max"] == s["signed_distance"][m].max()
        assert abs(j[side]["signed"]["mean"] - s["signed_distance"][m].mean()) < 1e-15


def test_samples_out_signed_distance_nan_against_an_open_mesh(cli, tmp_path):
    write_pyramid(tmp_path / "open.ply", 0.3, 3)
    write_cube(tmp_path / "cube.ply", -2.0, 2.0)
    out = tmp_path / "samples.ply"
    subprocess.run([cli, str(tmp_path / "cube.ply"), str(tmp_path / "open.ply"), "--no-roughness", "-n", "500",
                    "--samples-out", str(out), "--json", str(tmp_path / "c.json")], check=True,
                   stdout=subprocess.DEVNULL)
    j = json.load(open(tmp_path / "c.json"))["surface_distance"]
    assert j["forward"]["signed"] is None
    assert j["forward"]["signed_unavailable"].startswith("the processed mesh has 12 boundary edges")
    s = read_ply_cloud(out)
    assert np.all(np.isnan(s["signed_distance"][s["direction"] == 0]))
    back = s[s["direction"] == 1]
    # The open pyramid lies inside the cube: every backward sample has a negative signed distance.
    np.testing.assert_array_equal(back["signed_distance"], -back["distance"])
    assert b"comment signed_distance is NaN in the forward direction" in open(out, "rb").read()
