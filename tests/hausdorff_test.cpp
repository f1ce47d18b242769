#include "meshdiff/distance/hausdorff.h"

#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include "geometry/simd.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <utility>

using namespace meshdiff;

namespace {

const std::string kData = MESHDIFF_TEST_DATA_DIR;

// A triangle with three equal corners: a point of the mesh.
void add_point(Mesh& m, const Vec3& p)
{
    const int v = int(m.points.size());
    m.points.push_back(p);
    m.faces.push_back({v, v, v});
}

void add_triangle(Mesh& m, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const int v = int(m.points.size());
    m.points.insert(m.points.end(), {a, b, c});
    m.faces.push_back({v, v + 1, v + 2});
}

// The largest distance to B over a dense barycentric lattice of every face of
// A, (n + 1)(n + 2) / 2 points per face: a lower bound of the true value, up
// to the rounding of the lattice points (which may lie an ulp off the face:
// the comparisons with an upper bound allow 1e-12).
double dense_maximum(const Mesh& a, const Mesh& b, int n)
{
    const ClosestPointIndex index(b);
    std::vector<Vec3> q;
    for (const Face& f : a.faces)
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const double u = double(i) / n, v = double(j) / n;
                q.push_back((1 - u - v) * a.points[std::size_t(f[0])] + u * a.points[std::size_t(f[1])] +
                            v * a.points[std::size_t(f[2])]);
            }
    const std::vector<double> d = index.distances(q);
    return *std::max_element(d.begin(), d.end());
}

void expect_contains(const CertifiedHausdorff& h, double exact, double slack = 1e-14)
{
    EXPECT_LE(h.lower, exact + slack * std::max(1.0, exact));
    EXPECT_GE(h.upper, exact - slack * std::max(1.0, exact));
}

void expect_certified(const CertifiedHausdorff& h)
{
    EXPECT_TRUE(h.certified);
    EXPECT_FALSE(h.budget_exhausted);
    EXPECT_LE(h.lower, h.upper);
    EXPECT_LE(h.upper - h.lower, h.tolerance);
}

bool same_bits(double x, double y)
{
    return std::memcmp(&x, &y, sizeof(double)) == 0;
}

// Three points of B (degenerate triangles) around a small triangle of A: the
// distance to B is largest at their circumcentre (0, 5/12), inside A's
// triangle, where it is the circumradius 13/12; every corner and edge of A is
// closer.
struct Circumcentre
{
    Mesh a, b;
    Circumcentre()
    {
        add_point(b, {-1, 0, 0});
        add_point(b, {1, 0, 0});
        add_point(b, {0, 1.5, 0});
        add_triangle(a, {-0.3, 0.2, 0}, {0.3, 0.2, 0}, {0, 0.7, 0});
    }
};

}  // namespace

TEST(HausdorffBound, EqualsBruteForceMinimumOfMaximumCornerDistance)
{
    const Mesh b = noisy_sphere(2, 0.05, 7).mesh;
    const ClosestPointIndex index(b);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3 o(u(rng), u(rng), u(rng));
        const double s = trial % 2 ? 0.05 : 0.5;
        const std::array<Vec3, 3> c{o, o + s * Vec3(u(rng), u(rng), u(rng)), o + s * Vec3(u(rng), u(rng), u(rng))};
        double brute = std::numeric_limits<double>::infinity();
        for (const Face& f : b.faces) {
            double v = 0.0;
            for (const Vec3& q : c)
                v = std::max(v, closest_point_on_triangle(q, b.points[std::size_t(f[0])], b.points[std::size_t(f[1])],
                                                          b.points[std::size_t(f[2])])
                                    .distance);
            brute = std::min(brute, v);
        }
        std::uint32_t face = 0;
        const double got = index.hull_distance_bound(c, 0.0, &face);
        EXPECT_NEAR(got, brute, 1e-15) << trial;
        // A good-enough value stops the search at a value below it (still a
        // bound); below the minimum there is none: +inf.
        const double early = index.hull_distance_bound(c, 2.0 * brute + 0.1);
        EXPECT_LE(early, 2.0 * brute + 0.1);
        EXPECT_GE(early, brute - 1e-15);
        EXPECT_EQ(index.hull_distance_bound(c, 0.999 * brute), std::numeric_limits<double>::infinity());
        EXPECT_LE(index.hull_distance_bound(c, brute * (1 + 1e-12)), brute * (1 + 1e-12));
        // It is an upper bound of the distance of the triangle's points.
        for (double w : {0.2, 0.5})
            EXPECT_LE(index.closest_point(w * c[0] + (1 - w) / 2 * (c[1] + c[2])).distance, got);
    }
}

