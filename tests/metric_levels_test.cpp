#include "meshdiff/roughness/metric_levels.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/roughness/roughness.h"
#include "meshdiff/roughness/roughness_distance.h"
#include "meshdiff/studies/shapes.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <random>
#include <string>

using namespace meshdiff;

namespace {

// Brute force, straight from the definition: the vertices inside the closed
// ball, then the component of the centre among them by relaxing every face
// edge until nothing changes. O(n * faces) per centre.
std::vector<std::uint32_t> brute_patch(const Mesh& mesh, std::size_t v, double r)
{
    const std::size_t n = mesh.n_vertices();
    std::vector<char> inside(n), reached(n, 0);
    for (std::size_t j = 0; j < n; ++j) inside[j] = (mesh.points[j] - mesh.points[v]).squaredNorm() <= r * r;
    reached[v] = 1;
    for (bool changed = true; changed;) {
        changed = false;
        for (const Face& f : mesh.faces)
            for (int k = 0; k < 3; ++k) {
                const auto a = std::size_t(f[std::size_t(k)]), b = std::size_t(f[std::size_t((k + 1) % 3)]);
                if (inside[a] && inside[b] && reached[a] != reached[b]) {
                    reached[a] = reached[b] = 1;
                    changed = true;
                }
            }
    }
    std::vector<std::uint32_t> ids;
    for (std::size_t j = 0; j < n; ++j)
        if (j != v && reached[j]) ids.push_back(std::uint32_t(j));
    return ids;
}

// A strip folded into a U: flat at z = 0 for s in [0, 1], a half circle of
// radius h, then flat again at z = 2h going back. A ball on the lower sheet
// holds upper-sheet vertices that only the bend joins to the centre.
Mesh folded_strip(int ns, int nw, double h)
{
    Mesh m;
    const double len = 2.0 + M_PI * h;
    for (int j = 0; j < nw; ++j)
        for (int i = 0; i < ns; ++i) {
            const double s = len * i / (ns - 1), y = 0.5 * j / (nw - 1);
            Vec3 p;
            if (s <= 1.0) {
                p = Vec3(s, y, 0.0);
            } else if (s <= 1.0 + M_PI * h) {
                const double a = (s - 1.0) / h;
                p = Vec3(1.0 + h * std::sin(a), y, h - h * std::cos(a));
            } else {
                p = Vec3(1.0 - (s - 1.0 - M_PI * h), y, 2.0 * h);
            }
            m.points.push_back(p);
        }
    for (int j = 0; j + 1 < nw; ++j)
        for (int i = 0; i + 1 < ns; ++i) {
            const int a = j * ns + i, b = a + 1, c = a + ns, d = c + 1;
            m.faces.push_back({a, b, d});
            m.faces.push_back({a, d, c});
        }
    return m;
}

// Two separate components: a sphere and a small one beside it.
Mesh two_spheres()
{
    Mesh a = icosphere(2).mesh;
    const Mesh b = icosphere(1, 0.3).mesh;
    const auto off = std::int32_t(a.points.size());
    for (const Vec3& p : b.points) a.points.push_back(p + Vec3(1.5, 0, 0));
    for (Face f : b.faces) a.faces.push_back({f[0] + off, f[1] + off, f[2] + off});
    return a;
}

// The same by union-find over the face edges whose ends are both inside the
// ball: O(faces) per centre, for the larger meshes.
std::vector<std::uint32_t> brute_patch_uf(const Mesh& mesh, std::size_t v, double r)
{
    const std::size_t n = mesh.n_vertices();
    std::vector<char> inside(n);
    for (std::size_t j = 0; j < n; ++j) inside[j] = (mesh.points[j] - mesh.points[v]).squaredNorm() <= r * r;
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](std::size_t a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    };
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const auto a = std::size_t(f[std::size_t(k)]), b = std::size_t(f[std::size_t((k + 1) % 3)]);
            if (inside[a] && inside[b]) parent[root(a)] = root(b);
        }
    std::vector<std::uint32_t> ids;
    const std::size_t rv = root(v);
    for (std::size_t j = 0; j < n; ++j)
        if (j != v && inside[j] && root(j) == rv) ids.push_back(std::uint32_t(j));
    return ids;
}

double rel(double a, double b)
{
    return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

}  // namespace

