#!/usr/bin/env python3
"""Print the Markdown tables of README.md from results.json (written by
crosscheck.py --json). Usage: reference/meshlab/make_tables.py [results.json]"""
import json
import os
import sys


def g(x):
    return "{:.7g}".format(x)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "results.json")
    results = json.load(open(path))
    titles = {
        "all": "Vertices + edges + faces (each tool's default mix)",
        "vertices": "Vertices only (the same points in both tools)",
        "faces": "Faces only: MeshLab Monte Carlo vs meshdiff similar triangles (default scheme)",
        "faces-mc": "Faces only: MeshLab Monte Carlo vs meshdiff Monte Carlo (--face-sampling montecarlo, seed 1)",
    }
    for mode, title in titles.items():
        rows = [r for r in results if r["mode"] == mode and not r.get("timing_case")]
        if not rows:
            continue
        print("\n#### {}\n".format(title))
        print("| samples on -> distance to | samples ML / md | max ML | max md | mean ML | mean md | mean md/ML - 1 "
              "| RMS ML | RMS md | ML filter CPU s | md CPU s (wall s, 2 thr) |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            ml, md = r["meshlab"], r["meshdiff"]
            print("| {} -> {} | {} / {} | {} | {} | {} | {} | {:+.2%} | {} | {} | {:.2f} | {:.2f} ({:.2f}) |".format(
                r["sampled"], r["target"], ml["samples"], md["samples"], g(ml["max"]), g(md["max"]), g(ml["mean"]),
                g(md["mean"]), md["mean"] / ml["mean"] - 1, g(ml["rms"]), g(md["rms"]), ml.get("filter_cpu_s", -1),
                md.get("cpu_s", -1), md["time_s"]))
    rows = [r for r in results if r.get("timing_case")]
    if rows:
        print("\n#### Timing: igea.ply vs its 10% decimation, equal sample counts\n")
        print("| samples on -> distance to | samples ML / md | max ML | max md | mean ML | mean md | RMS ML | RMS md "
              "| MeshLab filter: wall s (CPU s) | meshdiff 2 threads: wall s (CPU s) | meshdiff 1 thread: wall s (CPU s) "
              "| load (1 min) |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
        tot = [0.0] * 6
        for r in rows:
            ml, md, m1 = r["meshlab"], r["meshdiff"], r["meshdiff_1thread"]
            t = [ml["filter_s"], ml.get("filter_cpu_s", -1), md["time_s"], md.get("cpu_s", -1), m1["time_s"],
                 m1.get("cpu_s", -1)]
            tot = [a + b for a, b in zip(tot, t)]
            print("| {} -> {} | {} / {} | {} | {} | {} | {} | {} | {} | {:.2f} ({:.2f}) | {:.2f} ({:.2f}) | {:.2f} ({:.2f}) "
                  "| {:.1f} |".format(r["sampled"], r["target"], ml["samples"], md["samples"], g(ml["max"]),
                                      g(md["max"]), g(ml["mean"]), g(md["mean"]), g(ml["rms"]), g(md["rms"]), *t,
                                      ml.get("load1", -1)))
        print("| both directions | | | | | | | | {:.2f} ({:.2f}) | {:.2f} ({:.2f}) | {:.2f} ({:.2f}) | |".format(*tot))
        print("\nSpeed-up of meshdiff over MeshLab, both directions: {:.1f}x in wall time with 2 threads, "
              "{:.1f}x with 1 thread; {:.1f}x in CPU time (1 thread).".format(tot[0] / tot[2], tot[0] / tot[4],
                                                                              tot[1] / tot[5]))


if __name__ == "__main__":
    main()