TEST(Hausdorff, InteriorMaximumAtACircumcentre)
{
    const Circumcentre t;
    const double exact = 13.0 / 12.0;
    for (double rel : {1e-3, 1e-6, 1e-9}) {
        HausdorffOptions o;
        o.relative_tolerance = rel;
        const CertifiedHausdorff h = certified_hausdorff(t.a, t.b, o);
        expect_certified(h);
        expect_contains(h, exact);
        EXPECT_NEAR(h.tolerance, rel * h.lower, 1e-15);
        // The location is where the lower bound is attained, near the circumcentre.
        EXPECT_DOUBLE_EQ(h.lower, (h.location.point - h.location.closest_point).norm());
        EXPECT_LT((h.location.point - Vec3(0, 5.0 / 12.0, 0)).norm(), 10 * std::sqrt(rel)) << rel;
        EXPECT_EQ(h.location.face, 0u);
        EXPECT_GT(h.rounds, 0);
    }
    // Metro's sampling misses the interior maximum; the certified lower bound does not.
    const SurfaceDistance sd = surface_distance(t.a, t.b);
    EXPECT_LT(sd.forward.max, exact - 1e-4);
}

namespace {

// The square [-1, 1]^2 as a fan of four triangles around its centre, the
// centre raised to height h (a pyramid for h > 0), moved by shift.
Mesh raised_square(double h, const Vec3& shift = Vec3::Zero())
{
    Mesh m;
    m.points = {{0, 0, h}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}};
    m.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
    for (Vec3& p : m.points) p += shift;
    return m;
}

}  // namespace

TEST(Hausdorff, RaisedCentreOfASquareInBothDirections)
{
    // A: the square [-1, 1]^2 as a fan of four triangles around its centre;
    // B: the same with the centre raised to height h, a pyramid.
    const double h = 0.3;
    const Mesh a = raised_square(0.0), b = raised_square(h);
    // A -> B: the centre of A is farthest, at distance h / sqrt(1 + h^2) from
    // each slanted face. B -> A: the apex, at height h above A.
    const CertifiedHausdorff f = certified_hausdorff(a, b, {});
    const CertifiedHausdorff g = certified_hausdorff(b, a, {});
    expect_certified(f);
    expect_certified(g);
    expect_contains(f, h / std::sqrt(1 + h * h));
    expect_contains(g, h);
    EXPECT_LT((f.location.point - Vec3::Zero()).norm(), 1e-12);
    EXPECT_LT((g.location.point - Vec3(0, 0, h)).norm(), 1e-12);
    EXPECT_LT((g.location.closest_point - Vec3::Zero()).norm(), 1e-12);
}

TEST(Hausdorff, AMaximumAtAVertexComesWithItsClosestPoint)
{
    // The raised square again, moved away from the origin: B -> A is largest
    // at B's apex, a vertex, whose closest point on A (the fan's centre) the
    // certification finds again from the vertex (it keeps the vertices'
    // distances and faces only): the index's closest point, bit for bit.
    const Vec3 shift(5.0, 7.0, 3.0);
    const Mesh a = raised_square(0.0, shift), b = raised_square(0.3, shift);
    const CertifiedHausdorff g = certified_hausdorff(b, a, {});
    expect_certified(g);
    EXPECT_EQ(g.location.point, b.points[0]);
    const ClosestPoint q = ClosestPointIndex(a).closest_point(b.points[0]);
    EXPECT_EQ(g.location.closest_point, q.point);
    EXPECT_EQ(g.location.closest_face, q.face);
    EXPECT_LT((g.location.closest_point - shift).norm(), 1e-12);
}

