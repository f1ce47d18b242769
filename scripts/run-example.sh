#!/usr/bin/env bash
# Installs the dependencies, builds meshdiff and runs it on a bundled example:
# the roughness profile of a real mesh, then the comparison of Stanford's
# bunny decimation res3 against res4 (both bundled in tests/data/), and the
# same comparison from Python (the package build/python/meshdiff/).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMESHDIFF_BUILD_PYTHON=ON > /dev/null
cmake --build build -j"${JOBS:-2}" --target meshdiff_cli meshdiff_python
echo "\$ build/meshdiff profile tests/data/fandisk.ply --levels 1,2,5,10,20"
build/meshdiff profile tests/data/fandisk.ply --levels 1,2,5,10,20
echo
echo "\$ build/meshdiff tests/data/bunny_res3.ply tests/data/bunny_res4_ascii.ply --levels 1,2,5,10,20"
build/meshdiff tests/data/bunny_res3.ply tests/data/bunny_res4_ascii.ply --levels 1,2,5,10,20
echo
# The interpreter CMake chose (one that imports numpy: /usr/bin/python3 on Debian).
py=$(sed -n 's/^MESHDIFF_PYTHON_EXECUTABLE:[A-Z]*=//p' build/CMakeCache.txt)
code="import meshdiff; print(meshdiff.compare_files('tests/data/bunny_res3.ply', 'tests/data/bunny_res4_ascii.ply')['surface_distance']['hausdorff']['upper'])"
echo "\$ PYTHONPATH=build/python $py -c \"$code\""
PYTHONPATH=build/python "$py" -c "$code"
