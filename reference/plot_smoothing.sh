#!/usr/bin/env bash
# Plot smoothing curves (sigma at each recorded level against iterations) from
# `meshdiff smooth --profile-every K --json` reports: one panel per level (the global level
# last), one line per report.
#
#   reference/plot_smoothing.sh OUT.png "title" NAME=smoothing.json [NAME=smoothing.json ...]
#
# Writes OUT.png (reference/plot.py, matplotlib) and the plotted table OUT.csv beside it
# (columns name,iteration,level,sigma). The levels are those of the first report. Runs named
# "M post" and "M pre" share a colour (post solid, pre dashed).
# Environment: CLEAN_REF=PROFILE.json[#member] draws the clean mesh's sigma as a dashed black line in
# every panel; CLIP=10: the y range ignores values above CLIP times the largest starting sigma
# (runs cut off are named in the panel); LOGY=0 for a linear sigma axis (default logarithmic);
# PYNUM = python3 with numpy and matplotlib (default /usr/bin/python3).
set -euo pipefail

if [[ $# -lt 3 ]]; then
    sed -n '2,14p' "$0" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")" && pwd)
out=$1
title=$2
shift 2
python3 "$here/json2csv.py" smoothing "${out%.*}.csv" "$@"
opts=(--clip "${CLIP:-10}")
[[ -n ${CLEAN_REF:-} ]] && opts+=(--ref "$CLEAN_REF")
[[ ${LOGY:-1} == 0 ]] && opts+=(--linear)
"${PYNUM:-/usr/bin/python3}" "$here/plot.py" smoothing "$out" "$title" "$@" "${opts[@]}"