TEST(Hausdorff, ParallelPlanesAndTheMeshItself)
{
    const Mesh a = plane_grid(9, 7, 0.25).mesh;
    Mesh b = a;
    for (Vec3& p : b.points) p.z() += 0.125;
    for (const auto& h : {certified_hausdorff(a, b, {}), certified_hausdorff(b, a, {})}) {
        expect_certified(h);
        EXPECT_DOUBLE_EQ(h.lower, 0.125);
        EXPECT_LE(h.upper, 0.125 * (1 + 1e-4));
    }
    // A mesh against itself: [0, tiny], at once.
    const Mesh s = icosphere(3).mesh;
    const CertifiedHausdorff self = certified_hausdorff(s, s, {});
    expect_certified(self);
    EXPECT_EQ(self.lower, 0.0);
    EXPECT_LE(self.upper, 1e-12);
    EXPECT_EQ(self.rounds, 0);
}

TEST(Hausdorff, FarApartMeshes)
{
    // One triangle against a cloud of triangles 100 units away.
    Mesh a;
    add_triangle(a, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    Mesh b;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 60; ++i) {
        const Vec3 o = 100.0 * Vec3(u(rng), u(rng), u(rng)).normalized();
        add_triangle(b, o, o + Vec3(u(rng), u(rng), u(rng)), o + Vec3(u(rng), u(rng), u(rng)));
    }
    HausdorffOptions o;
    o.relative_tolerance = 1e-9;
    const CertifiedHausdorff h = certified_hausdorff(a, b, o);
    expect_certified(h);
    const double dense = dense_maximum(a, b, 200);
    EXPECT_LE(dense, h.upper * (1 + 1e-12));
    EXPECT_GE(h.lower, dense - o.relative_tolerance * 100 * 2);
    EXPECT_GT(h.lower, 90.0);
}

TEST(Hausdorff, CoarseSphereAgainstAFineOneBeatsSampling)
{
    // The maxima lie inside faces (the flat faces of the coarse sphere sag
    // below the fine one), where vertex and edge samples are not.
    const Mesh a = icosphere(2).mesh;
    const Mesh b = icosphere(5).mesh;
    const SurfaceDistance sd = surface_distance(a, b, {}, false, HausdorffOptions{});
    ASSERT_TRUE(sd.forward_hausdorff && sd.backward_hausdorff);
    for (const auto* h : {&*sd.forward_hausdorff, &*sd.backward_hausdorff}) {
        expect_certified(*h);
        EXPECT_GT(h->lower, 0.0);
    }
    EXPECT_GE(sd.forward_hausdorff->lower, sd.forward.max);
    EXPECT_GE(sd.backward_hausdorff->lower, sd.backward.max);
    const double dense_forward = dense_maximum(a, b, 64);
    EXPECT_LE(dense_forward, sd.forward_hausdorff->upper * (1 + 1e-12));
    EXPECT_GE(sd.forward_hausdorff->lower, dense_forward * (1 - 1e-4));
    const double dense_backward = dense_maximum(b, a, 4);
    EXPECT_LE(dense_backward, sd.backward_hausdorff->upper * (1 + 1e-12));
}

TEST(Hausdorff, OneTenThousandthGivesFourCertainDigitsOnRealMeshes)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
        const CertifiedHausdorff h = certified_hausdorff(*x, *y, {});
        expect_certified(h);
        EXPECT_LE(h.upper - h.lower, 1e-4 * h.lower);
        EXPECT_LE(dense_maximum(*x, *y, 6), h.upper * (1 + 1e-12));
        const ClosestPoint q = ClosestPointIndex(*y).closest_point(h.location.point);
        EXPECT_DOUBLE_EQ(q.distance, h.lower);
        EXPECT_EQ(q.face, h.location.closest_face);
    }
}

