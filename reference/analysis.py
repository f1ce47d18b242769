#!/usr/bin/env python3
"""Numerical checks of the reference studies that need the meshes themselves (numpy).

  analysis.py ringnoise VERTEXDATA.ply --levels 1,2,5,10,20 > OUT.json
      What white (uncorrelated) noise in H would give by itself. For a field e with variance
      s^2 and no correlation between vertices, Var(e_i - mean of e over n other vertices)
      = s^2 (1 + 1/n). With n_L(i) = |N_L(i)| from the mesh, the white-noise prediction is
      sigma_L / sigma_G = sqrt(mean_i (1 + 1/n_L(i)) / (1 + 1/(N - 1))). Also writes the
      measured ratio from the H stored in VERTEXDATA.ply (`meshdiff profile --vertex-data`)
      and the correlation of H between vertices one and exactly two edges apart.

  analysis.py fig3 DIR ITERATIONS > DIR/fig3.json
      Collects the reports of studies.sh section 8 (Fig. 3) into one file.

  analysis.py sphere-geometry IN.ply OUT.ply > OUT.json
      For a mesh meant to be a sphere (centred at the centroid): spread of the vertex radii
      r_i / mean(r) - 1 (min, max, RMS), the profile of 1/r_i (the mean curvature of the sphere
      through each vertex: the zeroth-order geometric part of H) at the global level, and
      OUT.ply = the same mesh with every vertex moved radially onto the sphere of the mean
      radius (same sampling, exact H = 1/r everywhere: what any estimator reports there is
      estimation error of that sampling).

Reads PLY with reference/plytool.py. Run with a python3 that has numpy (studies.sh uses PYNUM,
default /usr/bin/python3).
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plytool  # noqa: E402


def load(path):
    names, verts, faces, comments = plytool.read_ply(path)
    v = np.asarray(verts, dtype=float)
    tri = np.asarray([f for f in faces if len(f) == 3], dtype=np.int64)
    return names, v, tri, comments


def adjacency(n, tri):
    import scipy.sparse as sp
    i = np.concatenate([tri[:, 0], tri[:, 1], tri[:, 2], tri[:, 1], tri[:, 2], tri[:, 0]])
    j = np.concatenate([tri[:, 1], tri[:, 2], tri[:, 0], tri[:, 0], tri[:, 1], tri[:, 2]])
    a = sp.coo_matrix((np.ones(len(i), dtype=np.int8), (i, j)), shape=(n, n)).tocsr()
    a.data[:] = 1
    return a


def cmd_ringnoise(a):
    names, v, tri, _ = load(a.input)
    n = len(v)
    levels = [int(x) for x in a.levels.split(",")]
    H = v[:, names.index("H")]
    ok = np.isfinite(H)
    A = adjacency(n, tri)
    # Ring sets by breadth-first growth of a dense reach matrix (fine for the ~4,000-vertex spheres).
    reach = np.eye(n, dtype=bool)
    Af = A.astype(np.float32)
    out = {"mesh": a.input, "vertices": n, "levels": [], "white_noise_ratio": [], "measured_ratio": [],
           "mean_ring_size": []}
    Hc = H - H[ok].mean()
    sG = np.sqrt(np.mean(Hc[ok] ** 2) * (ok.sum() / (ok.sum() - 1)) ** 2)
    # sigma_G exactly as METHOD.md section 5: D_G(i) = H_i - mean of the others = n/(n-1) (H_i - mean).
    for L in range(1, max(levels) + 1):
        reach = reach | (Af @ reach.astype(np.float32) > 0)
        if L not in levels:
            continue
        ring = reach.copy()
        np.fill_diagonal(ring, False)
        ring &= ok[None, :]
        size = ring.sum(axis=1)
        mean_other = (ring.astype(float) @ np.where(ok, H, 0.0)) / np.maximum(size, 1)
        D = H - mean_other
        use = ok & (size > 0)
        sL = np.sqrt(np.mean(D[use] ** 2))
        pred = np.sqrt(np.mean(1 + 1 / size[use]) / (1 + 1 / (ok.sum() - 1)))
        out["levels"].append(L)
        out["mean_ring_size"].append(float(size[use].mean()))
        out["white_noise_ratio"].append(float(pred))
        out["measured_ratio"].append(float(sL / sG))
    e = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    e = np.unique(np.sort(e, axis=1), axis=0)
    e = e[ok[e[:, 0]] & ok[e[:, 1]]]
    out["sigma_global"] = float(sG)
    out["h_correlation_1_ring"] = float(np.mean(Hc[e[:, 0]] * Hc[e[:, 1]]) / np.mean(Hc[ok] ** 2))
    # Correlation between vertices exactly two edges apart.
    A2 = (A @ A).tocoo()
    two = (A2.row != A2.col)
    r, c = A2.row[two], A2.col[two]
    near = np.asarray(A[r, c]).ravel() == 0
    r, c = r[near], c[near]
    keep = ok[r] & ok[c]
    out["h_correlation_2_ring"] = float(np.mean(Hc[r[keep]] * Hc[c[keep]]) / np.mean(Hc[ok] ** 2))
    json.dump(out, sys.stdout, indent=1)
    sys.stdout.write("\n")


def cmd_sphere_geometry(a):
    names, v, tri, comments = load(a.input)
    p = v[:, :3] - v[:, :3].mean(axis=0)
    r = np.linalg.norm(p, axis=1)
    rbar = r.mean()
    rel = r / rbar - 1
    # On the scaled mesh (mean distance 1 from the centroid) the sphere through vertex i has H = rbar / r_i.
    h = rbar / r
    n = len(h)
    out = {"mesh": a.input, "vertices": n, "radius_mean": float(rbar),
           "radius_spread": {"min": float(rel.min()), "max": float(rel.max()), "rms": float(np.sqrt(np.mean(rel ** 2)))},
           "inverse_radius_sigma_global": float(np.std(h) * n / (n - 1)),
           "projected": a.output}
    q = p / r[:, None] * rbar
    plytool.write_ply(a.output, ["x", "y", "z"], q.tolist(), tri.tolist(),
                      [f"analysis.py sphere-geometry: {os.path.basename(a.input)} projected radially onto r = {rbar:.9g}"])
    json.dump(out, sys.stdout, indent=1)
    sys.stdout.write("\n")


def cmd_fig3(a):
    """Collect section 8's reports into one JSON for plot.py fig3 and summarize.py."""
    def rd(name):
        with open(os.path.join(a.dir, name)) as f:
            return json.load(f)
    out = {}
    for m in ("laplacian", "mcf"):
        its = list(range(0, a.iterations + 1, 5))
        r = {"iterations": its, "radius_spread": [], "inverse_radius_sigma_global": []}
        for c in ("goldfeather", "meyer"):
            sm = rd(f"{m}_pre_{c}.json")
            rec = dict(zip(sm["iterations"], range(len(sm["iterations"]))))
            r[c] = {"sigma_1": [sm["sigma"][rec[k]][sm["levels"].index(1)] for k in its],
                    "sigma_global": [sm["sigma_global"][rec[k]] for k in its],
                    "sigma_1_projected": [], "sigma_global_projected": []}
        for k in its:
            g = rd(f"{m}_{k}_geometry.json")
            r["radius_spread"].append(g["radius_spread"])
            r["inverse_radius_sigma_global"].append(g["inverse_radius_sigma_global"])
            for c in ("goldfeather", "meyer"):
                p = rd(f"{m}_{k}_projected_{c}.json")
                r[c]["sigma_1_projected"].append(p["sigma"][p["levels"].index(1)])
                r[c]["sigma_global_projected"].append(p["sigma_global"])
        out[m] = r
    json.dump(out, sys.stdout, indent=1)
    sys.stdout.write("\n")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    s = p.add_subparsers(dest="cmd", required=True)
    r = s.add_parser("ringnoise")
    r.add_argument("input")
    r.add_argument("--levels", default="1,2,5,10,20")
    r.set_defaults(func=cmd_ringnoise)
    g = s.add_parser("sphere-geometry")
    g.add_argument("input")
    g.add_argument("output")
    g.set_defaults(func=cmd_sphere_geometry)
    f = s.add_parser("fig3")
    f.add_argument("dir")
    f.add_argument("iterations", type=int)
    f.set_defaults(func=cmd_fig3)
    a = p.parse_args()
    a.func(a)


if __name__ == "__main__":
    main()
