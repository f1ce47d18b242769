"""The build of the Python package meshdiff (pyproject.toml holds the metadata).

`pip install --no-build-isolation .` and `python3 -m build --no-isolation --wheel`
run the project's CMake here: a Release build of the target meshdiff_python
(the extension meshdiff._meshdiff, linked with the same static libraries as the
CLI) for the interpreter that runs pip, in build-python/ under the source tree.

MESHDIFF_CMAKE_BUILD_DIR=DIR reuses an existing CMake build tree instead (one
configured with -DMESHDIFF_BUILD_PYTHON=ON for the same interpreter version,
e.g. the Release tree of scripts/test.sh): the backend then only runs
`cmake --build DIR --target meshdiff_python`, a no-op when DIR is up to date,
and packs the extension it holds.

The version is the one of project(meshdiff VERSION ...) in CMakeLists.txt, the
project's one version source.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def cmake_version() -> str:
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    m = re.search(r"project\(\s*meshdiff\s+VERSION\s+([0-9][0-9.]*)", text)
    if not m:
        raise RuntimeError("no project(meshdiff VERSION ...) in CMakeLists.txt")
    return m.group(1)


class CMakeExtension(Extension):
    """The extension meshdiff._meshdiff, made by CMake (no sources for setuptools)."""

    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """build_ext that builds the CMake target meshdiff_python and copies the result."""

    def run(self) -> None:
        if shutil.which("cmake") is None:
            raise RuntimeError("meshdiff: cmake not found (Debian: scripts/install-deps.sh installs it)")
        super().run()

    def build_extension(self, ext: Extension) -> None:
        given = os.environ.get("MESHDIFF_CMAKE_BUILD_DIR")
        if given:
            build_dir = pathlib.Path(given).resolve()
            if not (build_dir / "CMakeCache.txt").exists():
                raise RuntimeError(f"MESHDIFF_CMAKE_BUILD_DIR={given}: not a configured CMake build tree")
        else:
            build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
            self.configure(build_dir)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(self.parallel or os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "meshdiff_python", "-j", jobs], check=True)
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build_dir / "python" / "meshdiff" / ("_meshdiff" + suffix)
        if not built.exists():
            found = sorted(p.name for p in (build_dir / "python" / "meshdiff").glob("_meshdiff*"))
            raise RuntimeError(f"meshdiff: {built} is missing (found {found or 'nothing'}): the CMake tree "
                               f"{build_dir} was built for another interpreter than {sys.executable}, or "
                               f"without -DMESHDIFF_BUILD_PYTHON=ON")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)

    def configure(self, build_dir: pathlib.Path) -> None:
        if (build_dir / "CMakeCache.txt").exists():
            return
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                        "-DMESHDIFF_BUILD_PYTHON=ON", "-DMESHDIFF_BUILD_TESTS=OFF", "-DMESHDIFF_BUILD_BENCH=OFF",
                        "-DMESHDIFF_BUILD_CLI=OFF", "-DMESHDIFF_WARNINGS_AS_ERRORS=OFF",
                        f"-DPython3_EXECUTABLE={sys.executable}"], check=True)


setup(
    version=cmake_version(),
    ext_modules=[CMakeExtension("meshdiff._meshdiff")],
    cmdclass={"build_ext": CMakeBuild},
    # Not build/: that is the CMake build tree of scripts/test.sh and the docs.
    options={"build": {"build_base": "build-python"}},
    zip_safe=False,
)
