#include "meshdiff/closest_point.h"

#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/shapes.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace meshdiff;

namespace {

const std::string kData = MESHDIFF_TEST_DATA_DIR;

// Minimum distance from p to a dense barycentric grid of triangle (a, b, c)
// (n + 1)(n + 2) / 2 points, and the grid spacing bound h: every point of the
// triangle is within h of a grid point.
double grid_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int n, double* h)
{
    double best = INFINITY;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const Vec3 q = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
            best = std::min(best, (p - q).norm());
        }
    *h = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / n;
    return best;
}

// A 6 x 6 grid in z = 0 with extra degenerate faces: a collinear one, one with
// a repeated corner, a zero-length-edge sliver, and a duplicate face.
Mesh mesh_with_degenerate_faces()
{
    Mesh m = plane_grid(6, 6, 0.2).mesh;
    const auto n = std::int32_t(m.points.size());
    m.points.emplace_back(0.0, 0.0, 0.3);
    m.points.emplace_back(0.5, 0.0, 0.3);
    m.points.emplace_back(1.0, 0.0, 0.3);  // collinear with the two before
    m.points.emplace_back(0.2, 0.4, -0.2);
    m.faces.push_back({n, n + 1, n + 2});      // collinear
    m.faces.push_back({n + 3, n + 3, n + 1});  // repeated corner: a segment
    m.faces.push_back({n + 3, n + 3, n + 3});  // a point
    m.faces.push_back(m.faces[3]);             // duplicate
    return m;
}

std::vector<Vec3> random_queries(const Mesh& m, std::size_t n, std::uint64_t seed)
{
    const BoundingBox box = bounding_box(m);
    const Vec3 c = 0.5 * (box.min + box.max);
    const double diag = box.diagonal();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec3> q;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 dir(u(rng), u(rng), u(rng));
        switch (i % 4) {
            case 0:
                q.push_back(c + 0.6 * diag * dir);
                break;  // around the mesh
            case 1:     // near the surface
                q.push_back(m.points[std::size_t(rng() % m.points.size())] + 1e-3 * diag * dir);
                break;
            case 2:
                q.push_back(c + 50.0 * diag * dir);
                break;  // far
            default:
                q.push_back(c + 1e6 * diag * dir);
                break;  // very far (no cut-off)
        }
    }
    return q;
}

void expect_index_matches_brute_force(const Mesh& m, std::size_t n_queries)
{
    const ClosestPointIndex index(m);
    for (const Vec3& p : random_queries(m, n_queries, 7)) {
        const ClosestPoint bf = closest_point_brute_force(m, p);
        const ClosestPoint ix = index.closest_point(p);
        ASSERT_NEAR(ix.distance, bf.distance, 1e-12 * bf.distance) << p.transpose();
        // The reported point is on the reported face and at the reported distance.
        const Face& t = m.faces[ix.face];
        const ClosestPoint on_face = closest_point_on_triangle(
            p, m.points[std::size_t(t[0])], m.points[std::size_t(t[1])], m.points[std::size_t(t[2])]);
        EXPECT_NEAR(on_face.distance, ix.distance, 1e-12 * ix.distance);
        EXPECT_NEAR((p - ix.point).norm(), ix.distance, 1e-12 * ix.distance);
    }
}

}  // namespace

TEST(ClosestPoint, TriangleMatchesDenseSamplingInEveryVoronoiRegion)
{
    const Vec3 a(0.1, -0.2, 0.05), b(1.3, 0.1, -0.1), c(0.4, 0.9, 0.3);
    const Vec3 n = (b - a).cross(c - a).normalized();
    const Vec3 centroid = (a + b + c) / 3.0;
    // Queries in the 3 vertex regions, the 3 edge regions and the face region,
    // each above, on and below the plane.
    std::vector<std::pair<Vec3, const char*>> queries;
    for (double z : {-0.4, 0.0, 0.7}) {
        queries.push_back({a + 0.5 * (a - centroid) + z * n, "vertex a"});
        queries.push_back({b + 0.5 * (b - centroid) + z * n, "vertex b"});
        queries.push_back({c + 0.5 * (c - centroid) + z * n, "vertex c"});
        for (auto [u, v] : {std::pair<Vec3, Vec3>{a, b}, {b, c}, {c, a}}) {
            const Vec3 mid = 0.5 * (u + v);
            queries.push_back({mid + 0.4 * (mid - centroid) + z * n, "edge"});
        }
        queries.push_back({centroid + 0.1 * (b - a) + z * n, "face"});
    }
    for (const auto& [p, region] : queries) {
        double h = 0.0;
        const double sampled = grid_distance(p, a, b, c, 400, &h);
        const ClosestPoint cp = closest_point_on_triangle(p, a, b, c);
        // Exact distance: never above any point of the triangle, and within the
        // grid spacing of the densest sampling.
        EXPECT_LE(cp.distance, sampled + 1e-15) << region;
        EXPECT_GE(cp.distance, sampled - h) << region;
        EXPECT_NEAR((p - cp.point).norm(), cp.distance, 1e-15) << region;
    }
    // Vertex regions return the vertex itself.
    EXPECT_EQ(closest_point_on_triangle(a + 0.5 * (a - centroid), a, b, c).point, a);
    EXPECT_EQ(closest_point_on_triangle(c + 0.5 * (c - centroid) + n, a, b, c).point, c);
    // The face region projects orthogonally.
    const Vec3 inside = centroid + 0.05 * (b - a);
    EXPECT_NEAR(closest_point_on_triangle(inside + 0.3 * n, a, b, c).distance, 0.3, 1e-15);
    EXPECT_NEAR(closest_point_on_triangle(inside - 0.3 * n, a, b, c).distance, 0.3, 1e-15);
}

