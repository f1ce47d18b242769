"""Summary metrics (METHOD.md section 6) through compare(): closed forms on a flat fan
against a pyramid, F-score 1 of a mesh against itself, same-connectivity metrics."""
import math

import numpy as np
import pytest

import meshdiff


def pyramid(h):
    V = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], [0, 0, h]], dtype=float)
    F = np.array([[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])
    return V, F


def test_fan_against_pyramid_gives_the_surface_integrals():
    h = 0.75
    s = math.sqrt(1 + h * h)
    V1, F1 = pyramid(0.0)
    V2, F2 = pyramid(h)
    r = meshdiff.compare(V1, F1, V2, F2, roughness=False, samples=100000, fscore=[0.01, 0.05], histogram=6)
    sd = r["surface_distance"]
    assert sd["forward"]["area_weighted"]["mean"] == pytest.approx(h / (3 * s), abs=1e-12)
    assert sd["backward"]["area_weighted"]["mean"] == pytest.approx(h / 3, abs=1e-12)
    assert sd["chamfer"]["l1"] == pytest.approx(h / (3 * s) + h / 3, abs=1e-12)
    assert sd["chamfer"]["l2"] == pytest.approx(h * h / (6 * s * s) + h * h / 6, rel=1e-2)
    # PSNR by hand: peak = diagonal 2 sqrt(2), factor 3, e = h^2 / 6 (backward) and h^2 (the apex).
    assert sd["psnr"]["mse_db"] == pytest.approx(10 * math.log10(3 * 8 / (h * h / 6)), abs=0.05)
    assert sd["psnr"]["hausdorff_db"] == pytest.approx(10 * math.log10(3 * 8 / (h * h)), abs=1e-9)
    assert [f["threshold"] for f in sd["fscore"]] == [0.01, 0.05]
    assert len(sd["forward"]["histogram"]["counts"]) == 6
    assert sum(sd["backward"]["histogram"]["counts"]) == sd["backward"]["samples"]
    sc = r["same_connectivity"]
    assert sc["displacement"]["max"] == pytest.approx(h, abs=1e-15)
    assert sc["normal_deviation_deg"]["rms"] == pytest.approx(math.degrees(math.atan(h)), abs=1e-12)
    assert r["same_connectivity_unavailable"] is None


def test_mesh_against_itself_has_fscore_one(data):
    V, F = meshdiff.read_mesh(data / "bunny_res3.ply")
    r = meshdiff.compare(V, F, V, F, roughness=False, fscore=[0.001, 0.005])
    assert [f["fscore"] for f in r["surface_distance"]["fscore"]] == [1.0, 1.0]
    assert r["same_connectivity"]["displacement"]["max"] == 0.0


def test_compare_files_matches_the_cli_fields(data):
    r = meshdiff.compare_files(data / "bunny_res3.ply", data / "bunny_res4_ascii.ply", roughness=False,
                               samples=50000, fscore=[0.01])
    assert r["same_connectivity"] is None
    assert r["same_connectivity_unavailable"].startswith("vertex counts differ")
    assert r["surface_distance"]["fscore"][0]["fscore"] > 0


@pytest.mark.parametrize("kwargs", [{"fscore": [0.0]}, {"fscore": [float("nan")]}, {"histogram": -1}])
def test_bad_summary_options_raise(kwargs):
    V, F = pyramid(0.5)
    with pytest.raises(ValueError):
        meshdiff.compare(V, F, V, F, roughness=False, **kwargs)


def test_plot_histogram_draws_both_directions(cli, tmp_path):
    pytest.importorskip("matplotlib")
    import pathlib
    import subprocess
    import sys

    repo = pathlib.Path(__file__).resolve().parents[2]
    for name, h in (("fan", 0.0), ("pyr", 0.5)):
        V, F = pyramid(h)
        with open(tmp_path / f"{name}.ply", "w") as f:
            f.write("ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
                    "element face 4\nproperty list uchar int vertex_indices\nend_header\n")
            f.writelines("%r %r %r\n" % tuple(v) for v in V)
            f.writelines("3 %d %d %d\n" % tuple(t) for t in F)
    report = tmp_path / "c.json"
    subprocess.run([cli, str(tmp_path / "fan.ply"), str(tmp_path / "pyr.ply"), "--no-roughness", "-n", "20000",
                    "--histogram", "12", "--json", str(report)], check=True)
    out = tmp_path / "h.png"
    subprocess.run([sys.executable, str(repo / "reference" / "plot_histogram.py"), str(out), str(report), "--relative"],
                   check=True)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # Without --histogram the script says what is missing.
    subprocess.run([cli, str(tmp_path / "fan.ply"), str(tmp_path / "pyr.ply"), "--no-roughness", "-n", "20000",
                    "--json", str(report)], check=True)
    r = subprocess.run([sys.executable, str(repo / "reference" / "plot_histogram.py"), str(out), str(report)],
                       capture_output=True, text=True)
    assert r.returncode != 0 and "--histogram" in r.stderr
