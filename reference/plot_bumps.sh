#!/usr/bin/env bash
# Picture of where smoothing creates bumps on an ellipsoid (paper Fig. 10): the vertices of the
# front half (z > -0.05, seen from +z) projected onto the x-y plane and coloured by D_3, the
# mean curvature minus its mean over the 3-ring (on the scaled mesh). Valence-5 vertices are
# circled. One panel per smoothing result.
#
#   reference/plot_bumps.sh OUT.png DIR NAME [NAME ...]
#
# reads DIR/ellipsoid_NAME_vertices.dat (columns x y z valence H D_3, as written by
# `plytool.py points MESH.ply OUT.dat --prop H --prop D_3` from `meshdiff profile --vertex-data`).
# Environment: CB=0.3 colour range [-CB, CB] of D_3.
set -euo pipefail
if [[ $# -lt 3 ]]; then
    sed -n '2,11p' "$0" >&2
    exit 2
fi
out=$1
dir=$2
shift 2
n=$#
ncol=3
nrow=$(((n + ncol - 1) / ncol))
term=pngcairo
gnuplot -e "set terminal" 2>&1 | grep -qw pngcairo || term=png
{
    echo "set terminal $term size $((ncol * 460)),$((nrow * 330 + 40)) font \"DejaVu Sans,10\" noenhanced"
    echo "set output \"$out\""
    echo "set palette defined (-1 \"#1f3fbf\", -0.25 \"#7f9fff\", 0 \"#e0e0e0\", 0.25 \"#ff9f7f\", 1 \"#bf1f1f\")"
    echo "set cbrange [-${CB:-0.3}:${CB:-0.3}]"
    echo "set size ratio -1"
    echo "unset key"
    echo "set xtics 0.5; set ytics 0.5"
    echo "set multiplot layout $nrow,$ncol title \"Ellipsoid (1.5, 1, 1) after ${ITER:-50} post-updating iterations: D_3 (colour), valence-5 vertices circled\""
    for m in "$@"; do
        f=$dir/ellipsoid_${m}_vertices.dat
        label=$m
        [[ $m == none ]] && label="not smoothed"
        echo "set title \"$label\""
        echo "plot '$f' using (\$3 > -0.05 ? \$1 : 1/0):2:6 with points pt 7 ps 0.55 lc palette, \\"
        echo "     '$f' using (\$3 > -0.05 && \$4 == 5 ? \$1 : 1/0):2 with points pt 6 ps 2.2 lw 1.5 lc rgb \"black\""
    done
    echo "unset multiplot"
} | gnuplot
echo "$out"
