#!/usr/bin/env python3
"""Small PLY helpers for the reference studies (standard library only).

  plytool.py noise IN.ply OUT.ply --amplitude A [--seed S]
      Superseded by `meshdiff noise`; kept only as the fallback that studies.sh uses with a
      meshdiff build that lacks the noise command. Moves every vertex with a normal,
      boundary vertices included, along its area-weighted normal (meshdiff noise:
      angle-weighted, boundary fixed) by a uniform random amount in [-A, A) times the mean
      edge length, drawn with Python's random (not meshdiff's numbers for the same seed).
      Connectivity and vertex order are unchanged.

  plytool.py points IN.ply OUT.dat [--prop NAME ...]
      One line per vertex: x y z valence [props...], for gnuplot.

  plytool.py valence-stats IN.ply --prop NAME [--prop NAME ...]
      JSON on stdout: per vertex valence, the count and the RMS and mean |.| of each property.

Reads binary little-endian and ASCII PLY with scalar vertex properties and one face list.
"""
import argparse
import json
import math
import random
import struct
import sys

TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise SystemExit(f"plytool: {path}: not a PLY file")
    body = data.index(b"\n", end) + 1
    header = data[:body].decode("ascii", "replace").splitlines()
    fmt = None
    elements = []  # [name, count, [(prop, type, listcount_type or None)]]
    comments = []
    for line in header:
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "comment":
            comments.append(line[len("comment "):])
        elif w[0] == "element":
            elements.append([w[1], int(w[2]), []])
        elif w[0] == "property":
            if w[1] == "list":
                elements[-1][2].append((w[4], w[3], w[2]))
            else:
                elements[-1][2].append((w[2], w[1], None))
    if fmt not in ("binary_little_endian", "ascii"):
        raise SystemExit(f"plytool: {path}: format {fmt} not supported")
    verts, names, faces = [], [], []
    if fmt == "ascii":
        tokens = data[body:].split()
        pos = 0
        for name, count, props in elements:
            for _ in range(count):
                rec = []
                for pname, ptype, ltype in props:
                    if ltype:
                        n = int(tokens[pos]); pos += 1
                        rec.append([int(t) for t in tokens[pos:pos + n]]); pos += n
                    else:
                        rec.append(float(tokens[pos])); pos += 1
                if name == "vertex":
                    verts.append(rec)
                elif name == "face":
                    faces.append(rec[0])
            if name == "vertex":
                names = [p[0] for p in props]
        return names, verts, faces, comments
    pos = body
    for name, count, props in elements:
        if all(l is None for _, _, l in props):
            st = struct.Struct("<" + "".join(TYPES[t] for _, t, _ in props))
            recs = list(st.iter_unpack(data[pos:pos + st.size * count]))
            pos += st.size * count
            if name == "vertex":
                verts = [list(r) for r in recs]
                names = [p[0] for p in props]
            continue
        # One list property (faces); fast path for all-triangle meshes.
        if len(props) != 1:
            raise SystemExit(f"plytool: {path}: element {name} not supported")
        _, itype, ctype = props[0]
        cst = struct.Struct("<" + TYPES[ctype])
        ist = struct.calcsize("<" + TYPES[itype])
        tri = struct.Struct("<" + TYPES[ctype] + 3 * TYPES[itype])
        out = []
        for _ in range(count):
            n = cst.unpack_from(data, pos)[0]
            if n == 3:
                out.append(list(tri.unpack_from(data, pos)[1:]))
                pos += tri.size
            else:
                out.append(list(struct.unpack_from("<%d%s" % (n, TYPES[itype]), data, pos + cst.size)))
                pos += cst.size + n * ist
        if name == "face":
            faces = out
    return names, verts, faces, comments


def write_ply(path, names, verts, faces, comments):
    with open(path, "wb") as f:
        head = ["ply", "format binary_little_endian 1.0"] + ["comment " + c for c in comments]
        head.append(f"element vertex {len(verts)}")
        head += [f"property double {n}" for n in names]
        head += [f"element face {len(faces)}", "property list uchar int vertex_indices", "end_header"]
        f.write(("\n".join(head) + "\n").encode("ascii"))
        vs = struct.Struct("<" + "d" * len(names))
        f.write(b"".join(vs.pack(*v) for v in verts))
        f.write(b"".join(struct.pack("<B%di" % len(t), len(t), *t) for t in faces))


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def triangles(faces):
    for f in faces:
        for k in range(1, len(f) - 1):
            yield f[0], f[k], f[k + 1]


