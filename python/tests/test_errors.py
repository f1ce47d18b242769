"""Bad arrays, options and files raise the documented exceptions; nothing
crashes the interpreter."""
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import meshdiff
from conftest import child_env


@pytest.fixture(scope="module")
def mesh(data):
    return meshdiff.read_mesh(data / "hemisphere.ply")


def with_nan(V, row):
    V = V.copy()
    V[row, 1] = np.nan
    return V


@pytest.mark.parametrize("make,name", [
    (lambda V, F: meshdiff.profile(V[:, :2], F), "V"),
    (lambda V, F: meshdiff.profile(V.ravel(), F), "V"),
    (lambda V, F: meshdiff.profile(None, F), "V"),
    (lambda V, F: meshdiff.profile("abc", F), "V"),
    (lambda V, F: meshdiff.profile(V[:0], F), "V"),
    (lambda V, F: meshdiff.profile(with_nan(V, 7), F), "V"),
    (lambda V, F: meshdiff.profile(np.where(V > 0.5, np.inf, V), F), "V"),
    (lambda V, F: meshdiff.profile(V, F[:, :2]), "F"),
    (lambda V, F: meshdiff.profile(V, F.astype(float)), "F"),
    (lambda V, F: meshdiff.profile(V, F[:0]), "F"),
    (lambda V, F: meshdiff.profile(V, F + len(V)), "F"),
    (lambda V, F: meshdiff.profile(V, F - 1), "F"),
    (lambda V, F: meshdiff.profile(V, F.astype(np.uint64) + np.uint64(2 ** 63)), "F"),
    (lambda V, F: meshdiff.compare(V, F, with_nan(V, 3), F), "V2"),
    (lambda V, F: meshdiff.compare(V, F + 1, V, F), "F1"),
    (lambda V, F: meshdiff.compare(V, F, V, F[:, ::2]), "F2"),
    (lambda V, F: meshdiff.surface_distance(V[:, :1], F, V, F), "V1"),
    (lambda V, F: meshdiff.vertex_distances(V, F, V, -F), "F2"),
    (lambda V, F: meshdiff.mean_curvature(V, F * 1000), "F"),
    (lambda V, F: meshdiff.roughness(V.T, F), "V"),
    (lambda V, F: meshdiff.DistanceIndex(V, F + 5000), "F"),
    (lambda V, F: meshdiff.DistanceIndex(V, F).query(V[:, :2]), "P"),
    (lambda V, F: meshdiff.DistanceIndex(V, F).query(with_nan(V, 0)), "P"),
])
def test_bad_arrays_raise_value_error_naming_the_argument(mesh, make, name):
    V, F = mesh
    with pytest.raises(ValueError, match=rf"^{name}: "):
        make(V, F)


@pytest.mark.parametrize("options", [
    dict(levels=[0]), dict(levels="1-0"), dict(levels="a-b"), dict(levels=[], global_level=False),
    dict(curvature="nope"), dict(weighting="heavy"), dict(face_sampling="random"), dict(k=0.0), dict(k=-1.0),
    dict(samples=0), dict(samples=-5), dict(density=0.0), dict(samples=100, density=1.0),
    dict(vertex_samples=False, edge_samples=False, face_samples=False), dict(roughness=False, distance=False),
    dict(threads=-1),
])
def test_bad_options_raise_value_error(mesh, options):
    V, F = mesh
    with pytest.raises(ValueError):
        meshdiff.compare(V, F, V, F, **options)


def test_options_are_keyword_only_and_typed(mesh):
    V, F = mesh
    with pytest.raises(TypeError):
        meshdiff.compare(V, F, V, F, [1, 2])
    with pytest.raises(TypeError):
        meshdiff.compare(V, F, V, F, samples=1.5)
    with pytest.raises(TypeError, match="levels"):
        meshdiff.compare(V, F, V, F, levels=[1.5])
    with pytest.raises(TypeError, match="roughness"):
        meshdiff.compare(V, F, V, F, roughness="no")
    with pytest.raises(TypeError, match="k: expected a number"):
        meshdiff.compare(V, F, V, F, k="1e-4")
    with pytest.raises(TypeError):
        meshdiff.compare(V, F, V, F, no_such_option=1)


