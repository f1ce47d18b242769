"""DistanceIndex, vertex_distances and surface_distance(return_samples=True)
against a brute-force numpy oracle."""
import numpy as np
import pytest

import meshdiff


def brute_force_distance(P, V, F):
    """Distance of each point of P to the closest triangle of (V, F): the
    minimum over all triangles of the distance to the triangle's plane (when the
    projection is inside) and to its three edges."""
    A, B, C = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    out = np.empty(len(P))
    for i, p in enumerate(P):
        best = np.full(len(F), np.inf)
        for a, b in ((A, B), (B, C), (C, A)):
            ab = b - a
            t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.einsum("ij,ij->i", ab, ab), 0.0, 1.0)
            best = np.minimum(best, np.linalg.norm(p - (a + t[:, None] * ab), axis=1))
        n = np.cross(B - A, C - A)
        n /= np.linalg.norm(n, axis=1)[:, None]
        h = np.einsum("ij,ij->i", p - A, n)
        q = p - h[:, None] * n
        inside = np.ones(len(F), dtype=bool)
        for a, b in ((A, B), (B, C), (C, A)):
            inside &= np.einsum("ij,ij->i", np.cross(b - a, q - a), n) >= 0
        best = np.where(inside, np.minimum(best, np.abs(h)), best)
        out[i] = best.min()
    return out


@pytest.fixture(scope="module")
def bunny(data):
    return meshdiff.read_mesh(data / "bunny_res4_ascii.ply")


def test_query_agrees_with_brute_force_on_random_points(bunny):
    V, F = bunny
    rng = np.random.default_rng(12)
    lo, hi = V.min(axis=0), V.max(axis=0)
    span = hi - lo
    # Inside and around the box, and a few far away.
    P = np.vstack([rng.uniform(lo - 0.2 * span, hi + 0.2 * span, size=(300, 3)),
                   rng.uniform(-10, 10, size=(20, 3)),
                   V[rng.integers(0, len(V), 20)]])
    index = meshdiff.DistanceIndex(V, F)
    assert index.n_faces == len(F)
    distance, face, closest = index.query(P)
    assert distance.shape == (len(P),) and face.shape == (len(P),) and closest.shape == (len(P), 3)
    assert distance.dtype == np.float64 and face.dtype == np.int64
    expected = brute_force_distance(P, V, F)
    np.testing.assert_allclose(distance, expected, rtol=1e-9, atol=1e-15)
    # The closest point is at that distance and on the reported face.
    np.testing.assert_allclose(np.linalg.norm(P - closest, axis=1), distance, rtol=1e-9, atol=1e-15)
    for i in range(0, len(P), 17):
        d = brute_force_distance(closest[i:i + 1], V, F[face[i]:face[i] + 1])[0]
        assert d <= 1e-12 * (1 + np.abs(closest[i]).max())
    # Vertices of the mesh are at distance 0.
    assert np.all(distance[-20:] == 0.0)
    # Thread count does not change the result.
    d1, f1, c1 = index.query(P, threads=1)
    assert np.array_equal(d1, distance) and np.array_equal(f1, face) and np.array_equal(c1, closest)


def test_query_takes_float32_and_empty_input(bunny):
    V, F = bunny
    index = meshdiff.DistanceIndex(V.astype(np.float32), F)
    d, f, c = index.query(np.zeros((0, 3), dtype=np.float32))
    assert d.shape == (0,) and f.shape == (0,) and c.shape == (0, 3)
    lo, hi = index.bounds
    np.testing.assert_array_equal(lo, V.astype(np.float32).astype(np.float64).min(axis=0))
    assert index.memory_bytes > 0
    assert "DistanceIndex" in repr(index)


def test_vertex_distances_are_the_query_of_the_vertices(bunny, data):
    V1, F1 = bunny
    V2, F2 = meshdiff.read_mesh(data / "bunny_res3.ply")
    d = meshdiff.vertex_distances(V1, F1, V2, F2)
    assert d.shape == (len(V1),)
    assert np.array_equal(d, meshdiff.DistanceIndex(V2, F2).query(V1)[0])
    np.testing.assert_allclose(d[::9], brute_force_distance(V1[::9], V2, F2), rtol=1e-9, atol=1e-15)


