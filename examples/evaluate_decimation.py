#!/usr/bin/env python3
"""Evaluate a mesh decimator with meshdiff: decimate meshes at several ratios,
compare each result with its original, write one CSV row per (mesh, ratio) and
plot the error against the face count.

The decimator is OpenMesh's command-line decimater from Debian (package
libopenmesh-apps: OpenMesh-commandlineDecimater) with the quadric error metric
and the normal-flipping check, "-M Q -M NF" (quadrics alone fold the surface
over: 6% of the diagonal Hausdorff distance on fandisk at ratio 0.5, against
0.0005% with NF; --modules Q shows it); the ratio is the share of vertices
kept, "-n RATIO". Any other decimator works the same way: replace decimate()
below by a function that writes the decimated mesh to a file.

Usage (from the repository root, after scripts/test.sh or scripts/run-example.sh):

    PYTHONPATH=build/python /usr/bin/python3 examples/evaluate_decimation.py \\
        --out out/decimation tests/data/fandisk.ply tests/data/sphere_irregular_3072.ply

Writes OUT/decimation.csv and OUT/decimation.png (and the decimated meshes in
OUT/meshes/). CSV columns:

    mesh, ratio, vertices, faces    the decimated mesh (ratio: share of vertices asked for)
    hausdorff                       symmetric Hausdorff distance, in the mesh's unit: the upper end of its
                                    certified interval (width 1e-4 of the value)
    hausdorff_relative              ... divided by the original's bounding-box diagonal
    mean, rms                       the larger of the forward and backward sample mean / RMS
                                    (forward: samples on the original), in the mesh's unit
    d_1, d_5, d_20, d_global        roughness distance d_L (eq. 10, k = 1e-4) at levels 1, 5, 20, global
    seconds                         time of the meshdiff comparison
"""
import argparse
import csv
import pathlib
import shutil
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")  # headless: no display needed
import matplotlib.pyplot as plt  # noqa: E402

try:
    import meshdiff  # noqa: E402
except ImportError:
    sys.exit("evaluate_decimation: cannot import meshdiff; run with PYTHONPATH=build/python "
             "(the build tree) or install it with cmake --install (see docs/python.md)")

DECIMATOR = "OpenMesh-commandlineDecimater"
LEVELS = [1, 5, 20]
COLUMNS = ["mesh", "ratio", "vertices", "faces", "hausdorff", "hausdorff_relative", "mean", "rms",
           "d_1", "d_5", "d_20", "d_global", "seconds"]


def decimate(decimator, modules, source, target, ratio):
    """Decimates source to about ratio x its vertices into target (an .off file)."""
    cmd = [decimator]
    for module in modules:
        cmd += ["-M", module]
    cmd += ["-n", str(ratio), "-i", str(source), "-o", str(target)]
    target.unlink(missing_ok=True)
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0 or not target.exists():
        raise RuntimeError(f"{' '.join(cmd)} failed ({result.returncode}): {result.stderr.strip()}")


def evaluate(meshes, ratios, out, decimator, modules, threads):
    out.mkdir(parents=True, exist_ok=True)
    (out / "meshes").mkdir(exist_ok=True)
    rows = []
    for source in meshes:
        name = source.stem
        for ratio in ratios:
            target = out / "meshes" / f"{name}_{ratio:g}.off"
            decimate(decimator, modules, source, target, ratio)
            t0 = time.perf_counter()
            r = meshdiff.compare_files(source, target, levels=LEVELS, threads=threads)
            seconds = time.perf_counter() - t0
            sd, rd = r["surface_distance"], r["roughness_distance"]
            d = dict(zip(rd["levels"], rd["distance"]))
            rows.append({
                "mesh": name,
                "ratio": ratio,
                "vertices": r["processed"]["mesh"]["vertices"],
                "faces": r["processed"]["mesh"]["faces"],
                "hausdorff": sd["hausdorff"]["upper"],
                "hausdorff_relative": sd["hausdorff"]["relative"]["upper"],
                "mean": max(sd["forward"]["mean"], sd["backward"]["mean"]),
                "rms": max(sd["forward"]["rms"], sd["backward"]["rms"]),
                "d_1": d[1], "d_5": d[5], "d_20": d[20], "d_global": rd["global"]["distance"],
                "seconds": round(seconds, 4),
            })
            print(f"{name} ratio {ratio:g}: {rows[-1]['faces']} faces, Hausdorff {sd['hausdorff']['upper']:.4g} "
                  f"({100 * sd['hausdorff']['relative']['upper']:.3g}% of the diagonal), d_1 {d[1]:.3f}", flush=True)
    with open(out / "decimation.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    plot(rows, out / "decimation.png")
    return rows


def plot(rows, path):
    """Relative Hausdorff and RMS distance, and d_1 and d_global, against the face count."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for name in dict.fromkeys(r["mesh"] for r in rows):
        mine = sorted((r for r in rows if r["mesh"] == name), key=lambda r: r["faces"])
        faces = [r["faces"] for r in mine]
        line, = left.plot(faces, [100 * r["hausdorff_relative"] for r in mine], "o-", label=f"{name} Hausdorff")
        diag = mine[0]["hausdorff"] / mine[0]["hausdorff_relative"]
        left.plot(faces, [100 * r["rms"] / diag for r in mine], "s--", color=line.get_color(),
                  label=f"{name} RMS")
        right.plot(faces, [r["d_1"] for r in mine], "o-", color=line.get_color(), label=f"{name} d_1")
        right.plot(faces, [r["d_global"] for r in mine], "s--", color=line.get_color(), label=f"{name} d_global")
    left.set(xscale="log", yscale="log", xlabel="faces after decimation",
             ylabel="distance, % of the original's bbox diagonal", title="Surface distance")
    right.set(xscale="log", xlabel="faces after decimation", ylabel="d_L (k = 1e-4)", title="Roughness distance")
    for ax in (left, right):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv=None):
    here = pathlib.Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("meshes", nargs="*", type=pathlib.Path,
                        default=[here / "tests/data/fandisk.ply", here / "tests/data/sphere_irregular_3072.ply"],
                        help="original meshes (default: fandisk and the irregular sphere of tests/data)")
    parser.add_argument("--ratios", default="0.5,0.25,0.1,0.05",
                        help="shares of vertices to keep, comma-separated (default: %(default)s)")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("out/decimation"),
                        help="output directory (default: %(default)s)")
    parser.add_argument("--decimator", default=DECIMATOR,
                        help="the OpenMesh command-line decimater (default: %(default)s, Debian libopenmesh-apps)")
    parser.add_argument("--modules", default="Q,NF",
                        help="decimater modules, comma-separated, each passed as -M (default: %(default)s)")
    parser.add_argument("--threads", type=int, default=0, help="meshdiff threads, 0: all cores")
    args = parser.parse_args(argv)
    ratios = [float(r) for r in args.ratios.split(",")]
    if not all(0.0 < r < 1.0 for r in ratios):
        parser.error("--ratios: each ratio must be in (0, 1)")
    decimator = shutil.which(args.decimator)
    if decimator is None:
        sys.exit(f"evaluate_decimation: {args.decimator} not found; on Debian: apt-get install libopenmesh-apps")
    evaluate(args.meshes, ratios, args.out, decimator, args.modules.split(","), args.threads)
    print(f"wrote {args.out / 'decimation.csv'} and {args.out / 'decimation.png'}")


if __name__ == "__main__":
    main()
