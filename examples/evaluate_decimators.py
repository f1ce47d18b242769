#!/usr/bin/env python3
"""Evaluate mesh decimators with meshdiff: decimate meshes at several ratios with
each decimator, compare each result with its original, print a table, write one
CSV row per (mesh, decimator, ratio) and plot the error against the face count.

Decimators (both from Debian):
  open3d    Open3D's quadric error decimation (python3-open3d):
            TriangleMesh.simplify_quadric_decimation(ratio x faces)
  openmesh  OpenMesh's command-line decimater (libopenmesh-apps) with quadrics and
            the normal-flipping check, "-M Q -M NF", keeping ratio x vertices
Add another by writing a function that takes (V, F, ratio) and returns a mesh
object or (V, F), and adding it to DECIMATORS.

The table ranks the decimations of each mesh and ratio by the certified Hausdorff
distance (the upper end of its interval); the RMS distance and the roughness
distance at the metric level of radius 0.2 (on the unit-scaled mesh) are shown
beside it. Ring-level d_L is not used: across resolutions the same ring spans
different patches of surface, and a decimated mesh always looks rougher at ring
L (README, "rings or radii"); a radius is the same patch on both meshes.

Usage (after `pip install --no-build-isolation .`, docs/python.md):

    python3 examples/evaluate_decimators.py --out out/decimators \\
        tests/data/fandisk.ply tests/data/sphere_irregular_3072.ply

Writes OUT/decimators.csv and OUT/decimators.png. CSV columns:

    mesh, decimator, ratio, vertices, faces   the decimated mesh (ratio: share asked for)
    hausdorff            symmetric Hausdorff distance in the mesh's unit: the upper end of its
                         certified interval (width 1e-4 of the value)
    hausdorff_relative   ... divided by the original's bounding-box diagonal
    rms                  the larger of the forward and backward RMS distance, in the mesh's unit
    d_r0.2               roughness distance at radius 0.2 (eq. 10, k = 1e-4; METHOD.md 5a)
    seconds              time of the decimation plus the comparison
"""
import argparse
import csv
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time
import warnings
from typing import Any, Callable, Dict, List, Sequence, Tuple

import matplotlib

matplotlib.use("Agg")  # headless: no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import open3d as o3d  # noqa: E402

import meshdiff  # noqa: E402

# Decimations leave the reports' warnings (non-manifold edges, outlier-dominated levels) in each result's
# "warnings"; shown once each here rather than for every comparison.
warnings.simplefilter("once", meshdiff.MeshWarning)

COLUMNS = ["mesh", "decimator", "ratio", "vertices", "faces", "hausdorff", "hausdorff_relative", "rms", "d_r0.2",
           "seconds"]
RADIUS = 0.2  # the metric level reported beside the distances
Row = Dict[str, Any]


def decimate_open3d(V: np.ndarray, F: np.ndarray, ratio: float) -> Any:
    """Open3D's quadric decimation to ratio x the faces: an open3d TriangleMesh."""
    mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F))
    out = mesh.simplify_quadric_decimation(target_number_of_triangles=max(4, int(ratio * len(F))))
    return out.remove_unreferenced_vertices()


def decimate_openmesh(V: np.ndarray, F: np.ndarray, ratio: float) -> Tuple[np.ndarray, np.ndarray]:
    """OpenMesh's decimater (-M Q -M NF) to ratio x the vertices, through OFF files."""
    tool = shutil.which("OpenMesh-commandlineDecimater")
    if tool is None:
        sys.exit("evaluate_decimators: OpenMesh-commandlineDecimater not found; apt-get install libopenmesh-apps")
    with tempfile.TemporaryDirectory() as d:
        source, target = pathlib.Path(d) / "in.off", pathlib.Path(d) / "out.off"
        with open(source, "w") as f:
            f.write(f"OFF\n{len(V)} {len(F)} 0\n")
            np.savetxt(f, V, fmt="%.17g")
            np.savetxt(f, np.column_stack([np.full(len(F), 3), F]), fmt="%d")
        cmd = [tool, "-M", "Q", "-M", "NF", "-n", str(ratio), "-i", str(source), "-o", str(target)]
        result = subprocess.run(cmd, capture_output=True, text=True)
        if result.returncode != 0 or not target.exists():
            raise RuntimeError(f"{' '.join(cmd)} failed ({result.returncode}): {result.stderr.strip()}")
        Vd, Fd = meshdiff.read_mesh(target)
        return Vd, Fd


DECIMATORS: Dict[str, Callable[[np.ndarray, np.ndarray, float], Any]] = {
    "open3d": decimate_open3d,
    "openmesh": decimate_openmesh,
}