TEST(Hausdorff, DegenerateAndNonManifoldMeshes)
{
    // A: an open strip with a zero-area face (repeated corner) and a sliver;
    // B: three triangles sharing one edge (non-manifold) and a point.
    Mesh a;
    a.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.2}, {1, 1, 0.1}, {2, 0, 0}, {2, 1e-9, 0}};
    a.faces = {{0, 1, 2}, {1, 3, 2}, {1, 1, 3}, {1, 4, 5}};
    Mesh b;
    b.points = {{0, 0, 0.5}, {2, 0, 0.5}, {1, 1, 0.5}, {1, -1, 0.6}, {1, 0.2, 1.5}, {3, 3, 3}};
    b.faces = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {5, 5, 5}};
    for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
        HausdorffOptions o;
        o.relative_tolerance = 1e-7;
        const CertifiedHausdorff h = certified_hausdorff(*x, *y, o);
        expect_certified(h);
        EXPECT_LE(dense_maximum(*x, *y, 300), h.upper * (1 + 1e-12));
        EXPECT_GE(h.lower, dense_maximum(*x, *y, 300) * (1 - 1e-4));
    }
}

namespace {
// The same interval, location and work, to the bit.
void expect_same_result(const CertifiedHausdorff& x, const CertifiedHausdorff& y)
{
    EXPECT_TRUE(same_bits(x.lower, y.lower));
    EXPECT_TRUE(same_bits(x.upper, y.upper));
    EXPECT_EQ(x.location.point, y.location.point);
    EXPECT_EQ(x.location.face, y.location.face);
    EXPECT_EQ(x.location.closest_face, y.location.closest_face);
    EXPECT_EQ(x.bound_evaluations, y.bound_evaluations);
    EXPECT_EQ(x.rounds, y.rounds);
}

// certified_hausdorff(a, b, o) on 1 thread and on \p many (at least), the
// thread count restored after.
std::pair<CertifiedHausdorff, CertifiedHausdorff> on_one_and_many_threads(const Mesh& a, const Mesh& b,
                                                                          const HausdorffOptions& o, int many)
{
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    CertifiedHausdorff one = certified_hausdorff(a, b, o);
    omp_set_num_threads(std::max(many, threads));
    CertifiedHausdorff more = certified_hausdorff(a, b, o);
    omp_set_num_threads(threads);
    return {std::move(one), std::move(more)};
}
}  // namespace

TEST(Hausdorff, SameIntervalAndLocationForAnyThreadCount)
{
    const Mesh a = noisy_sphere(3, 0.03, 5).mesh;
    const Mesh b = icosphere(4).mesh;
    HausdorffOptions o;
    o.relative_tolerance = 1e-8;
    const auto [one, many] = on_one_and_many_threads(a, b, o, 2);
    expect_same_result(one, many);
}

// Rounds of more open cells than a block of parts is made from (16K cells):
// the parts are bounded block by block and the open ones made again, in
// order, whatever the thread count. A coarse sphere against a finer one: every
// face sags about as far, so the round after the first splits every one of
// the coarse sphere's 20480 faces (two blocks).
TEST(Hausdorff, RoundsMadeInBlocksGiveTheStoredIntervalAtAnyThreadCount)
{
    const Mesh a = icosphere(5).mesh;
    const Mesh b = icosphere(6).mesh;
    HausdorffOptions o;
    o.relative_tolerance = 1e-9;
    const auto [one, many] = on_one_and_many_threads(a, b, o, 3);
    expect_certified(one);
    expect_same_result(one, many);
    // The first round (a cell per face) and four parts of every face in the next.
    EXPECT_GE(one.bound_evaluations, 5u * a.n_faces());
    // The search before its rounds were made in blocks (fcdf8de: all four
    // parts of every cell held, then bounded and pruned), stored: the same
    // interval, location and work to the last bit. A part bounded or kept in
    // the wrong place changes the work, if not the interval.
    EXPECT_EQ(one.lower, 0x1.bff59d96526efp-13);
    EXPECT_EQ(one.upper, 0x1.bff59d9ae917ep-13);
    EXPECT_EQ(one.bound_evaluations, 117520u);
    EXPECT_EQ(one.point_evaluations, 73362u);
    EXPECT_EQ(one.rounds, 22);
    EXPECT_EQ(one.location.face, 1021u);
    EXPECT_EQ(one.location.closest_face, 4087u);
}