def test_surface_distance_samples_are_those_of_the_statistics(bunny, data):
    V1, F1 = bunny
    V2, F2 = meshdiff.read_mesh(data / "bunny_res3.ply")
    plain = meshdiff.surface_distance(V1, F1, V2, F2)
    r = meshdiff.surface_distance(V1, F1, V2, F2, return_samples=True)
    for direction, (Va, Fa, Vb, Fb) in (("forward", (V1, F1, V2, F2)), ("backward", (V2, F2, V1, F1))):
        s = r[direction]
        stats = {k: v for k, v in s.items()
                 if k not in ("points", "distances", "signed_distances", "kinds", "elements")}
        assert stats == plain[direction]
        n = s["samples"]
        assert s["points"].shape == (n, 3) and s["distances"].shape == (n,)
        assert s["kinds"].dtype == np.uint8 and s["elements"].dtype == np.int64
        # The statistics come from these distances.
        assert s["distances"].max() == s["max"] and s["distances"].min() == s["min"]
        ordered = np.sort(s["distances"])
        assert ordered[int(np.ceil(0.95 * n)) - 1] == s["p95"]
        np.testing.assert_allclose(np.sqrt(np.mean(s["distances"] ** 2)), s["rms"], rtol=1e-12)
        counts = np.bincount(s["kinds"], minlength=len(meshdiff.SAMPLE_KINDS))
        by_kind = s["samples_by_kind"]
        assert list(counts) == [by_kind[k] for k in meshdiff.SAMPLE_KINDS]
        # Samples lie on the first surface of the direction; distances are to the other.
        assert np.all(s["points"][s["kinds"] == 0] == Va[s["elements"][s["kinds"] == 0]])
        pick = np.arange(0, n, 97)
        np.testing.assert_allclose(s["distances"][pick], brute_force_distance(s["points"][pick], Vb, Fb),
                                   rtol=1e-9, atol=1e-15)
        assert np.all(brute_force_distance(s["points"][pick[:30]], Va, Fa) < 1e-12)
    assert r["sampled_hausdorff"] == plain["sampled_hausdorff"] == max(r["forward"]["max"], r["backward"]["max"])
    assert r["hausdorff"]["method"] == "sampled" and r["forward"]["hausdorff"] is None
    assert r["forward_is"].startswith("samples on the original")


def test_compare_certifies_the_hausdorff_distance(data):
    # A flat square against the same square with its centre raised by 0.3: the
    # backward Hausdorff distance is 0.3 exactly (at the apex).
    V = np.array([[0, 0, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], [-1, -1, 0]], dtype=float)
    F = np.array([[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]])
    W = V.copy()
    W[0, 2] = 0.3
    sd = meshdiff.compare(V, F, W, F, roughness=False, hausdorff_tolerance=1e-9)["surface_distance"]
    h = sd["hausdorff"]
    assert h["method"] == "certified" and h["certified"]
    assert h["lower"] <= 0.3 <= h["upper"] and h["upper"] - h["lower"] <= 1e-9 * 0.3 + 1e-15
    assert h["attained"] == "backward"
    np.testing.assert_allclose(sd["backward"]["hausdorff"]["location"]["point"], [0, 0, 0.3], atol=1e-12)
    assert sd["forward"]["hausdorff"]["lower"] == pytest.approx(0.3 / np.sqrt(1.09), rel=1e-9)
    absolute = meshdiff.compare(V, F, W, F, roughness=False, hausdorff_abs_tolerance=1e-6)["surface_distance"]
    assert absolute["backward"]["hausdorff"]["tolerance"] == 1e-6
    sampled = meshdiff.compare(V, F, W, F, roughness=False, hausdorff="sampled")["surface_distance"]
    assert sampled["hausdorff"]["method"] == "sampled" and sampled["hausdorff"]["upper"] is None
    assert sampled["forward"]["hausdorff"] is None
    for bad in ({"hausdorff": "exact"}, {"hausdorff_tolerance": 0.0}, {"hausdorff_abs_tolerance": -1.0}):
        with pytest.raises(ValueError):
            meshdiff.compare(V, F, W, F, roughness=False, **bad)


def test_surface_distance_signed_samples_and_statistics():
    """A small sphere inside a big one: signed = -distance forward, +distance backward; an open target gives None."""
    def sphere(r, n=24):
        t = np.linspace(0, np.pi, n // 2 + 1)[1:-1]
        p = np.linspace(0, 2 * np.pi, n, endpoint=False)
        V = [[0, 0, r]] + [[r * np.sin(a) * np.cos(b), r * np.sin(a) * np.sin(b), r * np.cos(a)] for a in t for b in p]
        V.append([0, 0, -r])
        F = [(0, 1 + i, 1 + (i + 1) % n) for i in range(n)]
        for k in range(len(t) - 1):
            for i in range(n):
                a, b = 1 + k * n + i, 1 + k * n + (i + 1) % n
                F += [(a, a + n, b), (b, a + n, b + n)]
        last = len(V) - 1
        F += [(last, last - n + (i + 1) % n, last - n + i) for i in range(n)]
        return np.array(V, dtype=float), np.array(F, dtype=np.int32)
    V1, F1 = sphere(0.5)
    V2, F2 = sphere(1.0)
    r = meshdiff.surface_distance(V1, F1, V2, F2, return_samples=True)
    fw, bw = r["forward"], r["backward"]
    assert r["sign"] == "positive outside"
    np.testing.assert_array_equal(fw["signed_distances"], -fw["distances"])
    np.testing.assert_array_equal(bw["signed_distances"], bw["distances"])
    assert fw["signed"]["max"] == -fw["min"] and fw["signed"]["min"] == -fw["max"]
    assert fw["signed"]["mean"] == -fw["mean"] and bw["signed"]["mean"] == bw["mean"]
    assert fw["signed_unavailable"] is None
    # Open target: the sphere without its first cap triangle.
    r = meshdiff.surface_distance(V1, F1, V2, F2[1:], return_samples=True)
    assert r["forward"]["signed"] is None and r["forward"]["signed_distances"] is None
    assert r["forward"]["signed_unavailable"].startswith("the processed mesh has 3 boundary edges")
    assert r["backward"]["signed"] is not None