TEST(MetricLevels, DefaultRadiiAreGeometricAndPositive)
{
    const auto r = default_radii();
    ASSERT_GE(r.size(), 2u);
    for (std::size_t k = 1; k < r.size(); ++k) EXPECT_NEAR(r[k] / r[k - 1], std::sqrt(2.0), 1e-12);
    EXPECT_NO_THROW(check_radii(r));
}

TEST(MetricLevels, CheckRadiiRejectsBadValues)
{
    for (double bad : {0.0, -1.0, std::nan(""), double(INFINITY)})
        EXPECT_THROW(check_radii({0.1, bad}), InvalidArgumentError) << bad;
    ProfileOptions o;
    o.radii = {0.1, -0.2};
    EXPECT_THROW(roughness_profile(icosphere(1).mesh, o), InvalidArgumentError);
}

TEST(MetricLevels, VertexAreasSumToSurfaceArea)
{
    const Mesh m = torus_irregular(2000, 1.0, 0.3, 5).mesh;
    const auto a = vertex_areas(m);
    EXPECT_NEAR(std::accumulate(a.begin(), a.end(), 0.0), surface_area(m), 1e-12 * surface_area(m));
    Mesh d = m;
    d.faces.push_back({0, 0, 1});  // repeated corner: contributes nothing
    d.faces.push_back({0, 1, 1});
    EXPECT_EQ(vertex_areas(d), a);
}

TEST(MetricLevels, PatchEqualsBruteForce)
{
    const std::vector<Mesh> meshes = {folded_strip(40, 5, 0.08), noisy_sphere(2, 0.2, 3).mesh, two_spheres(),
                                      torus_irregular(300, 1.0, 0.25, 2).mesh};
    for (std::size_t im = 0; im < meshes.size(); ++im) {
        const Mesh& m = meshes[im];
        const Adjacency adj = vertex_adjacency(m);
        for (double r : {0.01, 0.12, 0.2, 0.35, 0.7, 10.0})
            for (std::size_t v = 0; v < m.n_vertices(); v += 3)
                ASSERT_EQ(ball_patch(m, adj, v, r), brute_patch(m, v, r)) << "mesh " << im << " r " << r << " v " << v;
    }
}

TEST(MetricLevels, FoldIsNotJoinedThroughTheAir)
{
    // Vertex 10 on the lower sheet, at s = 0.51; the upper sheet 0.16 above it.
    const Mesh m = folded_strip(40, 5, 0.08);
    const Adjacency adj = vertex_adjacency(m);
    const std::size_t v = 2 * 40 + 10;
    const auto patch = ball_patch(m, adj, v, 0.3);
    bool upper_in_ball = false;
    for (std::size_t j = 0; j < m.n_vertices(); ++j)
        if (m.points[j].z() > 0.1 && (m.points[j] - m.points[v]).norm() <= 0.3) upper_in_ball = true;
    ASSERT_TRUE(upper_in_ball);
    for (auto j : patch) EXPECT_LT(m.points[j].z(), 0.1) << j;
    // Larger than the mesh: the whole component but the centre.
    EXPECT_EQ(ball_patch(m, adj, v, 100.0).size(), m.n_vertices() - 1);
    const Mesh two = two_spheres();
    EXPECT_EQ(ball_patch(two, vertex_adjacency(two), 0, 100.0).size(), icosphere(2).mesh.n_vertices() - 1);
}

TEST(MetricLevels, MeansEqualBruteForceAtEveryRadius)
{
    const std::vector<Mesh> meshes = {folded_strip(40, 5, 0.08), noisy_sphere(2, 0.2, 3).mesh, two_spheres()};
    const std::vector<double> radii = {0.35, 0.05, 0.12, 0.35, 0.2, 3.0};  // any order, a duplicate
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (std::size_t im = 0; im < meshes.size(); ++im) {
        const Mesh& m = meshes[im];
        const std::size_t n = m.n_vertices();
        std::vector<double> x(n), w(n);
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = i % 7 == 3 ? std::nan("") : U(rng);
            w[i] = 0.5 + 0.5 * U(rng);
        }
        const BallMeans bm = ball_means(m, vertex_adjacency(m), x, w, radii, true);
        ASSERT_EQ(bm.mean.size(), radii.size());
        for (std::size_t k = 0; k < radii.size(); ++k)
            for (std::size_t v = 0; v < n; ++v) {
                if (std::isnan(x[v])) {
                    EXPECT_TRUE(std::isnan(bm.mean[k][v]));
                    continue;
                }
                const auto patch = brute_patch(m, v, radii[k]);
                EXPECT_EQ(bm.size[k][v], patch.size());
                double s = 0, ws = 0;
                for (auto j : patch)
                    if (!std::isnan(x[j])) {
                        s += w[j] * x[j];
                        ws += w[j];
                    }
                if (ws == 0.0) {
                    EXPECT_TRUE(std::isnan(bm.mean[k][v])) << im << " " << k << " " << v;
                } else {
                    EXPECT_NEAR(bm.mean[k][v], s / ws, 1e-12) << im << " " << k << " " << v;
                }
            }
    }
}