def cmd_noise(a):
    names, verts, faces, comments = read_ply(a.input)
    ix, iy, iz = names.index("x"), names.index("y"), names.index("z")
    P = [(v[ix], v[iy], v[iz]) for v in verts]
    N = [[0.0, 0.0, 0.0] for _ in P]
    edges = set()
    for i, j, k in triangles(faces):
        n = cross(sub(P[j], P[i]), sub(P[k], P[i]))  # length = twice the area: area weighting
        for v in (i, j, k):
            N[v][0] += n[0]; N[v][1] += n[1]; N[v][2] += n[2]
        for e in ((i, j), (j, k), (k, i)):
            edges.add((min(e), max(e)))
    mean_edge = sum(math.dist(P[i], P[j]) for i, j in edges) / len(edges)
    rng = random.Random(a.seed)
    h = a.amplitude * mean_edge
    out = []
    for p, n in zip(P, N):
        ln = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
        t = rng.uniform(-h, h)
        if ln > 0:
            p = (p[0] + t * n[0] / ln, p[1] + t * n[1] / ln, p[2] + t * n[2] / ln)
        out.append(p)
    comments = [c for c in comments if not c.startswith("written by")]
    comments.append(f"plytool noise: {a.input} moved along vertex normals by uniform [-{a.amplitude}, "
                    f"{a.amplitude}) x mean edge length {mean_edge:.6g}, seed {a.seed}")
    write_ply(a.output, ["x", "y", "z"], out, faces, comments)
    print(f"{a.output}: {len(out)} vertices, noise +-{h:.4g} ({a.amplitude} x mean edge {mean_edge:.4g})")


def valences(n, faces):
    nb = [set() for _ in range(n)]
    for i, j, k in triangles(faces):
        nb[i].update((j, k)); nb[j].update((i, k)); nb[k].update((i, j))
    return [len(s) for s in nb]


def cmd_points(a):
    names, verts, faces, _ = read_ply(a.input)
    val = valences(len(verts), faces)
    cols = [names.index(c) for c in ["x", "y", "z"] + (a.prop or [])]
    with open(a.output, "w") as f:
        f.write("# x y z valence " + " ".join(a.prop or []) + "\n")
        for v, k in zip(verts, val):
            vals = [v[c] for c in cols]
            f.write(" ".join("%.7g" % x for x in vals[:3]) + " %d " % k
                    + " ".join("%.7g" % x for x in vals[3:]) + "\n")


def cmd_valence_stats(a):
    names, verts, faces, _ = read_ply(a.input)
    val = valences(len(verts), faces)
    res = {}
    for prop in a.prop:
        c = names.index(prop)
        groups = {}
        for v, k in zip(verts, val):
            x = v[c]
            if x != x:  # NaN: undefined
                continue
            groups.setdefault(k, []).append(x)
        res[prop] = {str(k): {"count": len(g), "rms": math.sqrt(sum(x * x for x in g) / len(g)),
                              "mean_abs": sum(abs(x) for x in g) / len(g)}
                     for k, g in sorted(groups.items())}
    json.dump({"mesh": a.input, "by_valence": res}, sys.stdout, indent=1)
    sys.stdout.write("\n")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    s = p.add_subparsers(dest="cmd", required=True)
    n = s.add_parser("noise", help="superseded by `meshdiff noise` (fallback for studies.sh)")
    n.add_argument("input"); n.add_argument("output")
    n.add_argument("--amplitude", type=float, required=True)
    n.add_argument("--seed", type=int, default=1)
    n.set_defaults(func=cmd_noise)
    q = s.add_parser("points", help="x y z valence [props] per vertex, for gnuplot")
    q.add_argument("input"); q.add_argument("output")
    q.add_argument("--prop", action="append")
    q.set_defaults(func=cmd_points)
    v = s.add_parser("valence-stats", help="per-valence count, RMS and mean |.| of properties (JSON)")
    v.add_argument("input")
    v.add_argument("--prop", action="append", required=True)
    v.set_defaults(func=cmd_valence_stats)
    a = p.parse_args()
    a.func(a)


if __name__ == "__main__":
    main()
