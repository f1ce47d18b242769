#!/usr/bin/env python3
"""Issue 30's anchor ratios: meshdiff's surface distance per sample against MeshLab's "Hausdorff Distance" filter
and Open3D's closest-point queries, on igea and its 10 % decimation, in one run (old and new binaries alternately).

meshdiff: `meshdiff IGEA DEC --no-roughness --hausdorff sampled --json J`, both directions at the default budget
(about 2.1M samples each on this pair); its time per sample is the process's wall time (median of RUNS) over the
samples of both directions. It includes reading both files, the topology reports and the two index builds, so the
ratios below are lower bounds of the query speed-up.

MeshLab (when `meshlabserver` and `xvfb-run` are there): the filter on the forward direction (samples on igea,
distances to the decimation) with SampleNum = 1,000,000 (it takes min(N, #vertices) vertex, N edge and N face
samples), timed as in reference/meshlab/crosscheck.py: the run's wall time minus that of the same script without
the filter (start-up, loading); per sample over the samples it reports.

Open3D (when `import open3d` works): `RaycastingScene` of the target and `compute_closest_points` of as many points
as meshdiff samples in each direction (uniform on the sampled mesh, made beforehand and not timed); the scene's
build is timed, as meshdiff's index build is.

Ratios: anchor time per sample / meshdiff's, for each binary (issue 30: >= 10x MeshLab, >= 5x Open3D).

With --queries-new (and --queries-old), meshdiff's stages are also timed alone by meshdiff_bench_queries (the
library's index builds and queries on the same samples, made beforehand and not timed), and the anchors' ratios
printed against them too: the queries alone, and the index builds with the queries (what Open3D is charged). The
whole-process ratios above stay the measure of record; these say how much of the gap is the queries'.

  bench/anchors.py --new build/meshdiff [--old OLD/meshdiff] [--runs 5] [--meshes ../shared/data/meshes]
                   [--decimated /tmp/meshdiff-targets/igea_dec10.ply]
                   [--queries-new build/meshdiff_bench_queries [--queries-old OLD/meshdiff_bench_queries]]
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "reference", "meshlab"))


def time_meshdiff(binary, igea, dec, out):
    t0 = time.monotonic()
    subprocess.run([binary, igea, dec, "--no-roughness", "--hausdorff", "sampled", "--json", out], check=True,
                   stdout=subprocess.DEVNULL)
    wall = time.monotonic() - t0
    with open(out) as f:
        sd = json.load(f)["surface_distance"]
    return wall, sd["forward"]["samples"], sd["backward"]["samples"]


def stage_times(bench, igea, dec, runs):
    """meshdiff_bench_queries' last line: seconds per sample of the queries alone and of the index builds with
    them, both directions (medians of `runs`)."""
    out = subprocess.run([bench, "--runs", str(runs), igea, dec], check=True, capture_output=True, text=True).stdout
    m = re.search(r"queries alone ([0-9.]+) ns, index builds and queries ([0-9.]+) ns", out)
    if not m:
        raise SystemExit(f"{bench}: no per-sample line in its output:\n{out}")
    return {"queries alone": 1e-9 * float(m.group(1)), "index builds and queries": 1e-9 * float(m.group(2))}


def meshlab_per_sample(igea, dec, runs, tmp):
    if not (shutil.which("meshlabserver") and shutil.which("xvfb-run")):
        return None, "meshlabserver or xvfb-run not found"
    import crosscheck  # reference/meshlab: the filter script and its timing
    hd, base = os.path.join(tmp, "hd.mlx"), os.path.join(tmp, "base.mlx")
    crosscheck.write_script(hd, 1000.0, 1000000)
    crosscheck.write_script(base, 1000.0, None)
    per = []
    for _ in range(runs):
        wall_base = crosscheck.run_meshlab(igea, dec, base, os.path.join(tmp, "base.log"))[0]
        wall, _, text, _ = crosscheck.run_meshlab(igea, dec, hd, os.path.join(tmp, "hd.log"))
        samples = crosscheck.parse_meshlab(text, 1000.0)["samples"]
        per.append(max(0.0, wall - wall_base) / samples)
    return statistics.median(per), f"filter time over {samples} samples, median of {runs}"


def open3d_per_sample(igea, dec, n_forward, n_backward, runs):
    try:
        import numpy as np
        import open3d as o3d
    except ImportError as e:
        return None, f"open3d not importable ({e})"
    meshes = {p: o3d.io.read_triangle_mesh(p) for p in (igea, dec)}
    pairs = [(igea, dec, n_forward), (dec, igea, n_backward)]
    points = {s: np.asarray(meshes[s].sample_points_uniformly(number_of_points=n).points, dtype=np.float32)
              for s, _, n in pairs}
    per = []
    for _ in range(runs):
        t0 = time.monotonic()
        for s, t, _ in pairs:
            scene = o3d.t.geometry.RaycastingScene()
            scene.add_triangles(o3d.t.geometry.TriangleMesh.from_legacy(meshes[t]))
            r = scene.compute_closest_points(o3d.core.Tensor(points[s]))
            r["points"].numpy()
        per.append((time.monotonic() - t0) / (n_forward + n_backward))
    return statistics.median(per), f"{o3d.__version__}, scene build + queries, median of {runs}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--new", required=True)
    ap.add_argument("--old")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--meshes", default=os.path.join(HERE, "..", "..", "shared", "data", "meshes"))
    ap.add_argument("--decimated", default="/tmp/meshdiff-targets/igea_dec10.ply")
    ap.add_argument("--queries-new", help="meshdiff_bench_queries of the new build (stages timed alone)")
    ap.add_argument("--queries-old", help="meshdiff_bench_queries built against the old library")
    a = ap.parse_args()
    igea = os.path.join(a.meshes, "igea.ply")
    if not os.path.exists(a.decimated):
        subprocess.run(["OpenMesh-commandlineDecimater", "-M", "Q", "-M", "NF", "-n", "0.1", "-i", igea, "-o",
                        a.decimated], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    bins = [("old", a.old), ("new", a.new)] if a.old else [("new", a.new)]
    walls = {label: [] for label, _ in bins}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(a.runs):
            for label, b in bins:
                wall, nf, nb = time_meshdiff(b, igea, a.decimated, os.path.join(tmp, label + ".json"))
                walls[label].append(wall)
        per = {label: statistics.median(w) / (nf + nb) for label, w in walls.items()}
        stages = [(label, stage_times(q, igea, a.decimated, a.runs))
                  for label, q in (("old", a.queries_old), ("new", a.queries_new)) if q]
        anchors = [("MeshLab Hausdorff filter", *meshlab_per_sample(igea, a.decimated, a.runs, tmp)),
                   ("Open3D closest points", *open3d_per_sample(igea, a.decimated, nf, nb, a.runs))]
    print(f"igea ({igea}) vs its 10 % decimation; {nf} + {nb} samples; medians of {a.runs} runs")
    for label, _ in bins:
        print(f"meshdiff {label}: {statistics.median(walls[label]):.3f} s, {1e9 * per[label]:.1f} ns per sample")
    target = {"MeshLab Hausdorff filter": 10.0, "Open3D closest points": 5.0}
    for name, value, how in anchors:
        if value is None:
            print(f"{name}: skipped ({how})")
            continue
        ratios = ", ".join(f"{label} {value / per[label]:.1f}x" for label, _ in bins)
        print(f"{name}: {1e9 * value:.1f} ns per sample ({how}); meshdiff is faster by: {ratios} "
              f"(target >= {target[name]:g}x)")
        for label, t in stages:
            parts = ", ".join(f"{stage} ({1e9 * per:.1f} ns) {value / per:.1f}x" for stage, per in t.items())
            print(f"  against meshdiff {label}'s stages alone: {parts}")
    print(f"{os.cpu_count()} cores; load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}; "
          f"{time.strftime('%Y-%m-%dT%H:%M:%SZ', time.gmtime())}")


if __name__ == "__main__":
    main()
