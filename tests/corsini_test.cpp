#include "meshdiff/roughness/corsini.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"
#include "meshdiff/roughness/metric_levels.h"
#include "meshdiff/studies/shapes.h"

#include <omp.h>

#include <cmath>
#include <cstdint>
#include <queue>
#include <utility>
#include <vector>

using namespace meshdiff;

namespace {

// A corrugated sheet: the grid i = 0..nx-1, j = 0..ny-1 (unit spacing) with
// z = h on the odd rows and 0 on the even ones, each unit square cut along
// the diagonal (i, j)-(i+1, j+1). The four corners of a square lie in one
// plane (two parallel rows), so each strip between two rows is planar and the
// strips slope alternately up and down: the edges along an inner row are
// creases of dihedral angle 2 atan(h) (the angle between the strips'
// normals (0, -h, 1) and (0, h, 1)); every other inner edge has angle 0.
Mesh zigzag(int nx, int ny, double h)
{
    Mesh m;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) m.points.emplace_back(i, j, j % 2 ? h : 0.0);
    auto id = [&](int i, int j) { return j * nx + i; };
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) {
            m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

// The sheet's edges classified by construction (not by normals): for each
// inner edge, whether it is a crease.
struct SheetEdge
{
    std::uint32_t a, b;
    bool crease;
};
std::vector<SheetEdge> zigzag_inner_edges(int nx, int ny)
{
    std::vector<SheetEdge> e;
    auto id = [&](int i, int j) { return std::uint32_t(j * nx + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            if (i + 1 < nx && j > 0 && j + 1 < ny) e.push_back({id(i, j), id(i + 1, j), true});   // along a row
            if (j + 1 < ny && i > 0 && i + 1 < nx) e.push_back({id(i, j), id(i, j + 1), false});  // across
            if (i + 1 < nx && j + 1 < ny) e.push_back({id(i, j), id(i + 1, j + 1), false});       // diagonal
        }
    return e;
}

// Graph distances from v by breadth-first search over the listed edges plus
// the boundary ones (all sheet edges).
std::vector<int> sheet_distances(int nx, int ny, std::uint32_t v)
{
    std::vector<std::vector<std::uint32_t>> nb(std::size_t(nx * ny));
    auto link = [&](int i0, int j0, int i1, int j1) {
        if (i1 < 0 || j1 < 0 || i1 >= nx || j1 >= ny) return;
        nb[std::size_t(j0 * nx + i0)].push_back(std::uint32_t(j1 * nx + i1));
    };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}})
                link(i, j, i + di, j + dj);
    std::vector<int> d(nb.size(), -1);
    std::queue<std::uint32_t> q;
    d[v] = 0;
    q.push(v);
    while (!q.empty()) {
        const auto u = q.front();
        q.pop();
        for (auto w : nb[u])
            if (d[w] < 0) {
                d[w] = d[u] + 1;
                q.push(w);
            }
    }
    return d;
}

// Population variance of a two-valued sample: a fraction p of value x, the rest 0.
double two_valued_variance(double p, double x)
{
    return p * (1.0 - p) * x * x;
}

}  // namespace

TEST(DihedralAngles, ZeroOnAPlaneAndOfTheSheetByConstruction)
{
    for (double a : dihedral_angles(plane_grid(6, 5).mesh)) {
        if (!std::isnan(a)) {
            EXPECT_EQ(a, 0.0);
        }
    }
    const int nx = 7, ny = 6;
    const double h = 0.3;
    const Mesh m = zigzag(nx, ny, h);
    const auto theta = dihedral_angles(m);
    const auto edges = unique_edges(m);
    ASSERT_EQ(theta.size(), edges.size());
    std::size_t defined = 0;
    for (const auto& e : zigzag_inner_edges(nx, ny)) {
        std::size_t k = 0;
        while (k < edges.size() && !(edges[k].a == std::min(e.a, e.b) && edges[k].b == std::max(e.a, e.b))) ++k;
        ASSERT_LT(k, edges.size());
        EXPECT_NEAR(theta[k], e.crease ? 2.0 * std::atan(h) : 0.0, 1e-14);
        ++defined;
    }
    std::size_t with_angle = 0;
    for (double a : theta) with_angle += std::isnan(a) ? 0 : 1;
    EXPECT_EQ(with_angle, defined);  // boundary edges have none
}