def evaluate(meshes: Sequence[pathlib.Path], ratios: Sequence[float], decimators: Sequence[str],
             threads: int) -> List[Row]:
    rows: List[Row] = []
    for source in meshes:
        V, F = meshdiff.read_mesh(source)
        for ratio in ratios:
            for name in decimators:
                t0 = time.perf_counter()
                decimated = DECIMATORS[name](V, F, ratio)
                args = decimated if isinstance(decimated, tuple) else (decimated,)
                r = meshdiff.compare(V, F, *args, levels=[1], radii=[RADIUS], threads=threads)
                sd, rd = r["surface_distance"], r["roughness_distance"]
                rows.append({
                    "mesh": source.stem, "decimator": name, "ratio": ratio,
                    "vertices": r["processed"]["mesh"]["vertices"], "faces": r["processed"]["mesh"]["faces"],
                    "hausdorff": sd["hausdorff"]["upper"], "hausdorff_relative": sd["hausdorff"]["relative"]["upper"],
                    "rms": max(sd["forward"]["rms"], sd["backward"]["rms"]), "d_r0.2": rd["distance_radii"][0],
                    "seconds": round(time.perf_counter() - t0, 4),
                })
    return rows


def print_table(rows: Sequence[Row]) -> None:
    """Per mesh and ratio, the decimators from the smallest certified Hausdorff distance up."""
    print(f"{'mesh':<24} {'ratio':>6} {'rank':>4} {'decimator':<9} {'faces':>7} {'Hausdorff %diag':>15} "
          f"{'RMS %diag':>10} {'d_r0.2':>9}")
    groups: Dict[Tuple[str, float], List[Row]] = {}
    for row in rows:
        groups.setdefault((row["mesh"], row["ratio"]), []).append(row)
    for (mesh, ratio), group in groups.items():
        for rank, row in enumerate(sorted(group, key=lambda r: r["hausdorff"]), 1):
            diag = row["hausdorff"] / row["hausdorff_relative"] if row["hausdorff_relative"] else 1.0
            print(f"{mesh:<24} {ratio:>6g} {rank:>4} {row['decimator']:<9} {row['faces']:>7} "
                  f"{100 * row['hausdorff_relative']:>15.4g} {100 * row['rms'] / diag:>10.4g} "
                  f"{row['d_r0.2']:>9.3f}")


def plot(rows: Sequence[Row], path: pathlib.Path) -> None:
    """Relative Hausdorff distance against the face count, one line per mesh and decimator."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for key in dict.fromkeys((r["mesh"], r["decimator"]) for r in rows):
        mine = sorted((r for r in rows if (r["mesh"], r["decimator"]) == key), key=lambda r: r["faces"])
        ax.plot([r["faces"] for r in mine], [100 * r["hausdorff_relative"] for r in mine], "o-",
                label=f"{key[0]}, {key[1]}")
    ax.set(xscale="log", yscale="log", xlabel="faces after decimation",
           ylabel="certified Hausdorff, % of the bbox diagonal", title="Decimators against their originals")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv: Sequence[str] = ()) -> None:
    here = pathlib.Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("meshes", nargs="*", type=pathlib.Path,
                        default=[here / "tests/data/fandisk.ply", here / "tests/data/sphere_irregular_3072.ply"],
                        help="original meshes (default: fandisk and the irregular sphere of tests/data)")
    parser.add_argument("--ratios", default="0.5,0.25,0.1,0.05",
                        help="shares to keep, comma-separated (default: %(default)s)")
    parser.add_argument("--decimators", default=",".join(DECIMATORS),
                        help="comma-separated, of " + ", ".join(DECIMATORS) + " (default: all)")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("out/decimators"),
                        help="output directory (default: %(default)s)")
    parser.add_argument("--threads", type=int, default=0, help="meshdiff threads, 0: all cores")
    args = parser.parse_args(list(argv) or None)
    ratios = [float(r) for r in args.ratios.split(",")]
    if not all(0.0 < r < 1.0 for r in ratios):
        parser.error("--ratios: each ratio must be in (0, 1)")
    decimators = args.decimators.split(",")
    unknown = [d for d in decimators if d not in DECIMATORS]
    if unknown:
        parser.error(f"--decimators: unknown {', '.join(unknown)}")
    rows = evaluate(args.meshes, ratios, decimators, args.threads)
    print_table(rows)
    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "decimators.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    plot(rows, args.out / "decimators.png")
    print(f"wrote {args.out / 'decimators.csv'} and {args.out / 'decimators.png'}")


if __name__ == "__main__":
    main()
