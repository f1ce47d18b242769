"""Shared set-up of the Python tests: they test the module of a build tree.

The build tree is $MESHDIFF_BUILD_DIR, or build/ at the repository root (what
scripts/test.sh builds). Its python/ directory goes first on sys.path, so that
an installed meshdiff cannot shadow the one under test; the CLI of the same
build tree is the reference of the bitwise tests.
"""
import os
import pathlib
import sys

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("MESHDIFF_BUILD_DIR", REPO / "build")).resolve()
DATA = REPO / "tests" / "data"

sys.path.insert(0, str(BUILD / "python"))

import meshdiff  # noqa: E402

if pathlib.Path(meshdiff.__file__).resolve().parent != BUILD / "python":
    raise RuntimeError(f"imported {meshdiff.__file__}, not the module of {BUILD}")


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
