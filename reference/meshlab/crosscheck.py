#!/usr/bin/env python3
"""Cross-check meshdiff's Metro-style surface distance against MeshLab's
"Hausdorff Distance" filter (meshlabserver, headless under xvfb-run).

For each pair (A, B) and each direction (samples on S, distances to T) it runs:
  1. MeshLab: `xvfb-run -a meshlabserver -i T S -s hd.mlx -l log`, where hd.mlx
     first scales both layers by SCALE about the origin ("Transform: Scale,
     Normalize", frozen; MeshLab's log prints only 6 decimals, so this keeps
     about 9 significant digits of small distances), removes the unreferenced
     vertices of S (the current layer; meshdiff drops them when reading, and
     MeshLab would otherwise sample them) and then runs "Hausdorff Distance"
     on SampledMesh = S, TargetMesh = T with SampleNum = N, the sample kinds of
     the mode, and MaxDist set to 1e9 (absolute) so that no sample is dropped
     (the default, 5% of the diagonal, silently drops far samples). MeshLab's
     numbers are divided by SCALE. MeshLab's filter time is estimated as the
     wall time of this run minus the wall time of a run of the same script
     without the Hausdorff step (start-up, loading, scaling).
  2. meshdiff, the command users run: `meshdiff compare S T --no-roughness
     --samples M --json -` (plus the sample-kind flags of the mode), where M is
     the number of samples MeshLab reports, so that both tools use the same
     total sample count; the forward direction (samples on S, distances to T)
     is compared. The time is measured separately with
     `meshdiff_bench_distance --pair S T --one-sided --samples M` (index build +
     sampling + queries + statistics of that one direction, files already
     loaded, as MeshLab's filter time), which must give the same numbers: the
     script checks that it does.

MeshLab's sample count is not N: its filter takes min(N, #vertices) vertex
samples, N edge samples and N Monte Carlo face samples (MeshLab 2020.09).
meshdiff splits the same total as Metro does (all vertices, then edges at
sqrt of the face density, then similar-triangles face samples).

Only the Python standard library is used. Usage:
  reference/meshlab/crosscheck.py --meshdiff build/meshdiff --bench build/meshdiff_bench_distance \
      [--data /work/shared/data/meshes] [--samplenum 1000000] \
      [--igea-decimated /tmp/igea_dec10.ply] [--json results.json]
"""
import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

SCALE_FILTER = """ <filter name="Transform: Scale, Normalize">
  <Param type="RichFloat" value="{s}" name="axisX"/>
  <Param type="RichFloat" value="{s}" name="axisY"/>
  <Param type="RichFloat" value="{s}" name="axisZ"/>
  <Param type="RichBool" value="true" name="uniformFlag"/>
  <Param type="RichEnum" value="0" enum_val0="origin" enum_val1="barycenter" enum_val2="custom point" enum_cardinality="3" name="scaleCenter"/>
  <Param type="RichPoint3f" x="0" y="0" z="0" name="customCenter"/>
  <Param type="RichBool" value="false" name="unitFlag"/>
  <Param type="RichBool" value="true" name="Freeze"/>
  <Param type="RichBool" value="true" name="allLayers"/>
 </filter>
"""

# Applies to the current layer, which is the last one loaded: the sampled mesh.
UNREFERENCED_FILTER = """ <filter name="Remove Unreferenced Vertices"/>
"""

HAUSDORFF_FILTER = """ <filter name="Hausdorff Distance">
  <Param type="RichMesh" value="1" name="SampledMesh"/>
  <Param type="RichMesh" value="0" name="TargetMesh"/>
  <Param type="RichBool" value="false" name="SaveSample"/>
  <Param type="RichBool" value="{v}" name="SampleVert"/>
  <Param type="RichBool" value="{e}" name="SampleEdge"/>
  <Param type="RichBool" value="false" name="SampleFauxEdge"/>
  <Param type="RichBool" value="{f}" name="SampleFace"/>
  <Param type="RichInt" value="{n}" name="SampleNum"/>
  <Param type="RichAbsPerc" value="1e9" min="0" max="1e9" name="MaxDist"/>
 </filter>
"""

PAIRS = [
    ("bunny.ply", "bunny_res2.ply"),
    ("bunny_closed.ply", "bunny_adaptive.ply"),
    ("face_neutral.ply", "face_smile.ply"),
]


# Sample kinds per mode: (vertices, edges, faces).
# faces-mc: meshdiff's Monte Carlo face scheme (MeshLab's face samples are
# always Monte Carlo).
MODES = {"all": (True, True, True), "vertices": (True, False, False), "faces": (False, False, True),
         "faces-mc": (False, False, True)}


