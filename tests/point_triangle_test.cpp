#include "meshdiff/geometry/point_triangle.h"

#include "meshdiff/distance/signed_distance.h"
#include "meshdiff/studies/shapes.h"

#include "geometry/point_triangle_kernels.h"
#include "geometry/point_triangle_x4.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace meshdiff;

namespace {

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

}  // namespace

TEST(PointTriangle, TriangleMatchesDenseSamplingInEveryVoronoiRegion)
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

TEST(PointTriangle, DegenerateTrianglesAreSegmentsOrPoints)
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

TEST(PointTriangle, ThinTriangleRuleSwitchesAtTheStatedSine)
{
    // Corner 0 at the origin, edges along x and at angle t: sin t just above
    // and below kThinTriangleSine. Above: the face region (projection onto the
    // plane, distance 1 for a point 1 above the triangle's interior); below:
    // the union of the edges, which gives the same distance to the rounding of
    // a triangle of width below 1e-8.
    const Vec3 a(0, 0, 0), b(1, 0, 0);
    for (double s : {10 * kThinTriangleSine, 0.1 * kThinTriangleSine}) {
        const Vec3 c(1, s, 0);
        const Vec3 p(0.9, 0.5 * s * 0.9, 1.0);
        const ClosestPoint cp = closest_point_on_triangle(p, a, b, c);
        EXPECT_NEAR(cp.distance, 1.0, 1e-12) << s;
        EXPECT_NEAR((cp.point - p).norm(), cp.distance, 1e-15) << s;
    }
}

TEST(PointTriangle, SegmentEndsAndInterior)
{
    const Vec3 a(0, 0, 0), b(2, 0, 0);
    EXPECT_EQ(closest_point_on_segment(Vec3(-1, 1, 0), a, b).point, a);
    EXPECT_EQ(closest_point_on_segment(Vec3(5, 1, 0), a, b).point, b);
    EXPECT_DOUBLE_EQ(closest_point_on_segment(Vec3(0.5, 3, 4), a, b).distance, 5.0);
    EXPECT_EQ(closest_point_on_segment(Vec3(1, 1, 1), a, a).point, a);
}

TEST(PointTriangle, BruteForceIsTheMinimumOverFacesWithTheLowestFaceOnTies)
{
    const Mesh m = icosphere(1).mesh;
    const Vec3 p(0.3, -1.7, 0.4);
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t face = 0;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
        const Face& t = m.faces[f];
        const double d = closest_point_on_triangle(p, m.points[std::size_t(t[0])], m.points[std::size_t(t[1])],
                                                   m.points[std::size_t(t[2])])
                             .distance;
        if (d < best) {
            best = d;
            face = std::uint32_t(f);
        }
    }
    const ClosestPoint bf = closest_point_brute_force(m, p);
    EXPECT_EQ(bf.distance, best);
    EXPECT_EQ(bf.face, face);
    // A vertex is shared by five faces: the lowest-numbered of them wins.
    const ClosestPoint at_vertex = closest_point_brute_force(m, m.points[0] * 1.5);
    std::uint32_t lowest = std::numeric_limits<std::uint32_t>::max();
    for (std::size_t f = 0; f < m.n_faces(); ++f)
        for (auto v : m.faces[f])
            if (v == 0) lowest = std::min(lowest, std::uint32_t(f));
    EXPECT_EQ(at_vertex.face, lowest);
    EXPECT_NEAR(at_vertex.distance, 0.5, 1e-15);
}