TEST(MetricLevels, BatchedMeansEqualBruteForceAndIgnoreThreads)
{
    // Meshes of several batches of 128 centres, balls spanning several
    // batches, folds, two components, undefined values; every centre.
    const std::vector<Mesh> meshes = {folded_strip(120, 12, 0.05), noisy_sphere(4, 0.1, 5).mesh, two_spheres(),
                                      torus_irregular(2500, 1.0, 0.25, 7).mesh};
    const std::vector<double> radii = {0.4, 0.03, 0.1, 0.2, 0.1, 0.06, 5.0};
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    const int threads = omp_get_max_threads();
    for (std::size_t im = 0; im < meshes.size(); ++im) {
        const Mesh& m = meshes[im];
        const std::size_t n = m.n_vertices();
        std::vector<double> x(n), w(n);
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = i % 11 == 5 ? std::nan("") : U(rng);
            w[i] = 0.5 + 0.5 * U(rng);
        }
        const Adjacency adj = vertex_adjacency(m);
        omp_set_num_threads(1);
        const BallMeans one = ball_means(m, adj, x, w, radii, true);
        omp_set_num_threads(std::max(threads, 3));
        const BallMeans bm = ball_means(m, adj, x, w, radii, true);
        omp_set_num_threads(threads);
        for (std::size_t k = 0; k < radii.size(); ++k)
            for (std::size_t v = 0; v < n; ++v) {
                // Bitwise the same for any thread count (NaN == NaN here).
                ASSERT_TRUE(std::memcmp(&one.mean[k][v], &bm.mean[k][v], sizeof(double)) == 0) << im << " " << k;
                ASSERT_EQ(one.size[k][v], bm.size[k][v]);
                if (std::isnan(x[v])) {
                    EXPECT_TRUE(std::isnan(bm.mean[k][v]));
                    continue;
                }
                const auto patch = brute_patch_uf(m, v, radii[k]);
                ASSERT_EQ(bm.size[k][v], patch.size()) << im << " " << k << " " << v;
                double s = 0, ws = 0;
                for (auto j : patch)
                    if (!std::isnan(x[j])) {
                        s += w[j] * x[j];
                        ws += w[j];
                    }
                if (ws == 0.0) {
                    EXPECT_TRUE(std::isnan(bm.mean[k][v])) << im << " " << k << " " << v;
                } else {
                    ASSERT_NEAR(bm.mean[k][v], s / ws, 1e-12) << im << " " << k << " " << v;
                }
            }
    }
    // The union-find brute force agrees with the relaxation one.
    const Mesh f = folded_strip(40, 5, 0.08);
    for (std::size_t v = 0; v < f.n_vertices(); v += 7) EXPECT_EQ(brute_patch_uf(f, v, 0.3), brute_patch(f, v, 0.3));
}

