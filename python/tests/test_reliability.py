"""Issue 33, the Python cases: the array path has the file readers' limits (no
hang on huge coordinates), DistanceIndex.query is finite or refused, a failing
call leaves no output file, an empty path is refused, a cloud without extent is
an error, not NaN."""
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import meshdiff
from conftest import child_env


@pytest.fixture(scope="module")
def sphere(data):
    return meshdiff.read_mesh(data / "sphere_ico_2562.ply")


def run_isolated(code, timeout=60):
    """Runs \\p code in a child interpreter (a hang is a failed test, not a stuck run)."""
    env = child_env()
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], env=env, capture_output=True, text=True,
                          timeout=timeout)


@pytest.mark.parametrize("scale", [1e80, 1e31])
def test_huge_coordinates_are_refused_not_a_hang(data, scale):
    """2. Arrays beyond the readers' limit of 1e30 are a ValueError naming the array (1e80 hung before)."""
    r = run_isolated(f"""
        import meshdiff
        V, F = meshdiff.read_mesh({str(data / "sphere_ico_2562.ply")!r})
        for call in (lambda: meshdiff.surface_distance(V * {scale}, F, V, F),
                     lambda: meshdiff.compare(V, F, V * {scale}, F, roughness=False)):
            try:
                call()
                print("accepted")
            except ValueError as e:
                print("ValueError", e)
    """)
    lines = r.stdout.splitlines()
    assert r.returncode == 0, r.stderr
    assert len(lines) == 2 and all(l.startswith("ValueError") for l in lines), lines
    assert "V1" in lines[0] and "V2" in lines[1] and "1e+30" in lines[0]


def test_the_limit_itself_is_accepted(sphere):
    V, F = sphere
    W = V / np.abs(V).max() * 1e30
    r = meshdiff.surface_distance(W, F, W, F, samples=2000)
    assert r["hausdorff"]["lower"] == 0.0 and r["forward"]["max"] == 0.0


def test_query_far_points_finite_or_refused(sphere):
    """13. Points beyond the limit are refused; at the limit the distance is finite."""
    V, F = sphere
    index = meshdiff.DistanceIndex(V, F)
    with pytest.raises(ValueError, match="^P: "):
        index.query(np.array([[1e200, 0.0, 0.0]]))
    d, _, _ = index.query(np.array([[1e30, 0.0, 0.0]]))
    assert np.isfinite(d).all() and d[0] == pytest.approx(1e30)


def test_a_failing_call_leaves_no_output(tmp_path, data):
    """5. compare_files() with a map and a JSON into a missing folder: OSError, and no map."""
    a, b = str(data / "bunny_res3.ply"), str(data / "bunny_res4_ascii.ply")
    with pytest.raises(OSError):
        meshdiff.compare_files(a, b, roughness=False, samples=2000, distance_map=str(tmp_path / "m.ply"),
                               json=str(tmp_path / "nodir" / "x.json"))
    assert list(tmp_path.iterdir()) == []


def test_empty_paths_are_refused(data):
    """15. json="" used to mean "no JSON"; None is that, "" is refused."""
    with pytest.raises(ValueError, match="^json: "):
        meshdiff.profile_file(data / "fandisk.ply", json="")


def test_a_cloud_without_extent_is_an_error():
    """8. One point compared with itself: ValueError, as the CLI's exit 4 (was NaN or 'relative_to')."""
    P = np.array([[1.0, 2.0, 3.0]])
    with pytest.raises(ValueError, match="no extent"):
        meshdiff.compare(P, None, P, None)


def test_subnormal_coordinates_do_not_crash(data):
    """A mesh scaled to subnormal coordinates (scripts/fuzz_arrays.py trial 143): the closest-point index of
    it crashed the interpreter (SIGSEGV). As the processed mesh or a cloud's target it is measured; as the
    original it has no extent, a ValueError."""
    r = run_isolated(f"""
        import numpy as np, meshdiff
        V, F = meshdiff.read_mesh({str(data / "sphere_ico_2562.ply")!r})
        tiny = V * 5e-324
        for A, FA in [(V, None), (V, F)]:
            h = meshdiff.compare(A, FA, tiny, F, samples=3000, roughness=False)["surface_distance"]["hausdorff"]
            print(round(h["lower"], 6))
        try:
            meshdiff.compare(tiny, F, tiny, F, roughness=False)
        except ValueError as e:
            print("no extent" in str(e))
    """)
    assert r.returncode == 0, r.stderr
    radius = float(np.linalg.norm(meshdiff.read_mesh(str(data / "sphere_ico_2562.ply"))[0], axis=1).max())
    lines = r.stdout.split()
    assert [float(x) for x in lines[:2]] == [round(radius, 6)] * 2
    assert lines[2] == "True"


def test_threads_that_cannot_start_warn_not_kill(data):
    """9. Under a memory limit 1000 threads cannot all start: a RuntimeWarning and fewer threads, the same
    numbers (libgomp ended the interpreter before)."""
    r = run_isolated(f"""
        import resource, warnings, meshdiff
        V, F = meshdiff.read_mesh({str(data / "sphere_ico_2562.ply")!r})
        one = meshdiff.profile(V, F, threads=1)
        resource.setrlimit(resource.RLIMIT_AS, (3_000_000_000, 3_000_000_000))
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            many = meshdiff.profile(V, F, threads=1000)
        print(many == one, [str(x.message) for x in w])
    """)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("True ['threads: only "), r.stdout


def test_threads_beyond_the_limit(sphere):
    """9. The CLI's thread limit holds in Python (2000 threads killed the interpreter under a memory cap)."""
    V, F = sphere
    with pytest.raises(ValueError, match="^threads: "):
        meshdiff.profile(V, F, threads=meshdiff.LIMITS["threads"] + 1)