// The AVX2 kernel of the closest-point index and the certification
// (geometry/point_triangle_x4.h) against detail::triangle_point(), lane by
// lane, bit for bit: points in every Voronoi region, on the corners, on the
// edges and in the plane, triangles from needles near the thin threshold to
// 1e6 wide and 1e-4 small far from the origin, one point for four
// triangles and four points for one.
TEST(PointTriangleX4, LanesAreTheScalarClosestPointsBitForBit)
{
    if (!detail::cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2: the scalar closest points only";
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> kind(0, 9);
    auto vec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
    std::size_t compared = 0, shared_compared = 0;
    std::array<std::size_t, 7> regions{};
    for (int round = 0; round < 200000; ++round) {
        Vec3 a[4], b[4], c[4], p[4];
        const bool one_point = round % 2 == 0;
        for (int k = 0; k < 4; ++k) {
            a[k] = vec();
            b[k] = vec();
            c[k] = vec();
            p[k] = 2.0 * vec();
            switch (kind(rng)) {
                case 0:
                    c[k] = a[k] + 1e-7 * (b[k] - a[k]) + Vec3(1e-9, 0.0, 0.0);
                    break;  // a needle
                case 1:
                    p[k] = b[k];
                    break;  // a corner
                case 2:
                    p[k] = 0.5 * (b[k] + c[k]);
                    break;  // an edge
                case 3:
                    p[k] = (a[k] + b[k] + c[k]) / 3.0;
                    break;  // the plane
                case 4:
                    a[k] *= 1e6, b[k] *= 1e6, c[k] *= 1e6;
                    break;
                case 5: {
                    const Vec3 far(3e3, -2e3, 1e3);
                    a[k] = far + 1e-4 * a[k], b[k] = far + 1e-4 * b[k], c[k] = far + 1e-4 * c[k];
                    p[k] = far + 1e-4 * p[k];
                    break;
                }
                default:
                    break;
            }
            if (one_point) p[k] = p[0];
        }
        if (round % 3 == 0)  // four points, one triangle (the certification's use)
            for (int k = 1; k < 4; ++k) a[k] = a[0], b[k] = b[0], c[k] = c[0];
        detail::PairsX4 in;
        for (int k = 0; k < 4; ++k) {
            in.p[k] = p[k].data();
            in.a[k] = a[k].data();
            in.b[k] = b[k].data();
            in.c[k] = c[k].data();
        }
        double d2[4], qx[4], qy[4], qz[4];
        const unsigned masks = detail::closest_points_x4(in, d2, qx, qy, qz);
        // The triangle the lanes share, read once: the same results to the
        // last bit.
        if (round % 3 == 0) {
            double e2[4], ex[4], ey[4], ez[4];
            const unsigned shared_masks = detail::closest_points_x4(in, e2, ex, ey, ez, detail::SharedX4::kTriangle);
            ASSERT_EQ(shared_masks, masks) << round;
            ASSERT_EQ(std::memcmp(e2, d2, sizeof d2), 0) << round;
            ASSERT_EQ(std::memcmp(ex, qx, sizeof qx), 0) << round;
            ASSERT_EQ(std::memcmp(ey, qy, sizeof qy), 0) << round;
            ASSERT_EQ(std::memcmp(ez, qz, sizeof qz), 0) << round;
            ++shared_compared;
        }
        // The index's form, one point and the corners by their positions in
        // an array (1 to 4 triangles, the lanes past the last repeating it):
        // each lane is the lane of its triangle above.
        if (one_point) {
            const unsigned count = 1u + unsigned(round / 2) % 4u;
            std::vector<Vec3> points;
            std::uint32_t corners[16];
            for (std::uint32_t k = 0; k < 4; ++k) {
                for (const Vec3* v : {&c[k], &a[k], &b[k]}) points.push_back(*v);  // not in corner order
                corners[4 * k] = 3 * k + 1;
                corners[4 * k + 1] = 3 * k + 2;
                corners[4 * k + 2] = 3 * k;
                corners[4 * k + 3] = 0xFFFFFFFFu;  // the triangle's fourth word, not read
            }
            double e2[4], ex[4], ey[4], ez[4];
            const unsigned indexed_masks =
                detail::closest_points_indexed_x4(p[0].data(), points.data(), corners, count, e2, ex, ey, ez);
            for (unsigned k = 0; k < 4; ++k) {
                const unsigned j = std::min(k, count - 1);
                ASSERT_EQ(detail::lane_region(indexed_masks, k), detail::lane_region(masks, j)) << round;
                ASSERT_EQ(std::memcmp(&e2[k], &d2[j], sizeof(double)), 0) << round;
                ASSERT_EQ(std::memcmp(&ex[k], &qx[j], sizeof(double)), 0) << round;
                ASSERT_EQ(std::memcmp(&ey[k], &qy[j], sizeof(double)), 0) << round;
                ASSERT_EQ(std::memcmp(&ez[k], &qz[j], sizeof(double)), 0) << round;
            }
            ++shared_compared;
        }
        for (int k = 0; k < 4; ++k) {
            if (detail::is_thin_triangle(a[k], b[k], c[k])) continue;  // never given to the kernel
            const Vec3 q = detail::triangle_point(p[k], a[k], b[k], c[k]);
            // The lane's region is the one closest_feature() finds (the signs use it).
            const ClosestFeature f = closest_feature(p[k], a[k], b[k], c[k]);
            ASSERT_EQ(std::memcmp(&q[0], &f.point[0], 3 * sizeof(double)), 0) << round << " lane " << k;
            const unsigned r = detail::lane_region(masks, unsigned(k));
            ++regions[r];
            const unsigned expected =
                f.kind == FeatureKind::Interior ? detail::kRegionInterior
                : f.kind == FeatureKind::Vertex
                    ? std::array<unsigned, 3>{detail::kRegionA, detail::kRegionB, detail::kRegionC}[f.index]
                    : std::array<unsigned, 3>{detail::kRegionAB, detail::kRegionBC, detail::kRegionAC}[f.index];
            ASSERT_EQ(r, expected) << round << " lane " << k;
            const double e2 = (p[k] - q).squaredNorm();
            ASSERT_EQ(std::memcmp(&e2, &d2[k], sizeof(double)), 0) << round << " lane " << k;
            ASSERT_EQ(std::memcmp(&q[0], &qx[k], sizeof(double)), 0) << round << " lane " << k;
            ASSERT_EQ(std::memcmp(&q[1], &qy[k], sizeof(double)), 0) << round << " lane " << k;
            ASSERT_EQ(std::memcmp(&q[2], &qz[k], sizeof(double)), 0) << round << " lane " << k;
            ++compared;
        }
    }
    EXPECT_GT(compared, 600000u);
    EXPECT_GT(shared_compared, 50000u);
    for (unsigned r = detail::kRegionA; r <= detail::kRegionInterior; ++r) EXPECT_GT(regions[r], 1000u) << r;
}