TEST(MetricLevels, HexagonFanExactValues)
{
    // Regular hexagon of side 1: centre H = 1, rim H = 0. Normalisation: s =
    // 6/7, so the rim is 7/6 from the centre and two apart rim vertices 7/6
    // sqrt(3) > 1.5 apart. Areas: centre sqrt(3)/2, rim sqrt(3)/6.
    Mesh m;
    m.points.push_back(Vec3::Zero());
    for (int k = 0; k < 6; ++k) m.points.push_back(Vec3(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0));
    for (int k = 0; k < 6; ++k) m.faces.push_back({0, 1 + k, 1 + (k + 1) % 6});
    std::vector<double> H(7, 0.0);
    H[0] = 1.0;
    ProfileOptions o;
    o.levels = {};
    o.global = false;
    o.radii = {1.5, 3.0, 0.5};
    const auto p = roughness_profile_from_curvature(m, H, o);
    ASSERT_EQ(p.radii.size(), 3u);
    const double s = 6.0 / 7.0;
    // r = 1.5: rim D = -(1/2) / (1/2 + 2/6) = -0.6.
    EXPECT_NEAR(p.radii[0].sigma, s * std::sqrt((0.5 + 0.36) / 1.5), 1e-15);
    EXPECT_EQ(p.radii[0].vertices_used, 7u);
    EXPECT_DOUBLE_EQ(p.radii[0].radius, 1.5);
    EXPECT_EQ(p.radii[0].level, 0);
    // r = 3 (the whole mesh): rim D = -(1/2) / (1/2 + 5/6) = -0.375.
    EXPECT_NEAR(p.radii[1].sigma, s * std::sqrt((0.5 + 0.140625) / 1.5), 1e-15);
    // r = 0.5 < every edge: nobody has a neighbourhood.
    EXPECT_EQ(p.radii[2].sigma, 0.0);
    EXPECT_EQ(p.radii[2].vertices_used, 0u);
    EXPECT_EQ(p.radii[2].no_neighborhood, 7u);
    EXPECT_TRUE(p.levels.empty());
    EXPECT_FALSE(p.has_global);
}

TEST(MetricLevels, PlaneIsZero)
{
    const Shape g = plane_grid(30, 30, 0.1);
    ProfileOptions o;
    o.radii = default_radii();
    const auto est = roughness_profile(g.mesh, o);
    for (const auto& l : est.radii) EXPECT_EQ(l.sigma, 0.0) << l.radius;
    // A linear field: the ball of an interior vertex is point-symmetric on
    // this grid, with equal areas, so D = 0 wherever the ball stays inside.
    std::vector<double> H(g.mesh.n_vertices());
    for (std::size_t i = 0; i < H.size(); ++i) H[i] = 3.0 * g.mesh.points[i].x() - g.mesh.points[i].y();
    o.radii = {0.1, 0.3};
    o.keep_vertex_data = true;
    const auto lin = roughness_profile_from_curvature(g.mesh, H, o);
    const Mesh unit = apply_normalization(g.mesh, lin.normalization);
    for (std::size_t k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < H.size(); ++i) {
            const Vec3& p = unit.points[i];
            const double half = 1.45 / lin.normalization.scale;  // half-width of the grid, unit scale
            if (std::abs(p.x()) + o.radii[k] < half - 1e-9 && std::abs(p.y()) + o.radii[k] < half - 1e-9) {
                EXPECT_NEAR(lin.D_radii[k][i], 0.0, 1e-12) << k << " " << i;
            }
        }
}

TEST(MetricLevels, SphereIsZero)
{
    for (const Shape& s : {icosphere(4), geodesic_sphere(13, 2.5), uv_sphere(40, 20)}) {
        ProfileOptions o;
        o.radii = default_radii();
        o.radii.push_back(0.3);
        const auto p = roughness_profile_from_curvature(s.mesh, s.exact_H, o);
        for (const auto& l : p.radii) {
            EXPECT_LT(l.sigma, 1e-14) << l.radius;
            EXPECT_EQ(l.vertices_used + l.no_neighborhood, s.mesh.n_vertices());
        }
        EXPECT_EQ(p.radii.back().vertices_used, s.mesh.n_vertices());  // 0.3: more than an edge everywhere
    }
}