// The certification's bounds with the AVX2 kernel (where the CPU has it) and
// without: the same interval, location and work, to the bit.
TEST(Hausdorff, VectorAndScalarKernelsGiveTheSameInterval)
{
    const Mesh a = noisy_sphere(3, 0.03, 5).mesh;
    const Mesh b = read_mesh(kData + "/sphere_irregular_3072.ply").mesh;
    HausdorffOptions o;
    o.relative_tolerance = 1e-8;
    for (const auto& [x, y] : {std::pair<const Mesh*, const Mesh*>{&a, &b}, {&b, &a}}) {
        const bool before = detail::allow_vector_kernels(false);
        const CertifiedHausdorff scalar = certified_hausdorff(*x, *y, o);
        detail::allow_vector_kernels(true);
        const CertifiedHausdorff vector = certified_hausdorff(*x, *y, o);
        detail::allow_vector_kernels(before);
        expect_same_result(scalar, vector);
    }
}

TEST(Hausdorff, BudgetStopsWithAValidInterval)
{
    const Circumcentre t;
    HausdorffOptions o;
    o.relative_tolerance = 1e-12;
    o.max_evaluations = 40;
    const CertifiedHausdorff h = certified_hausdorff(t.a, t.b, o);
    EXPECT_TRUE(h.budget_exhausted);
    EXPECT_FALSE(h.certified);
    EXPECT_LE(h.bound_evaluations, 40u);
    expect_contains(h, 13.0 / 12.0);
    EXPECT_GT(h.upper - h.lower, h.tolerance);
}

TEST(Hausdorff, MemoryBoundTakesTheOpenTrianglesInParts)
{
    // A coarse sphere against a fine one: every face of the coarse one sags
    // about as far, so many triangles stay open in the first rounds.
    const Mesh a = icosphere(2).mesh;
    const Mesh b = icosphere(4).mesh;
    HausdorffOptions o;
    const CertifiedHausdorff full = certified_hausdorff(a, b, o);
    expect_certified(full);
    EXPECT_EQ(full.chunks, 0);
    for (const std::size_t bound : {std::size_t(4), std::size_t(64), std::size_t(1000)}) {
        o.max_round_triangles = bound;  // at most bound / 4 open triangles per round
        const CertifiedHausdorff h = certified_hausdorff(a, b, o);
        expect_certified(h);
        EXPECT_GT(h.chunks, 0) << bound;
        // Both intervals hold the true value: they overlap.
        EXPECT_LE(h.lower, full.upper) << bound;
        EXPECT_GE(h.upper, full.lower) << bound;
        // A dense sampling's maximum is at most the true value.
        SamplingOptions so;
        so.samples = 200'000;
        const ClosestPointIndex index(b);
        const DistanceStats dense = one_sided_distance(a, index, so);
        EXPECT_GE(h.upper, dense.max) << bound;
    }
    o.max_round_triangles = 3;
    EXPECT_THROW(certified_hausdorff(a, b, o), InvalidArgumentError);
}

TEST(Hausdorff, AbsoluteToleranceAndSeed)
{
    const Circumcentre t;
    HausdorffOptions o;
    o.relative_tolerance = 0.0;
    o.absolute_tolerance = 2e-7;
    const CertifiedHausdorff h = certified_hausdorff(t.a, t.b, o);
    expect_certified(h);
    EXPECT_EQ(h.tolerance, 2e-7);
    expect_contains(h, 13.0 / 12.0);
    // A seed joins the lower bound.
    const ClosestPointIndex index(t.b);
    const Vec3 p(0, 5.0 / 12.0, 0);
    const HausdorffSeed seed{p, 0, index.closest_point(p).distance};
    const CertifiedHausdorff s = certified_hausdorff(t.a, t.b, index, o, seed);
    EXPECT_GE(s.lower, seed.distance);
    EXPECT_EQ(s.location.point, p);
}