TEST(CorsiniProfile, ZeroOnAPlaneAndOnRegularPolyhedra)
{
    CorsiniOptions o;
    o.levels = {1, 2, 5};
    for (const Mesh& m : {plane_grid(9, 7).mesh, icosphere(0).mesh, geodesic_sphere(1).mesh}) {
        const CorsiniProfile p = corsini_profile(m, o);
        for (const auto& l : p.levels) EXPECT_NEAR(l.roughness, 0.0, 1e-28);
        EXPECT_NEAR(p.global.roughness, 0.0, 1e-28);
        EXPECT_NEAR(p.multiscale, 0.0, 1e-28);
    }
    // The icosahedron's dihedral angle: the angle between face normals is
    // pi - arccos(-sqrt(5) / 3).
    const CorsiniProfile ico = corsini_profile(icosphere(0).mesh, o);
    EXPECT_EQ(ico.dihedral_edges, 30u);
    EXPECT_NEAR(ico.mean_dihedral, M_PI - std::acos(-std::sqrt(5.0) / 3.0), 1e-14);
    for (const auto& l : ico.levels) EXPECT_EQ(l.vertices_used, 12u);
}

TEST(CorsiniProfile, CubeGlobalVarianceIsTwoNinthsOfAQuarterPiSquared)
{
    // 12 triangles: 12 cube edges at pi/2, 6 face diagonals at 0.
    Mesh cube;
    for (int k = 0; k < 8; ++k) cube.points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    cube.faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                  {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    CorsiniOptions o;
    o.levels = {};
    const CorsiniProfile p = corsini_profile(cube, o);
    EXPECT_EQ(p.dihedral_edges, 18u);
    EXPECT_NEAR(p.global.roughness, two_valued_variance(12.0 / 18.0, M_PI / 2), 1e-14);
    o.unbiased = true;
    EXPECT_NEAR(corsini_profile(cube, o).global.roughness, two_valued_variance(12.0 / 18.0, M_PI / 2) * 18.0 / 17.0,
                1e-14);
}

TEST(CorsiniProfile, PerVertexVarianceOnTheSheetMatchesTheEdgeCount)
{
    const int nx = 15, ny = 14;
    const double h = 0.4, crease = 2.0 * std::atan(h);
    const Mesh m = zigzag(nx, ny, h);
    CorsiniOptions o;
    o.levels = {1, 2, 3};
    o.keep_vertex_data = true;
    const CorsiniProfile p = corsini_profile(m, o);
    ASSERT_EQ(p.R.size(), 3u);
    // Scale 1 of an inner vertex: 12 edges (6 spokes, 6 rim), 4 of them along rows.
    const std::uint32_t centre = std::uint32_t(7 * nx + 7);
    EXPECT_NEAR(p.R[0][centre], two_valued_variance(4.0 / 12.0, crease), 1e-14);
    // Every scale at a few vertices, against the edges counted by construction.
    const auto inner = zigzag_inner_edges(nx, ny);
    for (std::uint32_t v : {centre, std::uint32_t(6 * nx + 8), std::uint32_t(5 * nx + 5), std::uint32_t(2 * nx + 3)}) {
        const auto d = sheet_distances(nx, ny, v);
        for (std::size_t k = 0; k < 3; ++k) {
            const int L = o.levels[k];
            double all = 0, creases = 0;
            for (const auto& e : inner)
                if (d[e.a] <= L && d[e.b] <= L) {
                    ++all;
                    creases += e.crease ? 1 : 0;
                }
            EXPECT_NEAR(p.R[k][v], two_valued_variance(creases / all, crease), 1e-13) << "v " << v << " L " << L;
        }
    }
    // Global: all inner edges.
    double creases = 0;
    for (const auto& e : inner) creases += e.crease ? 1 : 0;
    EXPECT_NEAR(p.global.roughness, two_valued_variance(creases / double(inner.size()), crease), 1e-14);
    // The mesh value of a scale is the area-weighted mean of the vertex values.
    const auto A = vertex_areas(m);
    for (std::size_t k = 0; k < 3; ++k) {
        double num = 0, den = 0;
        for (std::size_t v = 0; v < m.n_vertices(); ++v)
            if (!std::isnan(p.R[k][v])) {
                num += A[v] * p.R[k][v];
                den += A[v];
            }
        EXPECT_NEAR(p.levels[k].roughness, num / den, 1e-15);
    }
    EXPECT_NEAR(p.multiscale, (p.levels[0].roughness + p.levels[1].roughness + p.levels[2].roughness) / 3, 1e-16);
}

TEST(CorsiniProfile, InvariantToScaleRotationAndTranslation)
{
    const Mesh m = noisy_sphere(2, 0.05, 3).mesh;
    CorsiniOptions o;
    o.levels = {1, 3};
    const CorsiniProfile p = corsini_profile(m, o);
    Mesh moved = m;
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    for (auto& x : moved.points) x = 37.5 * (rot * x) + Vec3(4, -2, 9);
    const CorsiniProfile q = corsini_profile(moved, o);
    ASSERT_GT(p.levels[0].roughness, 1e-4);
    for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(q.levels[k].roughness / p.levels[k].roughness, 1.0, 1e-9);
    EXPECT_NEAR(q.global.roughness / p.global.roughness, 1.0, 1e-9);
}

TEST(CorsiniProfile, IdenticalForAnyThreadCount)
{
    const Mesh m = noisy_sphere(3, 0.05, 4).mesh;
    CorsiniOptions o;
    o.levels = {1, 4, 9};
    omp_set_num_threads(1);
    const CorsiniProfile one = corsini_profile(m, o);
    omp_set_num_threads(3);
    const CorsiniProfile three = corsini_profile(m, o);
    omp_set_num_threads(omp_get_num_procs());
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(one.levels[k].roughness, three.levels[k].roughness);
}

TEST(CorsiniProfile, BadOptionsAreRefused)
{
    const Mesh m = icosphere(1).mesh;
    CorsiniOptions o;
    o.levels = {0};
    EXPECT_THROW(corsini_profile(m, o), InvalidArgumentError);
    o.levels = {};
    o.global = false;
    EXPECT_THROW(corsini_profile(m, o), InvalidArgumentError);
}

TEST(CorsiniProfile, VerticesWithoutAnAngleAreCounted)
{
    // One triangle: no edge has two faces.
    Mesh tri;
    tri.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    tri.faces = {{0, 1, 2}};
    CorsiniOptions o;
    o.levels = {1};
    const CorsiniProfile p = corsini_profile(tri, o);
    EXPECT_EQ(p.dihedral_edges, 0u);
    EXPECT_EQ(p.levels[0].no_neighborhood, 3u);
    EXPECT_EQ(p.levels[0].roughness, 0.0);
    EXPECT_EQ(p.global.roughness, 0.0);
    EXPECT_EQ(p.global.no_neighborhood, 3u);
}

TEST(CorsiniDistance, IsTheLogOfTheRelativeChangeShiftedByK)
{
    CorsiniProfile a, b;
    a.options.levels = b.options.levels = {1, 2};
    a.levels = {{1, 0.02, 10, 0, 12}, {2, 0.03, 10, 0, 30}};
    b.levels = {{1, 0.03, 10, 0, 12}, {2, 0.03, 10, 0, 30}};
    a.has_global = b.has_global = true;
    a.global.roughness = 0.05;
    b.global.roughness = 0.04;
    a.global.vertices_used = b.global.vertices_used = 10;
    a.multiscale = 0.025;
    b.multiscale = 0.03;
    const double k = 1e-3;
    const CorsiniDistance d = corsini_distance(a, b, k);
    ASSERT_EQ(d.levels.size(), 2u);
    EXPECT_NEAR(d.levels[0].distance, std::log(0.5 + k) - std::log(k), 1e-12);
    EXPECT_NEAR(d.levels[0].relative_change, 0.5, 1e-15);
    EXPECT_NEAR(d.levels[1].distance, 0.0, 1e-15);
    EXPECT_NEAR(d.global.distance, std::log(0.2 + k) - std::log(k), 1e-12);
    EXPECT_NEAR(d.global.relative_change, -0.2, 1e-15);
    ASSERT_TRUE(d.has_multiscale);
    EXPECT_NEAR(d.multiscale.distance, std::log(0.2 + k) - std::log(k), 1e-12);
    b.options.levels = {1};
    EXPECT_FALSE(corsini_distance(a, b, k).has_multiscale);
    EXPECT_THROW(corsini_distance(a, b, 0.0), InvalidArgumentError);
}
