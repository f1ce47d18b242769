#!/usr/bin/env python3
"""The relaxed numerical rule of issue 30, checked against stored outputs.

For every case of tests/data/tolerance/ (a bundled mesh and a curvature fit)
this runs `meshdiff profile MESH --curvature FIT --json --vertex-data` and
compares with the outputs stored there (made by the binary named in the
folder's README.md, before the change they guard):
  - deterministic: the JSON and the per-vertex PLY are byte-identical with
    --threads 1 and --threads 2;
  - the counters and strings of the profile JSON (curvature fallbacks,
    vertices used, ...) are equal;
  - aggregates (sigma per level, sigma_global, top_share) are within
    REL_AGGREGATE relative of the stored value;
  - per-vertex outputs (H at every vertex; D_1, D_5 and D_20 at every
    STRIDE-th vertex) are within REL_VERTEX of the stored largest absolute
    value of that output over all vertices, and NaN (undefined) exactly where
    the stored value is NaN. For D_L that scale is the larger of max |D_L| and
    max |H|: D_L = H - (mean of H over the ring) carries the rounding of H,
    and where the surface is a sphere (true D_L = 0) max |D_L| is 2,000 times
    below max |H|, so a change of H in its last bits (a few 1e-16) would
    exceed 1e-12 of max |D_L| (issue 30 states the bound against max |D_L|;
    this deviation is reported there).
It prints the worst change seen of each kind.

Usage:
  tolerance_test.py MESHDIFF DATA_DIR WORK_DIR           the test
  tolerance_test.py --store MESHDIFF DATA_DIR WORK_DIR   (re)write the stored outputs (generate.sh)
Environment: MESHDIFF_TOLERANCE_PERTURB=REL multiplies the stored H at one
vertex and the stored sigma_1 of the first case by (1 + REL), to show that
the test fails (REL above the bound) or passes (below).
"""
import json
import lzma
import math
import os
import struct
import subprocess
import sys

REL_AGGREGATE = 1e-12
REL_VERTEX = 1e-12
STRIDE = 4
MESHES = ["sphere_ico_2562", "sphere_irregular_3072", "torus_R1_r025", "bunny_res3", "fandisk"]
FITS = ["jet", "goldfeather"]
SAMPLED_COLUMNS = ["D_1", "D_5", "D_20"]
# The profile JSON's keys kept and compared (the rest names paths or versions).
KEPT = ["curvature", "sigma", "sigma_global", "global", "level_details", "levels"]
DROPPED = {"worst_vertices"}  # vertex ids ordered by |D|: ties may reorder under rounding


def run_profile(meshdiff, mesh, fit, out, threads, vertex_data=True):
    json_path, ply_path = out + ".json", out + ".ply"
    extra = ["--vertex-data", ply_path] if vertex_data else []
    subprocess.run([meshdiff, "profile", mesh, "--curvature", fit, "--json", json_path, *extra,
                    "--threads", str(threads), "-q"], check=True, stdout=subprocess.DEVNULL)
    return (json_path, ply_path) if vertex_data else (json_path,)


def worst_vertex_lists(report):
    """The worst-vertex ids of every level, in the report's order."""
    return [level.get("worst_vertices") for level in report.get("level_details", [])]


