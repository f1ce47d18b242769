"""Per-vertex roughness and curvature: roughness() reproduces the profile's sigma."""
import math

import numpy as np
import pytest

import meshdiff


def sequential_rms(column):
    """sqrt(mean of d^2 over the non-NaN entries), summed in vertex order as the library does."""
    total, n = 0.0, 0
    for d in column:
        if not math.isnan(d):
            total += d * d
            n += 1
    return math.sqrt(total / n)


@pytest.mark.parametrize("mesh", ["fandisk.ply", "bunny_res3.ply", "hemisphere.ply"])
def test_per_vertex_roughness_reproduces_sigma(data, mesh):
    V, F = meshdiff.read_mesh(data / mesh)
    levels = [1, 2, 5, 20]
    D, sigma = meshdiff.roughness(V, F, levels=levels)
    assert D.shape == (len(V), len(levels)) and sigma.shape == (len(levels),)
    for j in range(len(levels)):
        # The ring levels' sums are compensated and in batch order (issue 30,
        # lever 5): the plain sum in vertex order agrees to its own rounding.
        assert sequential_rms(D[:, j]) == pytest.approx(sigma[j], rel=1e-13)
    np.testing.assert_allclose(np.sqrt(np.nanmean(D ** 2, axis=0)), sigma, rtol=1e-12)
    # The same sigma as the profile, bit for bit; the global level as a last column.
    p = meshdiff.profile(V, F, levels=levels)
    assert list(sigma) == p["sigma"]
    Dg, sg = meshdiff.roughness(V, F, levels=levels, global_level=True)
    assert Dg.shape == (len(V), len(levels) + 1)
    assert np.array_equal(Dg[:, :-1], D, equal_nan=True)
    assert sg[-1] == p["sigma_global"] and sequential_rms(Dg[:, -1]) == sg[-1]
    # Vertices without a defined D are NaN, as many as the profile leaves out.
    used = [d["vertices_used"] for d in p["level_details"]]
    assert list(np.sum(~np.isnan(D), axis=0)) == used


def test_mean_curvature_sign_and_units(data):
    V, F = meshdiff.read_mesh(data / "sphere_ico_2562.ply")
    for radius in (1.0, 2.5):
        H = meshdiff.mean_curvature(V * radius, F)
        assert H.shape == (len(V),) and H.dtype == np.float64
        # Convex with outward normals: positive, 1 / radius in the mesh's unit.
        np.testing.assert_allclose(H, 1.0 / radius, rtol=0.02)
    inverted = meshdiff.mean_curvature(V, F[:, ::-1])
    np.testing.assert_allclose(inverted, -meshdiff.mean_curvature(V, F), rtol=1e-9)
    meyer = meshdiff.mean_curvature(V, F, method="meyer")
    np.testing.assert_allclose(meyer, 1.0, rtol=0.02)


def test_undefined_curvature_is_nan(data):
    V, F = meshdiff.read_mesh(data / "hemisphere.ply")
    meyer = meshdiff.mean_curvature(V, F, method="meyer")
    assert np.isnan(meyer).any() and not np.isnan(meyer).all()  # boundary vertices
    # An isolated vertex added to the array has no curvature and no D.
    V2 = np.vstack([V, [[3.0, 3.0, 3.0]]])
    assert np.isnan(meshdiff.mean_curvature(V2, F)[-1])
    D, _ = meshdiff.roughness(V2, F, levels=[1])
    assert np.isnan(D[-1, 0])
