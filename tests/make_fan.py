#!/usr/bin/env python3
"""make_fan.py N OUT.ply: a fan of N triangles around one vertex (valence N), binary PLY.

Centre (0, 0, 0.1); N rim vertices on the unit circle with z = 0.01 sin(7a); faces (0, i, i + 1 mod N).
Used by tests/cli_hub_test.sh and bench/hub_fan.sh (issue 13).
"""
import math
import struct
import sys

n, out = int(sys.argv[1]), sys.argv[2]
with open(out, "wb") as f:
    f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            b"property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n" % (n + 1, n))
    f.write(struct.pack("<3f", 0.0, 0.0, 0.1))
    for i in range(n):
        a = 2 * math.pi * i / n
        f.write(struct.pack("<3f", math.cos(a), math.sin(a), 0.01 * math.sin(7 * a)))
    for i in range(n):
        f.write(struct.pack("<B3i", 3, 0, 1 + i, 1 + (i + 1) % n))
