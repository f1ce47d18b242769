"""Shared set-up of the Python tests: they test the package of a build tree, or
the installed package.

The build tree is $MESHDIFF_BUILD_DIR, or build/ at the repository root (what
scripts/test.sh builds). Its python/ directory goes first on sys.path, so that
an installed meshdiff cannot shadow the one under test; the CLI of the same
build tree is the reference of the bitwise tests.

With MESHDIFF_TEST_INSTALLED=1 the tests import the package the interpreter has
installed (scripts/test.sh: `pip install .` into a virtual environment), and
refuse one of the build or source tree; the CLI is still the build tree's.
"""
import os
import pathlib
import sys

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("MESHDIFF_BUILD_DIR", REPO / "build")).resolve()
DATA = REPO / "tests" / "data"

INSTALLED = os.environ.get("MESHDIFF_TEST_INSTALLED") == "1"

if not INSTALLED:
    sys.path.insert(0, str(BUILD / "python"))

import meshdiff  # noqa: E402

PACKAGE = pathlib.Path(meshdiff.__file__).resolve().parent
if INSTALLED:
    if PACKAGE in (BUILD / "python" / "meshdiff", REPO / "python" / "meshdiff"):
        raise RuntimeError(f"imported {meshdiff.__file__}, not an installed package")
elif PACKAGE != BUILD / "python" / "meshdiff":
    raise RuntimeError(f"imported {meshdiff.__file__}, not the package of {BUILD}")


def child_env(**extra):
    """The environment of a child interpreter (sys.executable) that imports the
    same meshdiff as the tests."""
    env = dict(os.environ, **extra)
    if not INSTALLED:
        env["PYTHONPATH"] = str(BUILD / "python")
    return env


@pytest.fixture(scope="session")
def cli():
    path = BUILD / "meshdiff"
    if not path.exists():
        pytest.fail(f"{path} is missing: build the meshdiff_cli target")
    return str(path)


@pytest.fixture(scope="session")
def data():
    return DATA


@pytest.fixture(scope="session")
def build_dir():
    return BUILD


@pytest.fixture(scope="session")
def repo():
    return REPO


def pytest_configure(config):
    # The report warnings of the test meshes (python/tests/test_package.py checks them) would bury the summary.
    config.addinivalue_line("filterwarnings", "ignore::meshdiff.MeshWarning")
