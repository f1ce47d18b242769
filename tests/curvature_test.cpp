#include "meshdiff/roughness/curvature.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"
#include "meshdiff/geometry/normals.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include "geometry/simd.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

using namespace meshdiff;

namespace {

// The paper's estimator, the Goldfeather-Interrante cubic fit (the default
// is the jet since issue 28): the tests of its rules and cap use it.
CurvatureOptions paper()
{
    CurvatureOptions o;
    o.method = CurvatureMethod::GoldfeatherCubic;
    return o;
}

// The error of the estimate against the exact H over the interior vertices
// (the cubic fit unless told).
CurvatureError error(const Shape& s, const CurvatureOptions& o = paper())
{
    return curvature_error(mean_curvature(s.mesh, o).H, s.exact_H, boundary_vertex_mask(s.mesh));
}

CurvatureOptions method(CurvatureMethod m)
{
    CurvatureOptions o;
    o.method = m;
    return o;
}

// The surface of the cube [0, k]^3 as a closed triangle mesh: each face a
// k x k grid of unit squares, each square cut along the same diagonal,
// oriented outwards. 6 k^2 + 2 vertices.
Mesh subdivided_cube(int k)
{
    Mesh m;
    std::vector<int> id(std::size_t((k + 1) * (k + 1) * (k + 1)), -1);
    auto vertex = [&](int x, int y, int z) {
        int& i = id[std::size_t((x * (k + 1) + y) * (k + 1) + z)];
        if (i < 0) {
            i = int(m.points.size());
            m.points.emplace_back(x, y, z);
        }
        return i;
    };
    // Face `axis` = c (0 or k); (a, b) span the other two axes in a
    // right-handed order, so that a x b points along +axis.
    for (int axis = 0; axis < 3; ++axis)
        for (int c : {0, k}) {
            const int ia = (axis + 1) % 3, ib = (axis + 2) % 3;
            auto at = [&](int a, int b) {
                int p[3];
                p[axis] = c;
                p[ia] = a;
                p[ib] = b;
                return vertex(p[0], p[1], p[2]);
            };
            for (int a = 0; a < k; ++a)
                for (int b = 0; b < k; ++b) {
                    const auto v00 = at(a, b), v10 = at(a + 1, b), v11 = at(a + 1, b + 1), v01 = at(a, b + 1);
                    if (c == k) {
                        m.faces.push_back({v00, v10, v11});
                        m.faces.push_back({v00, v11, v01});
                    } else {
                        m.faces.push_back({v00, v11, v10});
                        m.faces.push_back({v00, v01, v11});
                    }
                }
        }
    return m;
}

}  // namespace

TEST(MeanCurvature, SphereEqualsInverseRadiusWithPositiveSign)
{
    for (double r : {0.5, 1.0, 3.0}) {
        const Shape s = icosphere(4, r);
        const auto field = mean_curvature(s.mesh);
        for (double h : field.H) EXPECT_NEAR(h, 1.0 / r, 0.015 / r);
        EXPECT_EQ(field.undefined, 0u);
    }
}

TEST(MeanCurvature, FlippedOrientationFlipsTheSign)
{
    Shape s = icosphere(3);
    for (auto& f : s.mesh.faces) std::swap(f[1], f[2]);
    for (double h : mean_curvature(s.mesh).H) EXPECT_NEAR(h, -1.0, 0.03);
}

TEST(MeanCurvature, CubicFitConvergesOnIcospheres)
{
    double previous = 1e9;
    for (int k = 2; k <= 5; ++k) {
        const double e = error(icosphere(k)).rms;
        EXPECT_LT(e, 0.8 * previous) << "k = " << k;
        previous = e;
    }
    EXPECT_LT(previous, 5e-3);
}

