#!/usr/bin/env python3
"""Which measure ranks a decimation series? (issue: roughness that ranks decimations)

Decimates meshes at 50/25/10/5 % of their vertices with two decimators from Debian (OpenMesh's
command-line decimater with quadrics and the normal-flipping check, package libopenmesh-apps; Open3D's
quadric decimation, package python3-open3d), compares every decimation with its original by
`meshdiff ORIGINAL DECIMATED --json` under each normalisation, and says for each measure whether it grows
strictly with the decimation ("monotone"). Writes OUT/decimation_study.csv (one row per comparison) and
OUT/decimation_study.md (the verdict table).

Usage (from the repository root, after the build):
    /usr/bin/python3 reference/decimation_study.py --meshdiff build/meshdiff --out reference/out/decimation \\
        tests/data/fandisk.ply ../shared/data/meshes/bunny_closed.ply ...
"""
import argparse
import csv
import json
import os
import subprocess
import sys

RATIOS = [0.5, 0.25, 0.1, 0.05]
LEVELS = [1, 2, 5]


def decimate_openmesh(src, dst, ratio):
    subprocess.run(["OpenMesh-commandlineDecimater", "-i", src, "-o", dst, "-M", "Q", "-M", "NF", "-n", str(ratio)],
                   check=True, capture_output=True)


def decimate_open3d(src, dst, ratio):
    import open3d as o3d
    m = o3d.io.read_triangle_mesh(src)
    target = max(4, int(round(len(m.triangles) * ratio)))
    d = m.simplify_quadric_decimation(target_number_of_triangles=target)
    d.remove_unreferenced_vertices()
    o3d.io.write_triangle_mesh(dst, d, write_ascii=False, write_vertex_normals=False, write_vertex_colors=False)


DECIMATORS = {"openmesh": decimate_openmesh, "open3d": decimate_open3d}


def measures(report):
    """The measures of one comparison, by name (None where there is no number)."""
    out = {}
    sd = report["surface_distance"]
    if sd:  # not with --no-distance
        out["hausdorff"] = sd["hausdorff"]["upper"] if "upper" in sd["hausdorff"] else sd["hausdorff"]["value"]
        out["rms_distance"] = max(sd["forward"]["rms"], sd["backward"]["rms"])
    rd = report["roughness_distance"]
    for L in LEVELS:
        i = rd["levels"].index(L)
        out[f"d_{L}"] = rd["distance"][i]
        out[f"local_{L}"] = rd["local"]["rms"][i]
    out["d_G"] = rd["global"]["distance"]
    out["local_G"] = rd["local"]["global"]
    for r, d, l in zip(rd.get("radii", []), rd.get("distance_radii", []), rd["local"].get("rms_radii", [])):
        out[f"d_r{r:g}"] = d
        out[f"local_r{r:g}"] = l
    return out


def monotone(values):
    return all(v is not None for v in values) and all(b > a for a, b in zip(values, values[1:]))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--meshdiff", default="build/meshdiff")
    ap.add_argument("--out", default="reference/out/decimation")
    ap.add_argument("--decimators", default="openmesh,open3d")
    ap.add_argument("--normalize", default="paper,area,original")
    ap.add_argument("--radii", default="0.05,0.1,0.2")
    ap.add_argument("--ratios", default=",".join(f"{r:g}" for r in RATIOS),
                    help="shares of the vertices kept, largest first (default: %(default)s)")
    ap.add_argument("--extra", default="", help="further options of every comparison, e.g. '--trim 0.01'")
    ap.add_argument("--tag", default="", help="a name for this run's JSON files (with --extra)")
    args = ap.parse_args()
    ratios = [float(r) for r in args.ratios.split(",")]
    os.makedirs(args.out, exist_ok=True)
    rows = []
    series = {}  # (mesh, decimator, normalize) -> [measures per ratio]
    for mesh in args.meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        for dec in args.decimators.split(","):
            for ratio in ratios:
                dst = os.path.join(args.out, f"{name}_{dec}_{ratio:g}.ply" if dec == "open3d" else
                                   f"{name}_{dec}_{ratio:g}.off")
                if not os.path.exists(dst):
                    DECIMATORS[dec](mesh, dst, ratio)
                for norm in args.normalize.split(","):
                    js = os.path.join(args.out, f"{name}_{dec}_{ratio:g}_{norm}{args.tag}.json")
                    cmd = [args.meshdiff, mesh, dst, "--normalize", norm, "--radii", args.radii, "--json", js,
                           *args.extra.split()]
                    subprocess.run(cmd, check=True, capture_output=True)
                    with open(js) as f:
                        m = measures(json.load(f))
                    rows.append(dict(mesh=name, decimator=dec, ratio=ratio, normalize=norm, **m))
                    series.setdefault((name, dec, norm), []).append(m)
    keys = list(rows[0].keys())
    with open(os.path.join(args.out, f"decimation_study{args.tag}.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    names = [k for k in keys if k not in ("mesh", "decimator", "ratio", "normalize")]
    lines = ["| measure | " + " | ".join(f"{n} ({len([s for s in series if s[2] == n])} series)"
                                         for n in args.normalize.split(",")) + " |",
             "|---|" + "---|" * len(args.normalize.split(","))]
    for measure in names:
        cells = []
        for norm in args.normalize.split(","):
            ss = [v for k, v in series.items() if k[2] == norm]
            good = sum(monotone([m.get(measure) for m in s]) for s in ss)
            cells.append(f"{good}/{len(ss)}")
        lines.append(f"| {measure} | " + " | ".join(cells) + " |")
    table = "\n".join(lines)
    # The series on which a local measure does not grow, with its values from the finest to the coarsest ratio.
    failing = []
    for measure in [n for n in names if n.startswith("local_")]:
        for (name, dec, norm), s in series.items():
            values = [m.get(measure) for m in s]
            if not monotone(values):
                failing.append(f"- {measure}, {name}/{dec}" + (f" ({norm})" if len(args.normalize.split(",")) > 1
                                                                else "") + ": "
                               + " -> ".join("-" if v is None else f"{v:.4g}" for v in values))
    failures = ("\n\nSeries on which a local measure does not grow (values at ratios " + ", ".join(f"{r:g}" for r in ratios)
                + "):\n\n" + ("\n".join(failing) if failing else "none")) if any(n.startswith("local_") for n in names) else ""
    with open(os.path.join(args.out, f"decimation_study{args.tag}.md"), "w") as f:
        f.write(f"Series whose measure grows strictly from {100 * ratios[0]:g} % to {100 * ratios[-1]:g} % kept (ratios "
                + ", ".join(f"{r:g}" for r in ratios) + "):\n\n" + table + failures + "\n")
    print(table + failures)


if __name__ == "__main__":
    sys.exit(main())