TEST(Hausdorff, RejectsBadOptionsAndMismatchedIndex)
{
    const Circumcentre t;
    for (auto [rel, abs] : {std::pair{-1e-4, 0.0}, std::pair{1.0, 0.0}, std::pair{0.0, 0.0},
                            std::pair{std::nan(""), 1e-3}, std::pair{1e-4, -1.0}, std::pair{1e-4, HUGE_VAL}}) {
        HausdorffOptions o;
        o.relative_tolerance = rel;
        o.absolute_tolerance = abs;
        EXPECT_THROW(certified_hausdorff(t.a, t.b, o), InvalidArgumentError) << rel << " " << abs;
    }
    const ClosestPointIndex wrong(t.a);
    EXPECT_THROW(certified_hausdorff(t.a, t.b, wrong), InvalidArgumentError);
    Mesh empty;
    empty.points = {{0, 0, 0}};
    EXPECT_THROW(certified_hausdorff(empty, t.b, {}), InvalidMeshError);
}

TEST(Hausdorff, EveryBundledPairIsCertifiedAboveItsSampledMaximum)
{
    // The pairs of the reference cross-check with CGAL (reference/out/9_hausdorff/cgal.md).
    const std::pair<const char*, const char*> pairs[] = {{"bunny_res3.ply", "bunny_res4_ascii.ply"},
                                                         {"sphere_ico_2562.ply", "sphere_irregular_3072.ply"},
                                                         {"sphere_ico_2562.ply", "ellipsoid_150_100_100.ply"},
                                                         {"hemisphere.ply", "sphere_ico_2562.ply"},
                                                         {"torus_R1_r025.ply", "hemisphere.ply"}};
    for (const auto& [x, y] : pairs) {
        const Mesh a = read_mesh(kData + "/" + x).mesh;
        const Mesh b = read_mesh(kData + "/" + y).mesh;
        const SurfaceDistance sd = surface_distance(a, b, {}, false, HausdorffOptions{});
        ASSERT_TRUE(sd.forward_hausdorff && sd.backward_hausdorff);
        for (const auto& [h, sampled] :
             {std::pair{&*sd.forward_hausdorff, sd.forward.max}, std::pair{&*sd.backward_hausdorff, sd.backward.max}}) {
            expect_certified(*h);
            EXPECT_GE(h->lower, sampled) << x << " " << y;
            EXPECT_LE(h->upper - h->lower, 1e-4 * h->lower) << x << " " << y;
            EXPECT_DOUBLE_EQ((h->location.point - h->location.closest_point).norm(), h->lower) << x << " " << y;
        }
    }
}

TEST(Hausdorff, TriangleSoupAndSplitTargetsGiveTheSameInterval)
{
    // The search descends over B's edge-adjacent triangles; a soup (no shared
    // vertex: no neighbours) and a mesh cut in two (a boundary across the
    // surface) must fall back on the hierarchy search and give an interval
    // that overlaps the connected mesh's, since each contains the true value
    // (the three B's are the same surface).
    const Mesh a = icosphere(2).mesh;
    const Mesh b = icosphere(4).mesh;
    Mesh soup, cut;
    for (const Face& f : b.faces) add_triangle(soup, b.points[f[0]], b.points[f[1]], b.points[f[2]]);
    cut.points = b.points;
    for (const Face& f : b.faces) {
        const bool upper = b.points[f[0]].z() + b.points[f[1]].z() + b.points[f[2]].z() > 0.0;
        Face g = f;
        if (upper)
            for (auto& v : g) v += int(b.points.size());
        cut.faces.push_back(g);
    }
    cut.points.insert(cut.points.end(), b.points.begin(), b.points.end());
    const CertifiedHausdorff whole = certified_hausdorff(a, b, {});
    expect_certified(whole);
    for (const Mesh* m : {&soup, &cut}) {
        const CertifiedHausdorff h = certified_hausdorff(a, *m, {});
        expect_certified(h);
        EXPECT_LE(std::max(h.lower, whole.lower), std::min(h.upper, whole.upper));
        const CertifiedHausdorff back = certified_hausdorff(*m, a, {});
        const CertifiedHausdorff whole_back = certified_hausdorff(b, a, {});
        expect_certified(back);
        EXPECT_LE(std::max(back.lower, whole_back.lower), std::min(back.upper, whole_back.upper));
    }
}