def write_script(path, scale, samplenum, mode="all"):
    v, e, fc = ("true" if x else "false" for x in MODES[mode])
    with open(path, "w") as f:
        f.write("<!DOCTYPE FilterScript>\n<FilterScript>\n")
        f.write(SCALE_FILTER.format(s=scale))
        f.write(UNREFERENCED_FILTER)
        if samplenum is not None:
            f.write(HAUSDORFF_FILTER.format(n=samplenum, v=v, e=e, f=fc))
        f.write("</FilterScript>\n")


def run_meshlab(sampled, target, script, log):
    if os.path.exists(log):
        os.remove(log)
    # The sampled mesh is loaded last, so that it is the current layer.
    cmd = ["xvfb-run", "-a", "meshlabserver", "-i", target, sampled, "-s", script, "-l", log]
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - t0
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (c1.ru_utime + c1.ru_stime) - (c0.ru_utime + c0.ru_stime)
    if p.returncode != 0:
        raise RuntimeError("meshlabserver failed ({}): {}".format(p.returncode, (p.stdout + p.stderr)[-2000:]))
    text = open(log).read() if os.path.exists(log) else ""
    return wall, cpu, text, " ".join(cmd)


def parse_meshlab(text, scale):
    m = re.search(r"Sampled (\d+) pts", text)
    v = re.search(r"min : ([-\d.e]+)\s+max ([-\d.e]+)\s+mean : ([-\d.e]+)\s+RMS : ([-\d.e]+)", text)
    d = re.search(r"BBox Diag \(([\d.e+-]+)\)", text)
    if not (m and v and d):
        raise RuntimeError("cannot parse MeshLab log:\n" + text)
    vals = [float(x) / scale for x in v.groups()]
    return {"samples": int(m.group(1)), "min": vals[0], "max": vals[1], "mean": vals[2], "rms": vals[3],
            "diag": float(d.group(1)) / scale}


def run_meshdiff(bench, sampled, target, samples, runs, mode="all", threads=None):
    cmd = [bench, "--pair", sampled, target, "--one-sided", "--samples", str(samples), "--runs", str(runs)]
    flags = dict(zip(("--no-vertex-samples", "--no-edge-samples", "--no-face-samples"), MODES[mode]))
    cmd += [k for k, on in flags.items() if not on]
    if mode == "faces-mc":
        cmd += ["--face-sampling", "montecarlo"]
    if threads:
        cmd += ["--threads", str(threads)]
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        raise RuntimeError("meshdiff failed: " + p.stderr)
    fields = p.stdout.split()
    r = {fields[i]: fields[i + 1] for i in range(1, len(fields) - 1, 2)}
    return {"samples": int(r["samples"]), "n_vertex": int(r["v"]), "n_edge": int(r["e"]), "n_face": int(r["f"]),
            "min": float(r["min"]), "max": float(r["max"]), "mean": float(r["mean"]), "rms": float(r["rms"]),
            "time_s": float(r["time_s"]), "cpu_s": float(r["cpu_s"]), "threads": int(r["threads"]), "process_wall_s": wall,
            "command": " ".join(cmd)}


