"""examples/evaluate_decimation.py runs headless on a small bundled mesh."""
import csv
import os
import shutil
import subprocess
import sys

import pytest

import meshdiff


def test_evaluation_script_writes_the_csv_and_the_plot(repo, data, build_dir, tmp_path):
    if shutil.which("OpenMesh-commandlineDecimater") is None:
        pytest.fail("OpenMesh-commandlineDecimater is missing: apt-get install libopenmesh-apps "
                    "(scripts/install-deps.sh installs it)")
    out = tmp_path / "eval"
    env = dict(os.environ, PYTHONPATH=str(build_dir / "python"), MPLBACKEND="Agg")
    env.pop("DISPLAY", None)
    r = subprocess.run([sys.executable, str(repo / "examples" / "evaluate_decimation.py"),
                        str(data / "hemisphere.ply"), "--ratios", "0.5,0.25", "--out", str(out)],
                       capture_output=True, text=True, env=env, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    with open(out / "decimation.csv", newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
    assert reader.fieldnames == ["mesh", "ratio", "vertices", "faces", "hausdorff", "hausdorff_relative", "mean",
                                 "rms", "d_1", "d_5", "d_20", "d_global", "seconds"]
    assert [(row["mesh"], float(row["ratio"])) for row in rows] == [("hemisphere", 0.5), ("hemisphere", 0.25)]
    V, F = meshdiff.read_mesh(data / "hemisphere.ply")
    faces = [int(row["faces"]) for row in rows]
    assert len(F) > faces[0] > faces[1] > 0
    for row in rows:
        values = {k: float(row[k]) for k in ("hausdorff", "mean", "rms", "d_1", "d_5", "d_20", "d_global")}
        assert all(v >= 0 for v in values.values())
        assert values["mean"] <= values["rms"] <= values["hausdorff"]
        # The row is what compare_files() gives for that decimated mesh.
        decimated = out / "meshes" / f"hemisphere_{float(row['ratio']):g}.off"
        sd = meshdiff.compare_files(data / "hemisphere.ply", decimated, roughness=False)["surface_distance"]
        assert float(row["hausdorff"]) == sd["hausdorff"]["upper"] and sd["hausdorff"]["certified"]
    png = out / "decimation.png"
    assert png.exists() and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