TEST(MetricLevels, ResolutionInvariantWhereRingsAreNot)
{
    // The exact H of an irregular torus at three resolutions (mean edge 0.08,
    // 0.04, 0.02 on the unit-scaled mesh): the metric profile converges once
    // the radius spans a few edges, the ring profile follows the edge length.
    // Measured: sigma_0.2 = 0.0263, 0.0254, 0.0243; sigma_0.4 = 0.0992,
    // 0.0993, 0.0998; ring 5: 0.115, 0.032, 0.0097.
    ProfileOptions o;
    o.levels = {5};
    o.global = false;
    o.radii = {0.2, 0.3, 0.4};
    std::vector<RoughnessProfile> p;
    for (std::size_t n : {2000u, 8000u, 32000u}) {
        const Shape t = torus_irregular(n, 1.0, 0.3, 7);
        p.push_back(roughness_profile_from_curvature(t.mesh, t.exact_H, o));
    }
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_LT(rel(p[1].radii[k].sigma, p[2].radii[k].sigma), 0.05) << o.radii[k];
        if (k > 0) {
            EXPECT_LT(rel(p[0].radii[k].sigma, p[2].radii[k].sigma), 0.04) << o.radii[k];
        }
    }
    EXPECT_LT(rel(p[0].radii[2].sigma, p[2].radii[2].sigma), 0.01);
    EXPECT_GT(rel(p[0].levels[0].sigma, p[2].levels[0].sigma), 5.0);
    EXPECT_GT(rel(p[1].levels[0].sigma, p[2].levels[0].sigma), 1.5);
}

TEST(MetricLevels, InvariantToVertexOrderScaleAndThreads)
{
    const Shape t = torus_irregular(3000, 1.0, 0.3, 9);
    ProfileOptions o;
    o.levels = {};
    o.radii = {0.15, 0.3, 0.6};
    const auto ref = roughness_profile_from_curvature(t.mesh, t.exact_H, o);

    // Permuted vertices.
    const std::size_t n = t.mesh.n_vertices();
    std::vector<std::size_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), std::mt19937(4));  // new id of old vertex i: perm[i]
    Mesh pm;
    pm.points.resize(n);
    std::vector<double> pH(n);
    for (std::size_t i = 0; i < n; ++i) {
        pm.points[perm[i]] = t.mesh.points[i];
        pH[perm[i]] = t.exact_H[i];
    }
    for (Face f : t.mesh.faces)
        pm.faces.push_back({std::int32_t(perm[std::size_t(f[1])]), std::int32_t(perm[std::size_t(f[2])]),
                            std::int32_t(perm[std::size_t(f[0])])});
    const auto permuted = roughness_profile_from_curvature(pm, pH, o);

    // Scaled and moved (H scales by 1 / scale).
    Mesh sm = t.mesh;
    for (Vec3& p : sm.points) p = 7.3 * p + Vec3(1, -2, 3);
    std::vector<double> sH(t.exact_H);
    for (double& h : sH) h /= 7.3;
    const auto scaled = roughness_profile_from_curvature(sm, sH, o);

    // One thread against several.
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const auto one = roughness_profile_from_curvature(t.mesh, t.exact_H, o);
    omp_set_num_threads(std::max(threads, 3));
    const auto many = roughness_profile_from_curvature(t.mesh, t.exact_H, o);
    omp_set_num_threads(threads);

    ASSERT_EQ(ref.radii.size(), o.radii.size());
    for (std::size_t k = 0; k < o.radii.size(); ++k) {
        EXPECT_GT(ref.radii[k].sigma, 0.0);
        EXPECT_NEAR(permuted.radii[k].sigma, ref.radii[k].sigma, 1e-12 * ref.radii[k].sigma) << k;
        EXPECT_NEAR(scaled.radii[k].sigma, ref.radii[k].sigma, 1e-10 * ref.radii[k].sigma) << k;
        EXPECT_EQ(one.radii[k].sigma, ref.radii[k].sigma) << k;
        EXPECT_EQ(many.radii[k].sigma, ref.radii[k].sigma) << k;
        EXPECT_EQ(many.radii[k].worst_vertices, ref.radii[k].worst_vertices) << k;
    }
}

TEST(MetricLevels, RadiiLeaveRingLevelsUnchanged)
{
    const Shape s = noisy_sphere(3, 0.05, 1);
    ProfileOptions o;
    const auto rings = roughness_profile(s.mesh, o);
    o.radii = {0.1, 0.3};
    const auto both = roughness_profile(s.mesh, o);
    ASSERT_EQ(rings.levels.size(), both.levels.size());
    for (std::size_t k = 0; k < rings.levels.size(); ++k) EXPECT_EQ(rings.levels[k].sigma, both.levels[k].sigma);
    EXPECT_EQ(rings.global.sigma, both.global.sigma);
    EXPECT_TRUE(rings.radii.empty());
    EXPECT_EQ(both.radii.size(), 2u);
}