TEST(MeanCurvature, CubicFitConvergesQuadraticallyOnTheTorus)
{
    // Regular torus grids: halving the spacing divides the error by about 4.
    const double e1 = error(torus(32, 16)).rms;
    const double e2 = error(torus(64, 32)).rms;
    const double e3 = error(torus(128, 64)).rms;
    EXPECT_GT(e1 / e2, 3.0);
    EXPECT_GT(e2 / e3, 3.0);
    EXPECT_LT(e3, 0.02);
}

TEST(MeanCurvature, CubicFitConvergesOnTheEllipsoid)
{
    double previous = 1e9;
    for (int k = 2; k <= 5; ++k) {
        const double e = error(ellipsoid(k, 1.5, 1.0, 1.0)).rms;
        EXPECT_LT(e, 0.8 * previous) << "k = " << k;
        previous = e;
    }
    EXPECT_LT(previous, 5e-3);
}

TEST(MeanCurvature, EstimatorsAgreeWithTheTorusFormula)
{
    // All three estimators on a fine regular torus: H within a few percent of
    // the range of H, which runs from -2 to 2.4 for R = 1, r = 0.25... here
    // R = 1, r = 0.25: inner H = (1 - 0.5) / (0.5 * 0.75) = 1.33, outer 1.2 / 0.625 = 2.4.
    for (auto m : {CurvatureMethod::GoldfeatherCubic, CurvatureMethod::Quadric, CurvatureMethod::MeyerCotangent,
                   CurvatureMethod::Jet}) {
        const CurvatureError e = error(torus(128, 64), method(m));
        EXPECT_LT(e.rms, 0.02) << to_string(m);
        EXPECT_LT(e.max, 0.03) << to_string(m);
        EXPECT_EQ(e.undefined, 0u);
    }
}

TEST(MeanCurvature, MeyerConvergesOnIcospheres)
{
    const double e3 = error(icosphere(3), method(CurvatureMethod::MeyerCotangent)).rms;
    const double e5 = error(icosphere(5), method(CurvatureMethod::MeyerCotangent)).rms;
    EXPECT_LT(e5, e3 / 4);
    EXPECT_LT(e5, 1e-5);
}

TEST(MeanCurvature, HeightFieldInteriorIsAccurateForEveryEstimator)
{
    const Shape s = heightfield(129);
    for (auto m : {CurvatureMethod::GoldfeatherCubic, CurvatureMethod::Quadric, CurvatureMethod::MeyerCotangent,
                   CurvatureMethod::Jet}) {
        const CurvatureError e = error(s, method(m));
        EXPECT_LT(e.rms, 0.02) << to_string(m);
    }
}

TEST(MeanCurvature, IndependentOfRotationAndScalesAsInverseLength)
{
    const Shape s = torus_irregular(3000, 1.0, 0.3, 5);
    Mesh moved = s.mesh;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(1.1, Vec3(0.3, -1, 2).normalized()).toRotationMatrix();
    for (auto& p : moved.points) p = 4.0 * (R * p) + Vec3(3, 2, 1);
    for (auto m : {CurvatureMethod::GoldfeatherCubic, CurvatureMethod::Jet}) {
        const auto ref = mean_curvature(s.mesh, method(m)).H;
        const auto h = mean_curvature(moved, method(m)).H;
        for (std::size_t i = 0; i < ref.size(); ++i)
            ASSERT_NEAR(h[i] * 4.0, ref[i], 1e-9 * (1 + std::abs(ref[i]))) << to_string(m) << " vertex " << i;
    }
}

TEST(MeanCurvature, JetOnTheSphereIsTheInverseRadiusWithPositiveSign)
{
    const Shape s = icosphere(5, 2.0);
    const auto f = mean_curvature(s.mesh, method(CurvatureMethod::Jet));
    EXPECT_EQ(f.undefined, 0u);
    EXPECT_EQ(f.quadric_fallback, 0u);
    for (double h : f.H) ASSERT_NEAR(h, 0.5, 1e-3);
}

