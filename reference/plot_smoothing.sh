#!/usr/bin/env bash
# Plot smoothing curves (sigma at each recorded level against iterations) from
# `meshdiff smooth --profile-every K --json` reports: one panel per level (the global level
# last), one line per report.
#
#   reference/plot_smoothing.sh OUT.png "title" NAME=smoothing.json [NAME=smoothing.json ...]
#
# Writes OUT.png (gnuplot, pngcairo or png terminal) and the plotted table OUT.csv beside it
# (columns name,iteration,level,sigma). The levels are those of the first report.
# Environment: LOGY=0 for a linear sigma axis (default logarithmic); COLS=3 panels per row;
# SIZE=WIDTH,HEIGHT in pixels.
set -euo pipefail

if [[ $# -lt 3 ]]; then
    sed -n '2,12p' "$0" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
out=$1
title=$2
shift 2
csv=${out%.*}.csv
python3 "$here/json2csv.py" smoothing "$csv" "$@"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
names=()
for arg in "$@"; do
    name=${arg%%=*}
    [[ $arg == *=* ]] || name=$(basename "${arg%.*}")
    names+=("$name")
    python3 "$here/json2csv.py" smoothing-wide "$tmp/${#names[@]}.csv" "$arg"
done
IFS=, read -r -a keys < "$tmp/1.csv"   # iteration,L1,L5,...,global
npanel=$((${#keys[@]} - 1))
ncol=${COLS:-3}
nrow=$(((npanel + ncol - 1) / ncol))
size=${SIZE:-$((ncol * 430)),$((nrow * 340 + 40))}
term=pngcairo
gnuplot -e "set terminal" 2>&1 | grep -qw pngcairo || term=png

{
    echo "set terminal $term size $size font \"DejaVu Sans,10\" noenhanced"
    echo "set output \"$out\""
    echo "set datafile separator \",\""
    echo "set grid"
    echo "set xlabel \"iteration\""
    if [[ ${LOGY:-1} == 1 ]]; then echo "set logscale y"; echo "set format y \"%.0e\""; fi
    echo "set multiplot layout $nrow,$ncol title \"$title\""
    for ((p = 1; p <= npanel; p++)); do
        key=${keys[$p]}
        label=$key
        [[ $key == L* ]] && label="level ${key#L}"
        echo "set title \"sigma, $label\""
        if ((p == 1)); then echo "set key top right font \",9\""; else echo "unset key"; fi
        plot=""
        for ((k = 1; k <= ${#names[@]}; k++)); do
            plot+="${plot:+, }'$tmp/$k.csv' using 1:$((p + 1)) with linespoints pt 7 ps 0.4 lw 2 lc $k title \"${names[$((k - 1))]}\""
        done
        echo "plot $plot"
    done
    echo "unset multiplot"
} > "$tmp/plot.gp"
gnuplot "$tmp/plot.gp"
echo "$out"
