#!/usr/bin/env bash
# Plot roughness profiles (sigma against level, one line per mesh) from
# `meshdiff profile --json` reports.
#
#   reference/plot_profiles.sh OUT.png "title" NAME=profile.json [NAME=profile.json ...]
#
# Writes OUT.png (gnuplot, pngcairo or png terminal) and the plotted table OUT.csv beside it.
# The global level is drawn at the right end, labelled G. When a report holds the profile of
# the exact curvature (`meshdiff profile --exact`), it is drawn dashed in the same colour.
# Environment: LOGY=1 for a logarithmic sigma axis; SIZE=900,600 for the image size in pixels.
set -euo pipefail

if [[ $# -lt 3 ]]; then
    sed -n '2,10p' "$0" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
out=$1
title=$2
shift 2
csv=${out%.*}.csv
python3 "$here/json2csv.py" profiles "$csv" "$@"

term=pngcairo
gnuplot -e "set terminal" 2>&1 | grep -qw pngcairo || term=png
size=${SIZE:-900,600}

# Header: level,name1[,name1_exact],name2,...
mapfile -t cols < <(python3 -c 'import csv, sys; print("\n".join(next(csv.reader(open(sys.argv[1])))))' "$csv")
# Largest numeric level decides where the global level is drawn.
lmax=$(awk -F, 'NR > 1 && $1 != "global" { if ($1 + 0 > m) m = $1 + 0 } END { print m + 0 }' "$csv")
gx=$(awk -v m="$lmax" 'BEGIN { d = int(m / 10); if (d < 1) d = 1; print m + d + 1 }')
hasglobal=$(awk -F, '$1 == "global" { g = 1 } END { print g + 0 }' "$csv")

plot=""
color=0
declare -A colour_of
for ((i = 1; i < ${#cols[@]}; i++)); do
    name=${cols[$i]//\"/\'}
    x='(strcol(1) eq "global" ? GX : $1)'
    if [[ $name == *_exact && -n ${colour_of[${name%_exact}]:-} ]]; then
        c=${colour_of[${name%_exact}]}
        style="with lines dt 2 lw 2 lc $c title \"${name%_exact} (exact H)\""
    else
        color=$((color + 1))
        colour_of[$name]=$color
        style="with linespoints pt 7 ps 0.6 lw 2 lc $color title \"$name\""
    fi
    plot+="${plot:+, }'$csv' using $x:$((i + 1)) $style"
done

gnuplot <<EOF
set terminal $term size $size font "DejaVu Sans,11" noenhanced
set output "$out"
set datafile separator ","
set key outside right top
set grid
set title "$title"
set xlabel "level L (rings)"
set ylabel "sigma_L"
GX = $gx
set xrange [0.5:GX + 0.5]
set xtics 0,1,$lmax nomirror
if ($lmax > 12) set xtics 0,2,$lmax
if ($hasglobal) set xtics add ("G" GX)
if ("${LOGY:-0}" eq "1") set logscale y
set yrange [0:*]
if ("${LOGY:-0}" eq "1") set yrange [*:*]
plot $plot
EOF
echo "$out"