def run_meshdiff_cli(meshdiff, sampled, target, samples, mode="all"):
    """The forward distance (samples on `sampled`) from `meshdiff compare`."""
    cmd = [meshdiff, "compare", sampled, target, "--no-roughness", "--samples", str(samples), "--json", "-"]
    flags = dict(zip(("--no-vertex-samples", "--no-edge-samples", "--no-face-samples"), MODES[mode]))
    cmd += [k for k, on in flags.items() if not on]
    if mode == "faces-mc":
        cmd += ["--face-sampling", "montecarlo"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("meshdiff compare failed: " + p.stderr)
    fw = json.loads(p.stdout)["surface_distance"]["forward"]
    kinds = fw["samples_by_kind"]
    return {"samples": fw["samples"], "n_vertex": kinds["vertex"], "n_edge": kinds["edge"], "n_face": kinds["face"],
            "min": fw["min"], "max": fw["max"], "mean": fw["mean"], "rms": fw["rms"], "command": " ".join(cmd)}


def one_direction(args, tmp, sampled, target, samplenum, mode="all", single_thread=False):
    hd = os.path.join(tmp, "hd.mlx")
    base = os.path.join(tmp, "base.mlx")
    write_script(hd, args.scale, samplenum, mode)
    write_script(base, args.scale, None)
    log = os.path.join(tmp, "log.txt")
    wall_base, cpu_base, _, _ = run_meshlab(sampled, target, base, os.path.join(tmp, "base_log.txt"))
    wall, cpu, text, cmd = run_meshlab(sampled, target, hd, log)
    ml = parse_meshlab(text, args.scale)
    ml.update({"wall_s": wall, "baseline_wall_s": wall_base, "filter_s": max(0.0, wall - wall_base),
               "cpu_s": cpu, "baseline_cpu_s": cpu_base, "filter_cpu_s": max(0.0, cpu - cpu_base),
               "load1": os.getloadavg()[0],
               "command": cmd, "script": open(hd).read()})
    md = run_meshdiff_cli(args.meshdiff, sampled, target, ml["samples"], mode)
    timing = run_meshdiff(args.bench, sampled, target, ml["samples"], args.runs, mode)
    # The timing program runs the same library code: its numbers must be the CLI's.
    for k in ("samples", "n_vertex", "n_edge", "n_face", "max"):
        if timing[k] != md[k] and abs(timing[k] - md[k]) > 1e-9 * max(abs(md[k]), 1e-300):
            raise RuntimeError(f"meshdiff CLI and timing program disagree on {k}: {md[k]} vs {timing[k]}")
    md.update({"time_s": timing["time_s"], "cpu_s": timing["cpu_s"], "threads": timing["threads"],
               "process_wall_s": timing["process_wall_s"], "timing_command": timing["command"]})
    r = {"sampled": os.path.basename(sampled), "target": os.path.basename(target), "mode": mode, "meshlab": ml,
         "meshdiff": md}
    if single_thread:
        r["meshdiff_1thread"] = run_meshdiff(args.bench, sampled, target, ml["samples"], args.runs, mode, 1)
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--meshdiff", required=True, help="path of the meshdiff tool (the numbers)")
    ap.add_argument("--bench", required=True, help="path of meshdiff_bench_distance (the timing)")
    ap.add_argument("--data", default="/work/shared/data/meshes")
    ap.add_argument("--samplenum", type=int, default=1000000, help="MeshLab SampleNum")
    ap.add_argument("--scale", type=float, default=1000.0, help="scale applied inside MeshLab")
    ap.add_argument("--runs", type=int, default=3, help="meshdiff runs (median time)")
    ap.add_argument("--igea-decimated", help="igea decimation for the timing case (see README.md)")
    ap.add_argument("--igea-samplenum", type=int, default=1276258,
                    help="MeshLab SampleNum for igea (134345 vertices + 2 x this = 10 x #faces of igea)")
    ap.add_argument("--modes", default="all,vertices,faces,faces-mc",
                    help="sample kinds to compare: all (V+E+F), vertices (vertices only), faces (faces only), "
                    "faces-mc (faces only, meshdiff's Monte Carlo scheme); empty: only the igea timing case")
    ap.add_argument("--json", help="write all results here")
    args = ap.parse_args()

    results = []
    with tempfile.TemporaryDirectory() as tmp:
        for mode in [m for m in args.modes.split(",") if m]:
            for a, b in PAIRS:
                pa, pb = os.path.join(args.data, a), os.path.join(args.data, b)
                for s, t in ((pa, pb), (pb, pa)):
                    r = one_direction(args, tmp, s, t, args.samplenum, mode)
                    results.append(r)
                    print(json.dumps(r_summary(r)), flush=True)
        if args.igea_decimated:
            igea = os.path.join(args.data, "igea.ply")
            for s, t in ((igea, args.igea_decimated), (args.igea_decimated, igea)):
                r = one_direction(args, tmp, s, t, args.igea_samplenum, "all", single_thread=True)
                r["timing_case"] = True
                results.append(r)
                print(json.dumps(r_summary(r)), flush=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    print_table(results)


def r_summary(r):
    ml, md = r["meshlab"], r["meshdiff"]
    return {"dir": r["sampled"] + " -> " + r["target"], "mode": r["mode"], "n": ml["samples"],
            "meshlab": [ml["max"], ml["mean"], ml["rms"], round(ml["filter_s"], 3)],
            "meshdiff": [md["max"], md["mean"], md["rms"], round(md["time_s"], 3)]}


def print_table(results):
    print("\n| samples on -> distance to | kinds | samples | tool | max | mean | RMS | time (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for r in results:
        ml, md = r["meshlab"], r["meshdiff"]
        d = "{} -> {}".format(r["sampled"], r["target"])
        print("| {} | {} | {} | MeshLab | {:.7g} | {:.7g} | {:.7g} | {:.2f} filter ({:.2f} whole run) |".format(
            d, r["mode"], ml["samples"], ml["max"], ml["mean"], ml["rms"], ml["filter_s"], ml["wall_s"]))
        rows = [("meshdiff", md)] + ([("meshdiff", r["meshdiff_1thread"])] if "meshdiff_1thread" in r else [])
        for name, m in rows:
            print("| | | {} | {} | {:.7g} | {:.7g} | {:.7g} | {:.2f} ({} thread(s), median of runs) |".format(
                m["samples"], name, m["max"], m["mean"], m["rms"], m["time_s"], m["threads"]))


if __name__ == "__main__":
    sys.exit(main())
