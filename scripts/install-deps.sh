#!/usr/bin/env bash
# Install the Debian packages meshdiff needs to build, test and run.
# Usage: scripts/install-deps.sh            (build + test dependencies)
#        scripts/install-deps.sh --reference (also MeshLab, gnuplot, hyperfine for reference/)
set -euo pipefail
pkgs=(build-essential cmake pkg-config
      libopenmesh-dev libeigen3-dev libfmt-dev
      libgtest-dev nlohmann-json3-dev libcli11-dev libnanoflann-dev
      clang-format python3
      # GNU parallel: the cluster recipe of docs/cli.md (batch shards), tested by tests/cli_batch_cluster_test.sh.
      parallel
      # kill(1) of a process group and script(1) for a pseudo-terminal: tests/cli_progress_test.sh.
      procps bsdutils
      # The Python module (python/) and its tests, for Debian's /usr/bin/python3;
      # OpenMesh's command-line decimater for examples/evaluate_decimators.py.
      pybind11-dev pybind11-json-dev python3-dev python3-numpy python3-pytest python3-matplotlib libopenmesh-apps
      # The Python package (pyproject.toml, setup.py): `pip install --no-build-isolation .` in a venv and
      # `python3 -m build --no-isolation --wheel`, offline; stubtest and mypy; the mesh objects of its tests
      # (meshio, Open3D); its Dask recipe and test (distributed); progress=True (tqdm).
      python3-setuptools python3-wheel python3-build python3-venv python3-mypy
      python3-meshio python3-open3d python3-distributed python3-tqdm
      # The fuzzing of the readers (scripts/fuzz.sh): clang with libFuzzer and its OpenMP runtime.
      clang libclang-rt-14-dev libomp-dev
      # The HTML report: three.js with its OrbitControls, inlined at build time (CMakeLists.txt), and its
      # test in a real browser (tests/html_browser_test.py: headless chromium driven by selenium, PIL).
      libjs-three chromium chromium-driver python3-selenium python3-pil)
if [[ "${1:-}" == "--reference" ]]; then
    pkgs+=(meshlab xvfb xauth gnuplot-nox hyperfine)
fi
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
missing=()
for p in "${pkgs[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -qq
    $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