TEST(ClosestPoint, DegenerateTrianglesAreSegmentsOrPoints)
{
    const Vec3 a(0, 0, 0), b(2, 0, 0), m(0.5, 0, 0);
    const Vec3 p(3.0, 1.0, 0.5);
    // Collinear: the longest edge [a, b], whatever the corner order.
    EXPECT_DOUBLE_EQ(closest_point_on_triangle(p, a, m, b).distance, closest_point_on_segment(p, a, b).distance);
    EXPECT_DOUBLE_EQ(closest_point_on_triangle(p, m, b, a).distance, std::sqrt(1.0 + 1.0 + 0.25));
    const Vec3 above(1.0, 0.0, 0.25);
    EXPECT_DOUBLE_EQ(closest_point_on_triangle(above, a, m, b).distance, 0.25);
    // Repeated corner: a segment; all corners equal: a point.
    EXPECT_DOUBLE_EQ(closest_point_on_triangle(p, a, a, b).distance, closest_point_on_segment(p, a, b).distance);
    EXPECT_DOUBLE_EQ(closest_point_on_triangle(p, b, b, b).distance, (p - b).norm());
    EXPECT_TRUE(std::isfinite(closest_point_on_triangle(p, a, a, a).distance));
}

TEST(ClosestPoint, IndexAgreesWithBruteForceOnAnIcosphere)
{
    expect_index_matches_brute_force(icosphere(3, 1.0).mesh, 400);
}

TEST(ClosestPoint, IndexAgreesWithBruteForceOnTheBunny)
{
    expect_index_matches_brute_force(read_mesh(kData + "/bunny_res4_ascii.ply").mesh, 400);
}

TEST(ClosestPoint, IndexAgreesWithBruteForceWithDegenerateTriangles)
{
    expect_index_matches_brute_force(mesh_with_degenerate_faces(), 400);
}

TEST(ClosestPoint, IndexAgreesWithBruteForceOnTheTeapot)
{
    expect_index_matches_brute_force(read_mesh(kData + "/teapot.obj").mesh, 200);
}

TEST(ClosestPoint, FarQueryHasItsTrueDistance)
{
    const Mesh m = icosphere(2, 1.0).mesh;
    const ClosestPointIndex index(m);
    // A unit-ish sphere seen from 1e9 away: the distance is about 1e9 - 1.
    const ClosestPoint r = index.closest_point(Vec3(0, 0, 1e9));
    EXPECT_NEAR(r.distance, 1e9 - 1.0, 1e-6);
}

TEST(ClosestPoint, TiesGoToTheLowestFace)
{
    const Mesh m = icosphere(2, 1.0).mesh;
    const ClosestPointIndex index(m);
    // A vertex is at distance 0 from each of its 5 or 6 faces.
    for (std::size_t v : {0u, 7u, 100u}) {
        std::uint32_t lowest = UINT32_MAX;
        for (std::size_t f = 0; f < m.n_faces(); ++f)
            for (auto c : m.faces[f])
                if (std::size_t(c) == v) lowest = std::min(lowest, std::uint32_t(f));
        const ClosestPoint r = index.closest_point(m.points[v]);
        EXPECT_EQ(r.distance, 0.0);
        EXPECT_EQ(r.face, lowest);
    }
}

TEST(ClosestPoint, BatchResultsAreIdenticalForOneAndTwoThreads)
{
    const Mesh m = read_mesh(kData + "/bunny_res3.ply").mesh;
    const ClosestPointIndex index(m);
    const auto queries = random_queries(m, 20000, 3);
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const auto one = index.closest_points(queries);
    omp_set_num_threads(2);
    const auto two = index.closest_points(queries);
    omp_set_num_threads(saved);
    ASSERT_EQ(one.size(), two.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
        ASSERT_EQ(std::memcmp(&one[i].distance, &two[i].distance, sizeof(double)), 0) << i;
        ASSERT_EQ(one[i].face, two[i].face) << i;
        ASSERT_EQ(one[i].point, two[i].point) << i;
    }
    // And the batch equals the single queries.
    for (std::size_t i = 0; i < queries.size(); i += 97)
        EXPECT_EQ(index.closest_point(queries[i]).distance, one[i].distance);
}

TEST(ClosestPoint, EmptyMeshThrows)
{
    EXPECT_THROW(ClosestPointIndex(Mesh{}), InvalidMeshError);
}

TEST(ClosestPoint, IndexBoundsContainTheMesh)
{
    const Mesh m = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const ClosestPointIndex index(m);
    const BoundingBox b = bounding_box(m);
    EXPECT_EQ(index.n_faces(), m.n_faces());
    EXPECT_TRUE((index.bounds().min.array() <= b.min.array()).all());
    EXPECT_TRUE((index.bounds().max.array() >= b.max.array()).all());
    EXPECT_GT(index.memory_bytes(), 0u);
}
