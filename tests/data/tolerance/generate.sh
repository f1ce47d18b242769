#!/usr/bin/env bash
# (Re)writes the stored outputs of this folder with MESHDIFF (see README.md): for every bundled mesh and fit of
# tests/tolerance_test.py, the reduced profile JSON and the per-vertex H / D_L. Run it only with the binary that
# the outputs are meant to pin (the one before a change), never to make a failing check pass.
#
#   tests/data/tolerance/generate.sh MESHDIFF
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$here/../../tolerance_test.py" --store "$1" "$here/.." "$work"
