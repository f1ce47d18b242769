"""The types shipped with the package (issue 32): __init__.pyi and py.typed are
installed beside the module, stubtest finds the stub true to the module, the
stub has each extension function's keywords (no more, no fewer), and mypy uses
it: the example scripts pass, a mistyped keyword fails."""
import ast
import subprocess
import sys

import pytest

import meshdiff
from meshdiff import _calls, _meshdiff
from conftest import BUILD, INSTALLED, PACKAGE, REPO, child_env

# Keywords the package adds in Python to those of the extension's function.
PYTHON_ONLY = {"read_mesh": set()}
EXAMPLES = ["examples/evaluate_decimators.py"]


def mypy_env():
    # mypy does not read PYTHONPATH; the build tree's package is found through MYPYPATH.
    return child_env() if INSTALLED else child_env(MYPYPATH=str(BUILD / "python"))


def stub_functions():
    tree = ast.parse((PACKAGE / "__init__.pyi").read_text())
    functions = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            functions.setdefault(node.name, []).append(node)
    return functions


def test_the_package_ships_its_types():
    assert (PACKAGE / "py.typed").exists() and (PACKAGE / "__init__.pyi").exists()


def test_stubtest_finds_the_stub_true_to_the_module(tmp_path):
    config = tmp_path / "mypy.ini"
    config.write_text("[mypy]\nignore_missing_imports = True\n")
    allow = tmp_path / "allowlist"
    # A pybind11 class has pybind11's metaclass, which no stub names; the private modules _calls and _meshes are
    # plain Python that mypy checks as such.
    allow.write_text("meshdiff.DistanceIndex\nmeshdiff._calls.*\nmeshdiff._meshes.*\n")
    r = subprocess.run([sys.executable, "-m", "mypy.stubtest", "meshdiff", "--mypy-config-file", str(config),
                        "--allowlist", str(allow)],
                       capture_output=True, text=True, env=mypy_env(), cwd=tmp_path, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.parametrize("name", ["compare", "compare_files", "profile", "profile_file", "corsini_profile",
                                  "mean_curvature", "roughness", "surface_distance", "vertex_distances",
                                  "read_mesh"])
def test_the_stub_has_the_keywords_of_the_extension(name):
    _, keywords = _calls.signature(getattr(_meshdiff, name))
    assert keywords, f"no keyword-only arguments found in the docstring of _meshdiff.{name}"
    overloads = stub_functions()[name]
    for fn in overloads:
        stub_keywords = {a.arg for a in fn.args.kwonlyargs} - PYTHON_ONLY.get(name, {"progress"})
        assert stub_keywords == set(keywords), f"{name} (stub line {fn.lineno})"


def test_the_stub_names_every_public_function():
    public = {n for n in dir(_meshdiff) if not n.startswith("_")}
    tree = ast.parse((PACKAGE / "__init__.pyi").read_text())
    named = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    named |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]
              if isinstance(t, ast.Name)}
    assert public <= named, public - named
    assert set(meshdiff.__all__) <= named | {"__version__"}


def run_mypy(paths, tmp_path):
    return subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(tmp_path / "cache"),
                           "--ignore-missing-imports", *map(str, paths)],
                          capture_output=True, text=True, env=mypy_env(), cwd=REPO, timeout=600)


def test_the_examples_pass_mypy(tmp_path):
    r = run_mypy(EXAMPLES, tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr


def test_mypy_catches_a_mistyped_keyword(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("import meshdiff\nV, F = meshdiff.read_mesh('x.ply')\nmeshdiff.compare(V, F, V, F, levles=[1])\n")
    r = run_mypy([bad], tmp_path)
    assert r.returncode == 1 and 'No overload variant of "compare" matches' in r.stdout, r.stdout + r.stderr
