"""examples/evaluate_decimators.py runs headless on a small bundled mesh, with
both decimators, and its rows are what compare() gives for the decimated meshes."""
import csv
import importlib.util
import shutil
import subprocess
import sys
import warnings

import pytest

import meshdiff
from conftest import child_env


def test_evaluation_script_writes_the_table_csv_and_plot(repo, data, tmp_path):
    if shutil.which("OpenMesh-commandlineDecimater") is None:
        pytest.fail("OpenMesh-commandlineDecimater is missing: apt-get install libopenmesh-apps "
                    "(scripts/install-deps.sh installs it)")
    out = tmp_path / "eval"
    env = child_env(MPLBACKEND="Agg")
    env.pop("DISPLAY", None)
    r = subprocess.run([sys.executable, str(repo / "examples" / "evaluate_decimators.py"),
                        str(data / "hemisphere.ply"), "--ratios", "0.5,0.25", "--out", str(out)],
                       capture_output=True, text=True, env=env, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    with open(out / "decimators.csv", newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
    assert reader.fieldnames == ["mesh", "decimator", "ratio", "vertices", "faces", "hausdorff",
                                 "hausdorff_relative", "rms", "d_r0.2", "seconds"]
    assert [(row["mesh"], row["decimator"], float(row["ratio"])) for row in rows] == [
        ("hemisphere", d, ratio) for ratio in (0.5, 0.25) for d in ("open3d", "openmesh")]
    V, F = meshdiff.read_mesh(data / "hemisphere.ply")
    for d in ("open3d", "openmesh"):
        faces = [int(row["faces"]) for row in rows if row["decimator"] == d]
        assert len(F) > faces[0] > faces[1] > 0, d
    for row in rows:
        values = {k: float(row[k]) for k in ("hausdorff", "rms", "d_r0.2")}
        assert values["hausdorff"] > 0 and 0 <= values["rms"] <= values["hausdorff"]
    # The table: one line per row, ranked by the certified Hausdorff distance within (mesh, ratio).
    lines = [line.split() for line in r.stdout.splitlines() if line.startswith("hemisphere")]
    assert len(lines) == len(rows)
    for ratio in ("0.5", "0.25"):
        ranked = [line[3] for line in lines if line[1] == ratio]
        by_h = sorted((row for row in rows if row["ratio"] == ratio), key=lambda row: float(row["hausdorff"]))
        assert ranked == [row["decimator"] for row in by_h]
    # A row is what compare() gives for that decimation (Open3D's decimation is deterministic).
    spec = importlib.util.spec_from_file_location("evaluate_decimators", repo / "examples" / "evaluate_decimators.py")
    example = importlib.util.module_from_spec(spec)
    with warnings.catch_warnings():  # the example sets a filter of its own when imported
        spec.loader.exec_module(example)
    row = rows[0]
    r = meshdiff.compare(V, F, example.decimate_open3d(V, F, 0.5), levels=[1], radii=[0.2])
    assert float(row["hausdorff"]) == r["surface_distance"]["hausdorff"]["upper"]
    assert float(row["d_r0.2"]) == r["roughness_distance"]["distance_radii"][0]
    png = out / "decimators.png"
    assert png.exists() and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