def test_missing_file_raises_file_not_found(tmp_path, data):
    missing = tmp_path / "missing.ply"
    with pytest.raises(FileNotFoundError) as e:
        meshdiff.read_mesh(missing)
    assert e.value.filename == str(missing)
    with pytest.raises(FileNotFoundError):
        meshdiff.compare_files(data / "fandisk.ply", missing)
    with pytest.raises(FileNotFoundError):
        meshdiff.profile_file(str(missing))


def test_unreadable_files_raise_os_error(tmp_path):
    garbage = tmp_path / "garbage.ply"
    garbage.write_bytes(b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n")
    empty = tmp_path / "empty.off"
    empty.write_bytes(b"")
    unknown = tmp_path / "mesh.xyz"
    unknown.write_text("0 0 0\n")
    for path in (garbage, empty, unknown, tmp_path):
        with pytest.raises(OSError):
            meshdiff.read_mesh(path)
    with pytest.raises(TypeError):
        meshdiff.read_mesh(3)


def test_unusable_mesh_file_raises_value_error(tmp_path):
    no_faces = tmp_path / "points.off"
    no_faces.write_text("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")
    nan = tmp_path / "nan.off"
    nan.write_text("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    for path, message in ((no_faces, "no faces"), (nan, "non-finite")):
        with pytest.raises(ValueError, match=message):
            meshdiff.read_mesh(path)


def test_hostile_input_never_crashes_the_interpreter(build_dir):
    """Odd meshes and options in a child interpreter: every call returns or
    raises a Python exception; the child exits normally."""
    code = textwrap.dedent("""
        import numpy as np, meshdiff
        tri = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float)
        cases = [
            lambda: meshdiff.profile(np.zeros((3, 3)), [[0, 1, 2]]),
            lambda: meshdiff.compare(np.zeros((3, 3)), [[0, 1, 2]], tri, [[0, 1, 2]]),
            lambda: meshdiff.surface_distance(np.zeros((3, 3)), [[0, 1, 2]], np.zeros((3, 3)), [[0, 1, 2]]),
            lambda: meshdiff.compare(tri, [[0, 1, 2]], tri, [[0, 1, 2]]),
            lambda: meshdiff.compare(tri, [[0, 1, 1]], tri, [[0, 0, 0]]),
            lambda: meshdiff.roughness(tri, [[0, 1, 2]] * 5, levels=[1, 100000]),
            lambda: meshdiff.mean_curvature(tri, [[0, 1, 2]], method="meyer"),
            lambda: meshdiff.mean_curvature(tri, [[0, 1, 2]], min_neighbors=10**9),
            lambda: meshdiff.mean_curvature(tri, [[0, 1, 2]], max_normal_angle_deg=float("nan")),
            lambda: meshdiff.DistanceIndex(tri, [[0, 1, 2]]).query(np.full((4, 3), 1e308)),
            lambda: meshdiff.surface_distance(tri, [[0, 1, 2]], tri * 1e-300, [[0, 1, 2]], samples=10**6),
            lambda: meshdiff.compare(tri, [[0, 1, 2]], tri, [[0, 1, 2]], samples=2**62),
            lambda: meshdiff.profile(np.vstack([tri, [[5, 5, 5]]]), [[0, 1, 2]], levels=range(1, 4)),
            lambda: meshdiff.read_mesh("/dev/null/x.ply"),
        ]
        for i, case in enumerate(cases):
            try:
                case()
                print(i, "ok")
            except (ValueError, OSError, RuntimeError, MemoryError, TypeError) as e:
                print(i, type(e).__name__, str(e)[:80])
        print("done")
    """)
    env = child_env()
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.rstrip().endswith("done"), r.stdout + r.stderr