TEST(MeanCurvature, JetConvergesOnTheIrregularTorusWhereTheCubicFitStalls)
{
    // issue 28: 4K -> 16K -> 64K vertices, h halves at each step. The jet's
    // RMS and max error fall about 4x per step (measured 0.246 and 0.253,
    // docs/accuracy.md); the issue asks for at least 0.7x and below 1e-2 at
    // 64K. The cubic fit stalls at about 0.075 (the reason for the jet).
    double previous_rms = 0.0, previous_max = 0.0;
    for (std::size_t n : {4000u, 16000u, 64000u}) {
        const Shape s = torus_irregular(n, 1.0, 0.25, 1);
        const CurvatureError e = error(s, method(CurvatureMethod::Jet));
        EXPECT_EQ(e.undefined, 0u);
        if (previous_rms > 0.0) {
            EXPECT_LT(e.rms, 0.35 * previous_rms) << n;
            EXPECT_LT(e.max, 0.35 * previous_max) << n;
        }
        previous_rms = e.rms;
        previous_max = e.max;
        if (n == 16000u) {
            EXPECT_GT(error(s).rms, 5.0 * e.rms) << "the cubic fit no longer stalls: update the docs";
        }
    }
    EXPECT_LT(previous_rms, 2.5e-3);
}

TEST(MeanCurvature, JetIsNoWorseThanTheCubicFitOnRegularSurfaces)
{
    // issue 28: "the regular cases are no worse than today's fit".
    const Shape cases[] = {icosphere(5), uv_sphere(128, 64), torus(128, 64), ellipsoid(5, 1.5, 1.0, 1.0),
                           heightfield(129)};
    for (const Shape& s : cases) {
        const CurvatureError jet = error(s, method(CurvatureMethod::Jet));
        const CurvatureError cubic = error(s);
        EXPECT_LT(jet.rms, cubic.rms) << s.mesh.n_vertices();
        EXPECT_LT(jet.max, cubic.max) << s.mesh.n_vertices();
    }
}

TEST(MeanCurvature, JetLeavesOutADuplicatedPointAndRefusesARowWeighting)
{
    // A height field whose interior vertex 5 * 9 + 4 sits on its neighbour
    // 5 * 9 + 5: the neighbour's rows say nothing about the surface at it;
    // the fit stays defined there and at every other vertex.
    Shape s = heightfield(9, 0.3);
    s.mesh.points[5 * 9 + 4] = s.mesh.points[5 * 9 + 5];
    const auto f = mean_curvature(s.mesh, method(CurvatureMethod::Jet));
    EXPECT_EQ(f.undefined, 0u);
    for (double h : f.H) EXPECT_TRUE(std::isfinite(h));
    CurvatureOptions o = method(CurvatureMethod::Jet);
    o.weighting = RowWeighting::InverseSquare;
    EXPECT_THROW(mean_curvature(s.mesh, o), InvalidArgumentError);
}

TEST(MeanCurvature, FallbacksAndUndefinedVerticesAreCounted)
{
    // A single triangle: every vertex has two neighbours, too few for any fit.
    Mesh tri;
    tri.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    tri.faces = {{0, 1, 2}};
    const auto f = mean_curvature(tri, paper());
    EXPECT_EQ(f.undefined, 3u);
    for (double h : f.H) EXPECT_TRUE(std::isnan(h));
    // Meyer is undefined on boundary vertices, the fits are not.
    const Shape grid = heightfield(17);
    const auto meyer = mean_curvature(grid.mesh, method(CurvatureMethod::MeyerCotangent));
    EXPECT_EQ(meyer.undefined, std::size_t(4 * 16));
    EXPECT_EQ(mean_curvature(grid.mesh, paper()).undefined, 0u);
    // Valence-5 icosphere vertices widen to the 2-ring (min_neighbors 6).
    EXPECT_EQ(mean_curvature(icosphere(3).mesh, paper()).widened, 12u);
}

