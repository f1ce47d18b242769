#!/usr/bin/env python3
"""Writes a mesh with its vertices in a random order (faces renumbered): the input of the vertex-order benchmark in
docs/performance.md ("Vertex order").

    PYTHONPATH=build/python /usr/bin/python3 bench/shuffle_mesh.py IN.ply OUT.ply [SEED]

Needs the meshdiff Python module (built with -DMESHDIFF_BUILD_PYTHON=ON) and numpy.
"""
import sys

import numpy as np

import meshdiff


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    seed = int(sys.argv[3]) if len(sys.argv) == 4 else 1
    r = meshdiff.read_mesh(sys.argv[1])
    V, F = (r[0], r[1]) if isinstance(r, tuple) else (r["V"], r["F"])
    V = np.asarray(V, dtype="<f8")
    F = np.asarray(F)
    perm = np.random.default_rng(seed).permutation(len(V))  # new position of each old vertex
    V2 = np.empty_like(V)
    V2[perm] = V
    faces = np.zeros(len(F), dtype=[("n", "u1"), ("i", "<i4", 3)])
    faces["n"] = 3
    faces["i"] = perm[F]
    with open(sys.argv[2], "wb") as f:
        f.write(
            (
                "ply\nformat binary_little_endian 1.0\n"
                f"element vertex {len(V2)}\nproperty double x\nproperty double y\nproperty double z\n"
                f"element face {len(F)}\nproperty list uchar int vertex_indices\nend_header\n"
            ).encode()
        )
        f.write(V2.tobytes())
        f.write(faces.tobytes())
    print(f"{sys.argv[2]}: {len(V2)} vertices in a random order (seed {seed}), {len(F)} faces")


if __name__ == "__main__":
    main()
