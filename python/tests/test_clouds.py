"""Point clouds in compare() and compare_files() (issue 11): F None or an empty
(0, 3) array makes V a cloud; distances against closed forms and brute force."""
import numpy as np
import pytest

import meshdiff

SQUARE_V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
SQUARE_F = np.array([[0, 1, 2], [0, 2, 3]])
FIVE = np.array([[0.25, 0.25, 0.5], [0.75, 0.5, -0.25], [0.5, 0.5, 0.0], [2.0, 0.5, 0.0], [1.3, 1.4, 0.0]])
FIVE_D = np.array([0.5, 0.25, 0.0, 1.0, 0.5])  # their distances to the unit square


@pytest.mark.parametrize("faces", [None, np.zeros((0, 3), dtype=np.int64)])
def test_cloud_against_square(faces):
    j = meshdiff.compare(FIVE, faces, SQUARE_V, SQUARE_F)
    sd = j["surface_distance"]
    assert sd["forward"]["distance_kind"] == "point-to-surface"
    assert sd["backward"]["distance_kind"] == "surface-to-point"
    assert sd["forward"]["samples_by_kind"]["point"] == 5
    assert sd["forward"]["max"] == 1.0 and sd["forward"]["min"] == 0.0
    assert abs(sd["forward"]["mean"] - FIVE_D.mean()) < 1e-15
    assert sd["forward"]["hausdorff"]["exact_over_points"] and sd["forward"]["hausdorff"]["upper"] == 1.0
    assert j["roughness_distance"] is None and "point cloud" in j["roughness_unavailable"]
    assert j["original"]["mesh"]["point_cloud"] and j["original"]["mesh"]["path"] == "<array V1>"


def test_cloud_against_cloud_brute_force():
    rng = np.random.default_rng(3)
    A, B = rng.uniform(-1, 1, (400, 3)), rng.uniform(-1.1, 1.1, (250, 3))
    j = meshdiff.compare(A, None, B, None)["surface_distance"]
    fw = np.linalg.norm(A[:, None, :] - B[None, :, :], axis=2).min(axis=1)
    bw = np.linalg.norm(B[:, None, :] - A[None, :, :], axis=2).min(axis=1)
    assert j["forward"]["distance_kind"] == "point-to-point"
    assert j["forward"]["max"] == pytest.approx(fw.max(), rel=1e-15)
    assert j["backward"]["max"] == pytest.approx(bw.max(), rel=1e-15)
    assert j["forward"]["mean"] == pytest.approx(fw.mean(), rel=1e-13)
    assert j["chamfer"]["l1"] == pytest.approx(fw.mean() + bw.mean(), rel=1e-13)
    assert j["hausdorff"]["method"] == "certified" and j["hausdorff"]["lower"] == j["hausdorff"]["upper"]


def test_compare_files_reads_a_cloud(tmp_path):
    p = tmp_path / "five.off"
    p.write_text("OFF\n5 0 0\n" + "".join("%r %r %r\n" % tuple(x) for x in FIVE))
    q = tmp_path / "square.off"
    q.write_text("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
    j = meshdiff.compare_files(q, p)
    assert j["surface_distance"]["backward"]["distance_kind"] == "point-to-surface"
    assert j["surface_distance"]["backward"]["max"] == 1.0
    # The other functions keep refusing a faceless file.
    with pytest.raises(ValueError, match="point cloud"):
        meshdiff.profile_file(p)