TEST(MeanCurvature, DroppedNormalRowsAreCountedOnExactlyTheVerticesOfTheRule)
{
    // Subdivided cube: the angle-weighted normal of a vertex inside a face is
    // the face normal, of a vertex on a cube edge the bisector of the two face
    // normals (45 degrees from each), of a corner the diagonal (54.7 degrees
    // from each face normal, 35.3 from the edge bisectors). With a 40-degree
    // rule the normal rows are dropped exactly where a vertex of the fitting
    // neighbourhood lies on another plane or line: every edge and corner
    // vertex and every face vertex next to one, i.e. all but the inner
    // (k - 3) x (k - 3) vertices of each face (valence 6: not widened).
    CurvatureOptions o = paper();
    o.max_normal_angle_deg = 40.0;
    for (int k : {4, 6}) {
        const Mesh cube = subdivided_cube(k);
        ASSERT_EQ(cube.n_vertices(), std::size_t(6 * k * k + 2));
        const auto f = mean_curvature(cube, o);
        EXPECT_EQ(f.undefined, 0u);
        EXPECT_EQ(f.normal_rows_dropped, cube.n_vertices() - std::size_t(6 * (k - 3) * (k - 3))) << "k = " << k;
        // Only the cubic fit has normal rows.
        EXPECT_EQ(mean_curvature(cube, method(CurvatureMethod::Quadric)).normal_rows_dropped, 0u);
        EXPECT_EQ(mean_curvature(cube, method(CurvatureMethod::MeyerCotangent)).normal_rows_dropped, 0u);
    }
}

TEST(MeanCurvature, NoNormalRowsDroppedWhereNormalsAreClose)
{
    // A plane (all normals equal, boundary vertices widened) and icospheres
    // (neighbouring normals within a few degrees, valence-5 vertices widened).
    EXPECT_EQ(mean_curvature(plane_grid(12, 9).mesh, paper()).normal_rows_dropped, 0u);
    for (int k : {2, 3}) {
        const auto f = mean_curvature(icosphere(k).mesh, paper());
        EXPECT_EQ(f.normal_rows_dropped, 0u);
        EXPECT_EQ(f.widened, 12u);
    }
}

TEST(MeanCurvature, InverseSquareWeightingIsMeasuredNotDefault)
{
    // Both weightings converge on the sphere; the default stays unweighted
    // because the weighted fit is far less stable on real meshes (README).
    CurvatureOptions w = paper();
    w.weighting = RowWeighting::InverseSquare;
    EXPECT_LT(error(icosphere(5), w).rms, 5e-3);
    EXPECT_EQ(CurvatureOptions{}.weighting, RowWeighting::None);
}

TEST(MeanCurvature, RejectsBadOptions)
{
    const Shape s = icosphere(1);
    CurvatureOptions o;
    o.min_neighbors = 2;
    EXPECT_THROW(mean_curvature(s.mesh, o), InvalidArgumentError);
    o = {};
    o.max_normal_angle_deg = 0;
    EXPECT_THROW(mean_curvature(s.mesh, o), InvalidArgumentError);
    EXPECT_THROW(parse_enum<CurvatureMethod>("rusinkiewicz"), InvalidArgumentError);
    EXPECT_EQ(parse_enum<CurvatureMethod>("meyer"), CurvatureMethod::MeyerCotangent);
    EXPECT_EQ(parse_enum<CurvatureMethod>("jet"), CurvatureMethod::Jet);
}

namespace {

// A fan of n triangles around vertex 0 at (0, 0, 0.1): rim vertices 1..n on a
// circle of radius 1 + jitter x (a number in [0, 1)), z = 0.01 sin(7a).
Mesh fan(int n, double jitter = 0.0)
{
    Mesh m;
    m.points.emplace_back(0.0, 0.0, 0.1);
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        const double r = 1.0 + jitter * std::fmod(0.618034 * i * i, 1.0);
        m.points.emplace_back(r * std::cos(a), r * std::sin(a), 0.01 * std::sin(7.0 * a));
    }
    for (int i = 0; i < n; ++i) m.faces.push_back({0, 1 + i, 1 + (i + 1) % n});
    return m;
}