TEST(MetricLevels, WeightedSigmaWithEqualWeightsIsTheRingFormula)
{
    std::vector<double> D = {0.5, -1.0, std::nan(""), 2.0, 0.25};
    const auto a = weighted_level_roughness(0.3, D, std::vector<double>(5, 2.0), 0.4);
    const auto b = level_roughness(0, D, 0.4);
    EXPECT_NEAR(a.sigma, b.sigma, 1e-15);
    EXPECT_NEAR(a.top_share, b.top_share, 1e-15);
    EXPECT_EQ(a.worst_vertices, b.worst_vertices);
    EXPECT_EQ(a.vertices_used, 4u);
    EXPECT_DOUBLE_EQ(a.radius, 0.3);
    // Weights count: the heavy vertex dominates.
    const auto c = weighted_level_roughness(0.3, {1.0, 3.0}, {3.0, 1.0});
    EXPECT_NEAR(c.sigma, std::sqrt((3.0 + 9.0) / 4.0), 1e-15);
    EXPECT_THROW(weighted_level_roughness(0.3, {1.0}, {1.0, 2.0}), InvalidArgumentError);
}

TEST(MetricLevels, DistanceMatchesRadii)
{
    const Shape a = noisy_sphere(3, 0.02, 1), b = noisy_sphere(3, 0.06, 2);
    ProfileOptions o;
    o.levels = {1};
    o.radii = {0.1, 0.3};
    const auto pa = roughness_profile(a.mesh, o);
    o.radii = {0.3, 0.5};
    const auto pb = roughness_profile(b.mesh, o);
    const auto d = roughness_distance(pa, pb);
    ASSERT_EQ(d.radii.size(), 1u);  // only 0.3 is in both
    EXPECT_DOUBLE_EQ(d.radii[0].radius, 0.3);
    const auto expect = level_distance(0, pa.radii[1].sigma, pb.radii[0].sigma);
    EXPECT_EQ(d.radii[0].distance, expect.distance);
    EXPECT_EQ(d.radii[0].relative_change, expect.relative_change);
    EXPECT_GT(d.radii[0].relative_change, 0.5);  // rougher
    EXPECT_EQ(d.levels.size(), 1u);
}

TEST(MetricLevels, SummationOrderIsPinned)
{
    // As DiskMeans.SummationOrderIsPinned for the ball search: a hash of the
    // means' bits recorded when the order of the additions was fixed; a
    // change of the search that reorders a sum fails here. No libm in the
    // inputs (a mesh read from a file, hashed values and weights, radii from
    // the bounding box by + - * / and sqrt only).
    const Mesh mesh = read_mesh(std::string(MESHDIFF_TEST_DATA_DIR) + "/fandisk.ply").mesh;
    const Adjacency adj = vertex_adjacency(mesh);
    auto hashed = [](std::uint64_t i) {
        std::uint64_t x = (i + 1) * 0x9E3779B97F4A7C15ULL;
        x ^= x >> 29;
        x *= 0xBF58476D1CE4E5B9ULL;
        x ^= x >> 32;
        return 1.0 + double(x >> 12) * 0x1p-52;
    };
    const std::size_t n = mesh.n_vertices();
    std::vector<double> values(n), weights(n);
    for (std::size_t i = 0; i < n; ++i) {
        values[i] = i % 13 == 4 ? std::nan("") : hashed(i);
        weights[i] = hashed(i + n);
    }
    const BoundingBox box = bounding_box(mesh);
    const double diag = (box.max - box.min).norm();
    const std::vector<double> radii = {0.02 * diag, 0.05 * diag, 0.1 * diag};
    const BallMeans bm = ball_means(mesh, adj, values, weights, radii, true);
    std::uint64_t h = 0xCBF29CE484222325ULL;
    auto add = [&h](const void* p, std::size_t bytes) {
        for (std::size_t i = 0; i < bytes; ++i) h = (h ^ static_cast<const unsigned char*>(p)[i]) * 0x100000001B3ULL;
    };
    for (std::size_t k = 0; k < radii.size(); ++k) {
        add(bm.mean[k].data(), n * sizeof(double));
        add(bm.size[k].data(), n * sizeof(std::uint32_t));
    }
    EXPECT_EQ(h, 0x6FEE314DFB272E06ULL) << std::hex << h;
}