TEST(Hausdorff, CertifyingKeepsTheSampledNumbersBitForBit)
{
    // surface_distance() reuses its vertex samples' queries for the
    // certification and the vertex distances: every sampled number equals the
    // one of a run without certification, and the interval equals that of
    // certified_hausdorff() with the same seed.
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const SurfaceDistance plain = surface_distance(a, b, {}, true);
    const SurfaceDistance cert = surface_distance(a, b, {}, true, HausdorffOptions{});
    for (const auto& [x, y] : {std::pair{&plain.forward, &cert.forward}, std::pair{&plain.backward, &cert.backward}}) {
        EXPECT_EQ(x->min, y->min);
        EXPECT_EQ(x->max, y->max);
        EXPECT_EQ(x->mean, y->mean);
        EXPECT_EQ(x->rms, y->rms);
        EXPECT_EQ(x->p50, y->p50);
        EXPECT_EQ(x->p99, y->p99);
        EXPECT_EQ(x->max_element, y->max_element);
    }
    ASSERT_EQ(plain.b_vertex_distance.size(), b.n_vertices());
    EXPECT_EQ(plain.b_vertex_distance, cert.b_vertex_distance);
    ASSERT_TRUE(cert.forward_hausdorff);
    const ClosestPointIndex index(b);
    HausdorffSeed seed{cert.forward.max_point, 0, cert.forward.max};
    if (cert.forward.max_kind == SampleKind::OnVertex) {
        for (std::size_t f = 0; f < a.n_faces(); ++f)
            if (std::find(a.faces[f].begin(), a.faces[f].end(), int(cert.forward.max_element)) != a.faces[f].end()) {
                seed.face = std::uint32_t(f);
                break;
            }
    } else {
        seed.face = cert.forward.max_element;
    }
    const CertifiedHausdorff h = certified_hausdorff(a, b, index, {}, seed);
    EXPECT_EQ(h.lower, cert.forward_hausdorff->lower);
    EXPECT_EQ(h.upper, cert.forward_hausdorff->upper);
    EXPECT_EQ(h.location.face, cert.forward_hausdorff->location.face);
}

TEST(Hausdorff, TwoTriangulationsOfOneSurfaceAreCertifiedWithinTheBudget)
{
    // A remesher's pair: every triangle of one lies within the sag of the
    // other, so it is bounded only by cutting it along the planes between
    // the other's adjacent triangles (one triangle bounds no cell over an
    // edge or a vertex). Before those cuts the budget ran out here.
    const Mesh a = torus_irregular(3000, 1.0, 0.3, 1).mesh;
    const Mesh b = torus_irregular(3000, 1.0, 0.3, 2).mesh;
    for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
        const CertifiedHausdorff h = certified_hausdorff(*x, *y, {});
        expect_certified(h);
        EXPECT_FALSE(h.budget_exhausted);
        EXPECT_LT(h.bound_evaluations, 40 * x->n_faces());
        EXPECT_LE(dense_maximum(*x, *y, 8), h.upper * (1 + 1e-12));
        EXPECT_LE(h.upper - h.lower, 1e-4 * h.lower);
    }
}

// Each thread remembers the bisecting planes of the target's edges it made
// last (hausdorff_bounds.cpp), by half-edge: a second target with the same
// faces over other points has the same half-edges and other planes. The
// pair certified before and after it gives the same interval, the same cuts.
TEST(Hausdorff, PlanesOfAnotherTargetWithTheSameFacesAreNotReused)
{
    const Mesh a = torus_irregular(3000, 1.0, 0.3, 1).mesh;
    const Mesh b = torus_irregular(3000, 1.0, 0.3, 2).mesh;
    Mesh stretched = b;  // the same faces; not a similar shape, so not the same planes
    for (Vec3& p : stretched.points) p = Vec3(1.3 * p.x(), p.y(), 0.8 * p.z());
    const int threads = omp_get_max_threads();
    for (const int n : {1, 2}) {
        omp_set_num_threads(n);
        const CertifiedHausdorff before = certified_hausdorff(a, b, {});
        const CertifiedHausdorff other = certified_hausdorff(a, stretched, {});
        expect_certified(other);
        const CertifiedHausdorff after = certified_hausdorff(a, b, {});
        expect_certified(after);
        expect_same_result(before, after);
    }
    omp_set_num_threads(threads);
}