// The capped neighbourhood of v by its definition: the 1-ring in adjacency
// order, then the nearest of the rest of the 2-ring by (squared distance, id),
// kMaxFitNeighbors in all.
std::vector<std::uint32_t> brute_force_capped(const Mesh& m, const Adjacency& adj, std::size_t v)
{
    std::vector<std::uint32_t> out(adj.begin(v), adj.end(v));
    std::vector<std::pair<double, std::uint32_t>> rest;
    for (auto it = adj.begin(v); it != adj.end(v); ++it)
        for (auto jt = adj.begin(*it); jt != adj.end(*it); ++jt)
            if (*jt != v && std::find(out.begin(), out.end(), *jt) == out.end())
                rest.push_back({(m.points[*jt] - m.points[v]).squaredNorm(), *jt});
    std::sort(rest.begin(), rest.end());
    rest.erase(std::unique(rest.begin(), rest.end()), rest.end());
    EXPECT_GT(out.size() + rest.size(), kMaxFitNeighbors) << "vertex " << v << " is not capped";
    for (std::size_t k = 0; out.size() < kMaxFitNeighbors; ++k) out.push_back(rest[k].second);
    return out;
}

// H of \p check computed on neighbourhoods given as the adjacency rows of
// those vertices (1-ring fits, never widened), the same normals.
std::vector<double> fit_on_rows(const Mesh& m, const Adjacency& adj, const std::vector<std::size_t>& check)
{
    Adjacency rows;
    rows.offset.push_back(0);
    for (std::size_t v = 0; v < adj.size(); ++v) {
        if (std::find(check.begin(), check.end(), v) != check.end()) {
            const auto hood = brute_force_capped(m, adj, v);
            rows.index.insert(rows.index.end(), hood.begin(), hood.end());
        } else {
            rows.index.insert(rows.index.end(), adj.begin(v), adj.end(v));
        }
        rows.offset.push_back(std::uint32_t(rows.index.size()));
    }
    const auto H = mean_curvature(m, rows, vertex_normals(m), paper()).H;
    std::vector<double> out;
    for (auto v : check) out.push_back(H[v]);
    return out;
}

}  // namespace

