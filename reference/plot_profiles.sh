#!/usr/bin/env bash
# Plot roughness profiles (sigma against level, one line per mesh) from
# `meshdiff profile --json` reports.
#
#   reference/plot_profiles.sh OUT.png "title" NAME=profile.json [NAME=profile.json ...]
#
# Writes OUT.png (reference/plot.py, matplotlib) and the plotted table OUT.csv beside it.
# Markers at the measured levels, lines only between them; the global level is a separate
# marker at the right end, labelled G. A profile of the exact curvature in a report
# (`meshdiff profile --exact`) is drawn dotted in the same colour; a NAME
# "clean" is a dashed black reference line. Legend outside the axes.
# Environment: LOGY=1 for a logarithmic sigma axis; PYNUM = python3 with numpy and
# matplotlib (default /usr/bin/python3).
set -euo pipefail

if [[ $# -lt 3 ]]; then
    sed -n '2,13p' "$0" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
out=$1
title=$2
shift 2
python3 "$here/json2csv.py" profiles "${out%.*}.csv" "$@"
opts=()
[[ ${LOGY:-0} == 1 ]] && opts+=(--logy)
"${PYNUM:-/usr/bin/python3}" "$here/plot.py" profiles "$out" "$title" "$@" "${opts[@]}"
