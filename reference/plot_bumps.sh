#!/usr/bin/env bash
# Picture of where smoothing creates bumps on an ellipsoid (paper Fig. 10): the vertices of the
# front half (z > -0.05, seen from +z) projected onto the x-y plane and coloured by D_3, the
# mean curvature minus its mean over the 3-ring (on the scaled mesh). Valence-5 vertices are
# circled. One panel per smoothing result, one colour bar.
#
#   reference/plot_bumps.sh OUT.png DIR NAME [NAME ...]
#
# reads DIR/ellipsoid_NAME_vertices.dat (columns x y z valence H D_3, as written by
# `plytool.py points MESH.ply OUT.dat --prop H --prop D_3` from `meshdiff profile --vertex-data`).
# Environment: CB=0.3 colour range [-CB, CB] of D_3; ITER=50 (title only); PYNUM as plot.py.
set -euo pipefail
if [[ $# -lt 3 ]]; then
    sed -n '2,11p' "$0" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
out=$1
dir=$2
shift 2
"${PYNUM:-/usr/bin/python3}" "$here/plot.py" bumps "$out" \
    "Ellipsoid after ${ITER:-50} post-updating iterations: D_3 (colour), valence-5 vertices circled" \
    "$dir" "$@" --cb "${CB:-0.3}"