def read_vertex_columns(path):
    """The per-vertex double properties of a binary little-endian PLY, by name."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    assert "format binary_little_endian 1.0" in header, path
    count, props, in_vertex = 0, [], False
    for line in header:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count, in_vertex = int(words[2]), True
        elif words[:1] == ["element"]:
            in_vertex = False
        elif in_vertex and words[:1] == ["property"]:
            props.append((words[1], words[2]))
    codes = {"double": "d", "float": "f", "uchar": "B", "int": "i", "uint": "I"}
    fmt = "<" + "".join(codes[t] for t, _ in props)
    rows = struct.iter_unpack(fmt, data[end:end + count * struct.calcsize(fmt)])
    columns = list(zip(*rows))
    return {name: list(columns[k]) for k, (_, name) in enumerate(props)}


def reduced(report):
    """The stored part of a profile JSON."""
    def strip(x):
        if isinstance(x, dict):
            return {k: strip(v) for k, v in x.items() if k not in DROPPED}
        if isinstance(x, list):
            return [strip(v) for v in x]
        return x
    return {k: strip(report[k]) for k in KEPT if k in report}


def max_abs(values):
    return max((abs(v) for v in values if not math.isnan(v)), default=0.0)


def stored_vectors(columns):
    """H at every vertex, then each sampled column at every STRIDE-th vertex."""
    out = {"H": columns["H"]}
    for name in SAMPLED_COLUMNS:
        out[name] = columns[name][::STRIDE]
    return out


def store(meshdiff, data_dir, work):
    folder = os.path.join(data_dir, "tolerance")
    for mesh in MESHES:
        for fit in FITS:
            json_path, ply_path = run_profile(meshdiff, os.path.join(data_dir, mesh + ".ply"), fit,
                                              os.path.join(work, f"{mesh}.{fit}"), 2)
            with open(json_path) as f:
                report = json.load(f)
            columns = read_vertex_columns(ply_path)
            vectors = stored_vectors(columns)
            meta = {
                "mesh": mesh + ".ply",
                "curvature": fit,
                "vertices": len(columns["H"]),
                "stride": STRIDE,
                "columns": ["H"] + SAMPLED_COLUMNS,
                "max_abs": {name: max_abs(columns[name]) for name in ["H"] + SAMPLED_COLUMNS},
                "profile": reduced(report),
            }
            base = os.path.join(folder, f"{mesh}.{fit}")
            with open(base + ".json", "w") as f:
                json.dump(meta, f, indent=1, sort_keys=True)
                f.write("\n")
            raw = b"".join(struct.pack(f"<{len(v)}d", *v) for v in vectors.values())
            with open(base + ".f64.xz", "wb") as f:
                f.write(lzma.compress(raw, preset=9 | lzma.PRESET_EXTREME))


class Worst:
    def __init__(self):
        self.value, self.where = 0.0, ""

    def see(self, value, where):
        if value > self.value:
            self.value, self.where = value, where


def compare_json(old, new, where, errors, worst):
    if isinstance(old, dict):
        if not isinstance(new, dict) or set(old) != set(new):
            errors.append(f"{where}: keys {sorted(old)} became {new if not isinstance(new, dict) else sorted(new)}")
            return
        for k in old:
            compare_json(old[k], new[k], f"{where}.{k}", errors, worst)
    elif isinstance(old, list):
        if not isinstance(new, list) or len(old) != len(new):
            errors.append(f"{where}: list of {len(old)} became {new}")
            return
        for k, (a, b) in enumerate(zip(old, new)):
            compare_json(a, b, f"{where}[{k}]", errors, worst)
    elif isinstance(old, float) and isinstance(new, (int, float)) and not isinstance(new, bool):
        rel = 0.0 if old == new else abs(new - old) / abs(old) if old != 0.0 else math.inf
        worst.see(rel, f"{where}: {old!r} -> {new!r}")
        if rel > REL_AGGREGATE:
            errors.append(f"{where}: {old!r} became {new!r} (relative change {rel:.3g} > {REL_AGGREGATE:g})")
    elif old != new or type(old) is not type(new):
        errors.append(f"{where}: {old!r} became {new!r}")


def check(meshdiff, data_dir, work):
    folder = os.path.join(data_dir, "tolerance")
    perturb = float(os.environ.get("MESHDIFF_TOLERANCE_PERTURB", "0"))
    errors = []
    worst_aggregate, worst_vertex = Worst(), Worst()
    for case, (mesh, fit) in enumerate((m, f) for m in MESHES for f in FITS):
        base = os.path.join(folder, f"{mesh}.{fit}")
        with open(base + ".json") as f:
            meta = json.load(f)
        with open(base + ".f64.xz", "rb") as f:
            raw = lzma.decompress(f.read())
        n = meta["vertices"]
        sampled = len(range(0, n, meta["stride"]))
        sizes = [n] + [sampled] * (len(meta["columns"]) - 1)
        assert len(raw) == 8 * sum(sizes), f"{base}.f64.xz: {len(raw)} bytes for {sizes} values"
        old, offset = {}, 0
        for name, size in zip(meta["columns"], sizes):
            old[name] = list(struct.unpack_from(f"<{size}d", raw, offset))
            offset += 8 * size
        if case == 0 and perturb:
            k = next(k for k, h in enumerate(old["H"]) if h == h and abs(h) > 0.5 * meta["max_abs"]["H"])
            old["H"][k] *= 1.0 + perturb
            meta["profile"]["sigma"][0] *= 1.0 + perturb
            print(f"perturbed: {mesh} {fit} stored H at vertex {k} and sigma_1 by a relative {perturb:g}")

        mesh_path = os.path.join(data_dir, meta["mesh"])
        outputs = []
        for threads in (1, 2):
            paths = run_profile(meshdiff, mesh_path, fit, os.path.join(work, f"{mesh}.{fit}.t{threads}"), threads)
            outputs.append([open(p, "rb").read() for p in paths])
        if outputs[0] != outputs[1]:
            errors.append(f"{mesh} {fit}: the JSON or the PLY differs between --threads 1 and --threads 2")
        new_report = json.loads(outputs[1][0])
        compare_json(meta["profile"], reduced(new_report), f"{mesh} {fit}", errors, worst_aggregate)
        # Without per-vertex data the ring levels are folded batch by batch
        # (no stored D): the same rule, and the same worst vertices as the run
        # with D stored (the same D, ranked in the same total order).
        folded = [open(run_profile(meshdiff, mesh_path, fit, os.path.join(work, f"{mesh}.{fit}.folded.t{t}"), t,
                                   vertex_data=False)[0], "rb").read() for t in (1, 2)]
        if folded[0] != folded[1]:
            errors.append(f"{mesh} {fit}: without --vertex-data the JSON differs between --threads 1 and 2")
        folded_report = json.loads(folded[1])
        compare_json(meta["profile"], reduced(folded_report), f"{mesh} {fit} (folded)", errors, worst_aggregate)
        if worst_vertex_lists(folded_report) != worst_vertex_lists(new_report):
            errors.append(f"{mesh} {fit}: the worst vertices differ between the folded and the stored levels")

        columns = read_vertex_columns(paths[1])
        new = stored_vectors(columns)
        if len(columns["H"]) != n:
            errors.append(f"{mesh} {fit}: {n} vertices became {len(columns['H'])}")
            continue
        for name in meta["columns"]:
            scale = meta["max_abs"][name] if name == "H" else max(meta["max_abs"][name], meta["max_abs"]["H"])
            for k, (a, b) in enumerate(zip(old[name], new[name])):
                vertex = k if name == "H" else k * meta["stride"]
                if math.isnan(a) or math.isnan(b):
                    if math.isnan(a) != math.isnan(b):
                        errors.append(f"{mesh} {fit} {name} at vertex {vertex}: {a!r} became {b!r}")
                    continue
                change = abs(b - a) / scale if scale > 0.0 else (0.0 if a == b else math.inf)
                worst_vertex.see(change, f"{mesh} {fit} {name} at vertex {vertex}: {a!r} -> {b!r}")
                if change > REL_VERTEX:
                    errors.append(f"{mesh} {fit} {name} at vertex {vertex}: {a!r} became {b!r} "
                                  f"(change {change:.3g} of the scale {scale:.6g} > {REL_VERTEX:g})")
    print(f"worst relative change of an aggregate: {worst_aggregate.value:.3g} ({worst_aggregate.where})")
    print(f"worst change of a per-vertex output, relative to its largest |value|: {worst_vertex.value:.3g} "
          f"({worst_vertex.where})")
    for e in errors[:40]:
        print("FAIL", e)
    if len(errors) > 40:
        print(f"... and {len(errors) - 40} more")
    return 1 if errors else 0


def main(argv):
    if len(argv) == 5 and argv[1] == "--store":
        os.makedirs(argv[4], exist_ok=True)
        store(argv[2], argv[3], argv[4])
        return 0
    if len(argv) != 4:
        print(__doc__)
        return 2
    os.makedirs(argv[3], exist_ok=True)
    return check(argv[1], argv[2], argv[3])


if __name__ == "__main__":
    sys.exit(main(sys.argv))