TEST(MeanCurvature, CapEngagesBesideAHubAndCountsTheFits)
{
    // Every rim vertex of a fan has 3 neighbours, so widens to its 2-ring,
    // which holds the whole rim: capped. The hub fits on its 1-ring (never capped).
    const int n = 2000;
    const auto f = mean_curvature(fan(n), paper());
    EXPECT_EQ(f.capped, std::size_t(n));
    EXPECT_EQ(f.widened, std::size_t(n));
    EXPECT_EQ(f.undefined, 0u);
    EXPECT_EQ(f.capped_vertices, (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
    // A rim vertex's 2-ring holds the hub and the other n - 1 rim vertices: n
    // in all. Up to the cap nothing changes; one more, and every rim vertex is
    // capped (scanned and cut at n = cap + 1, through the hub's k-d tree above).
    const auto at_cap = mean_curvature(fan(int(kMaxFitNeighbors)), paper());
    EXPECT_EQ(at_cap.capped, 0u);
    EXPECT_TRUE(at_cap.capped_vertices.empty());
    EXPECT_EQ(at_cap.widened, kMaxFitNeighbors);
    for (std::size_t k : {kMaxFitNeighbors + 1, kMaxFitNeighbors + 2})
        EXPECT_EQ(mean_curvature(fan(int(k)), paper()).capped, k);
    // The largest latitude-longitude sphere of the estimator tables (poles of
    // valence 128) is not capped; one with 400 longitudes is, beside its poles.
    EXPECT_EQ(mean_curvature(uv_sphere(128, 64).mesh, paper()).capped, 0u);
    EXPECT_EQ(mean_curvature(uv_sphere(400, 40).mesh, paper()).capped, 800u);
}

TEST(MeanCurvature, CappedFitIsTheFitOnTheNearestOfTheTwoRing)
{
    // Through a hub (k-d tree of its neighbours, degree above kMaxFitNeighbors + 1):
    // rim vertices of a fan with irregular radii. H equals, bit for bit, the
    // fit on the neighbourhood built by the definition.
    const Mesh m = fan(3000, 0.3);
    const Adjacency adj = vertex_adjacency(m);
    const std::vector<std::size_t> check = {1, 2, 77, 1500, 2999, 3000};
    const auto H = mean_curvature(m, paper()).H;
    const auto want = fit_on_rows(m, adj, check);
    for (std::size_t k = 0; k < check.size(); ++k) EXPECT_EQ(H[check[k]], want[k]) << "vertex " << check[k];

    // Without a hub (every 2-ring scanned, then cut): vertex 0 with neighbours
    // 1, 2, 3, where 1 and 2 are centres of fans of 200 triangles (2-ring of
    // more than 400 vertices).
    Mesh two;
    two.points = {Vec3(0, 0, 0.2), Vec3(-1.2, 0, 0), Vec3(1.2, 0, 0), Vec3(0, 1, 0)};
    two.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}};
    for (int hub : {1, 2}) {
        const auto first = std::int32_t(two.points.size());
        for (int i = 0; i < 200; ++i) {
            const double a = 2.0 * M_PI * i / 200;
            two.points.push_back(two.points[std::size_t(hub)] +
                                 Vec3(std::cos(a), std::sin(a), 0.05 * std::cos(3 * a)) * (1.0 + 0.001 * i));
        }
        for (int i = 0; i < 200; ++i) two.faces.push_back({hub, first + i, first + (i + 1) % 200});
    }
    const Adjacency adj2 = vertex_adjacency(two);
    ASSERT_LE(adj2.degree(1), kMaxFitNeighbors + 1);
    const auto f = mean_curvature(two, paper());
    EXPECT_GE(f.capped, 1u);
    EXPECT_EQ(f.capped_vertices.front(), 0u);
    EXPECT_EQ(f.H[0], fit_on_rows(two, adj2, {0})[0]);
}

// The jet fits four vertices at a time (the normal equations on the lanes of
// AVX2 registers, with AVX2) give every vertex the H and the counters of the
// fits one at a time, to the last bit: on meshes with 1-ring and widened
// fits, sharp creases and fits the normal equations decline.
TEST(MeanCurvature, JetFitsFourAtATimeAreTheFitsOneAtATime)
{
    if (!detail::cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: one fit at a time only";
    const std::string data = MESHDIFF_TEST_DATA_DIR;
    for (const char* name : {"bunny_res3.ply", "fandisk.ply", "hemisphere.ply", "sphere_irregular_3072.ply"}) {
        const Mesh mesh = read_mesh(data + "/" + name).mesh;
        const bool before = detail::allow_vector_kernels(false);
        const CurvatureField one = mean_curvature(mesh, method(CurvatureMethod::Jet));
        detail::allow_vector_kernels(true);
        const CurvatureField four = mean_curvature(mesh, method(CurvatureMethod::Jet));
        detail::allow_vector_kernels(before);
        ASSERT_EQ(one.H.size(), four.H.size());
        for (std::size_t v = 0; v < one.H.size(); ++v) {
            std::uint64_t a, b;
            std::memcpy(&a, &one.H[v], sizeof a);
            std::memcpy(&b, &four.H[v], sizeof b);
            ASSERT_EQ(a, b) << name << " vertex " << v;
        }
        EXPECT_EQ(one.undefined, four.undefined) << name;
        EXPECT_EQ(one.quadric_fallback, four.quadric_fallback) << name;
        EXPECT_EQ(one.widened, four.widened) << name;
        EXPECT_EQ(one.steep, four.steep) << name;
    }
}
