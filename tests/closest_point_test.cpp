#include "meshdiff/geometry/closest_point.h"

#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include "geometry/bvh_build.h"
#include "geometry/simd.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>

using namespace meshdiff;

namespace {

const std::string kData = MESHDIFF_TEST_DATA_DIR;

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

// \p n slivers around vertex 0, a wavy rim.
Mesh fan(int n)
{
    Mesh m;
    m.points.emplace_back(0.0, 0.0, 0.1);
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        m.points.emplace_back(std::cos(a), std::sin(a), 0.01 * std::sin(7.0 * a));
    }
    for (int i = 0; i < n; ++i) m.faces.push_back({0, 1 + i, 1 + (i + 1) % n});
    return m;
}

}  // namespace

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

// Regression (scripts/fuzz_arrays.py trial 143): a mesh scaled to subnormal
// coordinates made the build's bin scale kBins / extent infinite, a centroid
// at the box's low end binned NaN and the partition wrote out of bounds.
TEST(ClosestPoint, SubnormalCoordinatesBuildAndAnswerAsBruteForce)
{
    for (const double scale : {5e-324, 1e-320, 1e-310}) {
        Mesh m = icosphere(1, 1.0).mesh;
        for (Vec3& p : m.points) p *= scale;
        const ClosestPointIndex index(m);
        for (const Vec3& p : {Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(-2e-300, 3e-300, 0), Vec3(0.3, -0.4, 1e3)}) {
            const ClosestPoint bf = closest_point_brute_force(m, p);
            const ClosestPoint ix = index.closest_point(p);
            EXPECT_EQ(ix.distance, bf.distance) << scale << " " << p.transpose();
            EXPECT_TRUE(std::isfinite(ix.distance));
        }
    }
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

TEST(ClosestPoint, IndexHoldsItsTrianglesInUnder72BytesAFace)
{
    // The index's triangles are positions into its own copy of the used
    // points (16 bytes a triangle, and 24 a point: a closed mesh has half as
    // many vertices as faces), beside the 4-wide tree and its tables (about
    // 40 bytes a face): 67 bytes a face on this sphere. Corners copied into
    // every triangle (80 bytes a face, 119 in all) would not fit; the same
    // distances either way (the brute-force tests above and below).
    const Mesh m = icosphere(6).mesh;
    const ClosestPointIndex index(m);
    EXPECT_LT(index.memory_bytes(), 72 * m.n_faces());
    EXPECT_GT(index.memory_bytes(), 40 * m.n_faces());
}

TEST(ClosestPoint, IndexEqualsBruteForceExactlyOnAFan)
{
    // 4000 slivers around one vertex: every triangle's box contains the hub
    // region, so the index bounds them by oriented boxes too. Queries on the
    // surface (along the hub's edges and inside the slivers, where the nearest
    // triangles tie at distance 0 or nearly), off it, and the hub itself: the
    // index's distance and face equal the brute force's (lowest face on ties).
    const int n = 4000;
    const Mesh m = fan(n);
    const ClosestPointIndex index(m);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> queries = {m.points[0]};
    for (int k = 0; k < 300; ++k) {
        const std::size_t i = 1 + std::size_t(rng() % std::uint64_t(n));
        const std::size_t j = 1 + i % std::size_t(n);
        const double t = std::pow(u(rng), 3.0), s = u(rng);
        queries.push_back(m.points[0] + t * (m.points[i] - m.points[0]));                              // on a hub edge
        queries.push_back(m.points[0] + t * ((1 - s) * m.points[i] + s * m.points[j] - m.points[0]));  // in a sliver
        queries.push_back(queries.back() + Vec3(0, 0, 1e-3 * (u(rng) - 0.5)));                         // just off it
        queries.push_back(Vec3(2 * u(rng) - 1, 2 * u(rng) - 1, u(rng) - 0.5));                         // around
    }
    for (const Vec3& p : queries) {
        const ClosestPoint bf = closest_point_brute_force(m, p);
        const ClosestPoint ix = index.closest_point(p);
        ASSERT_EQ(ix.distance, bf.distance) << p.transpose();
        ASSERT_EQ(ix.face, bf.face) << p.transpose();
    }
    const auto batch = index.distances(queries);
    for (std::size_t k = 0; k < queries.size(); ++k)
        ASSERT_EQ(batch[k], closest_point_brute_force(m, queries[k]).distance) << k;
    EXPECT_EQ(index.closest_point(m.points[0]).face, 0u);  // the hub: every face at distance 0
}

TEST(ClosestPoint, DistancesOfARangeEqualTheWholeBatch)
{
    const Mesh m = icosphere(3).mesh;
    const ClosestPointIndex index(m);
    std::vector<Vec3> q;
    for (int i = 0; i < 3000; ++i) q.push_back(Vec3(std::sin(i), std::cos(1.3 * i), std::sin(0.7 * i)) * 1.2);
    const std::vector<double> all = index.distances(q);
    std::vector<double> part(q.size() - 777, -1.0);
    index.distances(q.data() + 777, part.size(), part.data());
    for (std::size_t i = 0; i < part.size(); ++i) EXPECT_EQ(part[i], all[777 + i]) << i;
    index.distances(q.data(), 0, nullptr);  // nothing to do
}

// The order in which a batch's queries run (the surface distance runs a
// chunk's samples in Morton order of their elements) changes no answer: each
// query's distance, closest point, face, region and position are the same
// bits as in the given order, at one thread and two; and every query runs
// once, under its own index.
TEST(ClosestPoint, QueryOrderChangesNoAnswer)
{
    const Mesh m = icosphere(3).mesh;
    const ClosestPointIndex index(m);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    std::vector<Vec3> q;
    for (int i = 0; i < 5000; ++i) q.push_back(Vec3(u(rng), u(rng), u(rng)));
    struct Seen
    {
        double distance = -1.0;
        Vec3 point = Vec3::Zero();
        std::uint32_t face = 0, position = 0;
        unsigned region = 0, visits = 0;
    };
    std::vector<std::uint32_t> sequence;  // the queries as they ran (one thread)
    auto run = [&](const std::uint32_t* order, std::vector<double>& out) {
        std::vector<Seen> seen(q.size());
        out.assign(q.size(), -1.0);
        sequence.clear();
        detail::distances_with_regions(
            index, q.data(), q.size(), out.data(),
            [&](std::size_t i, const ClosestPoint& c, unsigned region, std::uint32_t position) {
                seen[i] = {c.distance, c.point, c.face, position, region, seen[i].visits + 1};
                if (omp_get_num_threads() == 1) sequence.push_back(std::uint32_t(i));
            },
            {}, order);
        return seen;
    };
    std::vector<double> given;
    const std::vector<Seen> expected = run(nullptr, given);
    std::vector<std::uint32_t> reversed(q.size()), shuffled(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) reversed[i] = std::uint32_t(q.size() - 1 - i);
    std::iota(shuffled.begin(), shuffled.end(), 0u);
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const int threads = omp_get_max_threads();
    for (const auto* order : {&reversed, &shuffled})
        for (const int t : {1, 2}) {
            omp_set_num_threads(t);
            std::vector<double> out;
            const std::vector<Seen> seen = run(order->data(), out);
            if (t == 1) {
                EXPECT_TRUE(sequence == *order);  // they ran in that order
            }
            for (std::size_t i = 0; i < q.size(); ++i) {
                ASSERT_EQ(seen[i].visits, 1u) << i;
                ASSERT_EQ(std::memcmp(&out[i], &given[i], sizeof(double)), 0) << i;
                ASSERT_EQ(std::memcmp(&seen[i].distance, &expected[i].distance, sizeof(double)), 0) << i;
                ASSERT_EQ(std::memcmp(seen[i].point.data(), expected[i].point.data(), 3 * sizeof(double)), 0) << i;
                ASSERT_EQ(seen[i].face, expected[i].face) << i;
                ASSERT_EQ(seen[i].position, expected[i].position) << i;
                ASSERT_EQ(seen[i].region, expected[i].region) << i;
            }
        }
    omp_set_num_threads(threads);
}

// The AVX2 leaf kernel (where the CPU has it) and the scalar loop give the
// same closest point, face and distance bits, on meshes with thin and
// degenerate triangles too; and so the same hull bounds.
TEST(ClosestPoint, VectorAndScalarKernelsGiveTheSameAnswersBitForBit)
{
    for (const Mesh& m : {read_mesh(kData + "/bunny_res3.ply").mesh, read_mesh(kData + "/teapot.obj").mesh,
                          mesh_with_degenerate_faces(), read_mesh(kData + "/fandisk.ply").mesh}) {
        const ClosestPointIndex index(m);
        const auto queries = random_queries(m, 20000, 11);
        const bool before = detail::allow_vector_kernels(false);
        const auto scalar = index.closest_points(queries);
        std::vector<double> scalar_hull;
        for (std::size_t f = 0; f < m.n_faces(); f += 7) {
            const Face& t = m.faces[f];
            scalar_hull.push_back(
                index.hull_distance_bound({m.points[std::size_t(t[0])] + Vec3(1e-3, 0, 0), m.points[std::size_t(t[1])],
                                           m.points[std::size_t(t[2])] - Vec3(0, 2e-3, 0)},
                                          0.0));
        }
        detail::allow_vector_kernels(true);
        const auto vector = index.closest_points(queries);
        std::size_t h = 0;
        for (std::size_t f = 0; f < m.n_faces(); f += 7, ++h) {
            const Face& t = m.faces[f];
            const double v =
                index.hull_distance_bound({m.points[std::size_t(t[0])] + Vec3(1e-3, 0, 0), m.points[std::size_t(t[1])],
                                           m.points[std::size_t(t[2])] - Vec3(0, 2e-3, 0)},
                                          0.0);
            ASSERT_EQ(std::memcmp(&v, &scalar_hull[h], sizeof(double)), 0) << f;
        }
        detail::allow_vector_kernels(before);
        for (std::size_t i = 0; i < queries.size(); ++i) {
            ASSERT_EQ(std::memcmp(&scalar[i].distance, &vector[i].distance, sizeof(double)), 0) << i;
            ASSERT_EQ(scalar[i].face, vector[i].face) << i;
            ASSERT_EQ(std::memcmp(scalar[i].point.data(), vector[i].point.data(), 3 * sizeof(double)), 0) << i;
        }
    }
}

// Needles (thin: their face-region projection is not used) in the same
// leaves as ordinary triangles, and points just above them: the vector path,
// which tests a leaf's triangles four at once and its thin ones alone, gives
// the scalar loop's and the brute force's answers, bit for bit. (The kernel's
// projection onto a needle would differ from the thin rule's closest point by
// about the needle's width, 1e-10: tens of units in the last place of the
// squared distance.)
TEST(ClosestPoint, ThinTrianglesBesideOthersInALeafKeepTheThinRule)
{
    Mesh m;
    for (int k = 0; k < 200; ++k) {
        const double y = 0.01 * k;
        const auto v = int(m.points.size());
        m.points.push_back(Vec3(0, y, 0));
        m.points.push_back(Vec3(1, y, 0));
        m.points.push_back(Vec3(0.5, y + 1e-10, 0));  // a needle: sine at a corner 2e-10
        m.points.push_back(Vec3(0.2, y + 0.004, 0.01));
        m.points.push_back(Vec3(0.8, y + 0.004, 0.01));
        m.points.push_back(Vec3(0.5, y + 0.006, 0.02));
        m.faces.push_back({v, v + 1, v + 2});
        m.faces.push_back({v + 3, v + 4, v + 5});
    }
    const ClosestPointIndex index(m);
    std::size_t thin = 0, ordinary = 0;
    const detail::Bvh& bvh = detail::bvh_of(index);
    for (std::size_t i = 0; i < bvh.tris.size(); ++i) (bvh.tris[i].thin ? thin : ordinary) += 1;
    ASSERT_EQ(thin, 200u);
    ASSERT_EQ(ordinary, 200u);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> queries;
    for (int k = 0; k < 200; ++k)
        for (int j = 0; j < 10; ++j)
            queries.push_back(Vec3(0.1 + 0.8 * u(rng), 0.01 * k + 0.5e-10, 1e-3 * (0.5 + u(rng))));
    const bool before = detail::allow_vector_kernels(false);
    const auto scalar = index.closest_points(queries);
    detail::allow_vector_kernels(true);
    const auto vector = index.closest_points(queries);
    detail::allow_vector_kernels(before);
    std::size_t on_needles = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
        const ClosestPoint bf = closest_point_brute_force(m, queries[i]);
        for (const ClosestPoint* r : {&scalar[i], &vector[i]}) {
            ASSERT_EQ(std::memcmp(&r->distance, &bf.distance, sizeof(double)), 0) << i;
            ASSERT_EQ(r->face, bf.face) << i;
            ASSERT_EQ(std::memcmp(r->point.data(), bf.point.data(), 3 * sizeof(double)), 0) << i;
        }
        on_needles += bf.face % 2 == 0;
    }
    EXPECT_EQ(on_needles, queries.size());  // every query's closest face is a needle
}

namespace {
std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t n)
{
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001B3ULL;
    return h;
}

// Answers that depend on the tree's layout, not only on the triangles: a
// hull bound with a target returns the first triangle found below it, in the
// traversal's order. Hashed over many corner triples of \p m.
std::uint64_t hash_of_first_bounds(const Mesh& m, const ClosestPointIndex& index)
{
    std::uint64_t h = 0xCBF29CE484222325ULL;
    const double scale = bounding_box(m).diagonal();
    for (std::size_t f = 0; f < m.n_faces(); f += 3) {
        const Face& t = m.faces[f];
        const std::array<Vec3, 3> c{m.points[std::size_t(t[0])] + Vec3(0.01 * scale, 0, 0), m.points[std::size_t(t[1])],
                                    m.points[std::size_t(t[2])]};
        std::uint32_t face = 0;
        const double v = index.hull_distance_bound(c, 0.05 * scale, &face);
        h = fnv1a(h, &v, sizeof v);
        h = fnv1a(h, &face, sizeof face);
    }
    return h;
}
}  // namespace

// The tree does not depend on the thread count (the build splits the root's
// two subtrees between threads): the first-found hull bounds, which follow the
// tree's order, are the same, and the same as those of the serial build the
// hashes were recorded with (2026-12-02, before the parallel build). The
// teapot (6,320 faces) and fandisk (12,946) are above the 4,096 faces from
// which the build splits; bunny_res3 (3,851) is below.
TEST(ClosestPoint, TreeIsTheSameForAnyThreadCount)
{
    const std::pair<const char*, std::uint64_t> cases[] = {{"/bunny_res3.ply", 0xA0D1AFA766B50E47ULL},
                                                           {"/fandisk.ply", 0x39C6683C8EDEE934ULL},
                                                           {"/teapot.obj", 0xDC9BF00B22058FFDULL}};
    const int saved = omp_get_max_threads();
    for (const auto& [name, pinned] : cases) {
        const Mesh m = read_mesh(kData + name).mesh;
        omp_set_num_threads(1);
        const std::uint64_t one = hash_of_first_bounds(m, ClosestPointIndex(m));
        omp_set_num_threads(2);
        const std::uint64_t two = hash_of_first_bounds(m, ClosestPointIndex(m));
        EXPECT_EQ(one, two) << name;
        EXPECT_EQ(one, pinned) << name << std::hex << " 0x" << one;
    }
    omp_set_num_threads(saved);
}

namespace {

// The index's tables, field by field (a WideNode's padding is not set).
void expect_same_tables(const detail::Bvh& x, const detail::Bvh& y, const std::string& name)
{
    ASSERT_EQ(x.nodes.size(), y.nodes.size()) << name;
    for (std::size_t w = 0; w < x.nodes.size(); ++w) {
        const detail::WideNode &a = x.nodes[w], &b = y.nodes[w];
        ASSERT_TRUE(a.lo == b.lo && a.hi == b.hi && a.child == b.child && a.count == b.count &&
                    a.obb_first == b.obb_first && a.obb_mask == b.obb_mask && a.slots == b.slots && a.split == b.split)
            << name << " wide node " << w;
    }
    EXPECT_EQ(x.parent_of, y.parent_of) << name;
    EXPECT_EQ(x.leaf_of, y.leaf_of) << name;
    EXPECT_EQ(x.position_of, y.position_of) << name;
    EXPECT_EQ(x.exact_box, y.exact_box) << name;
    ASSERT_EQ(x.obbs.size(), y.obbs.size()) << name;
    for (std::size_t i = 0; i < x.obbs.size(); ++i)
        EXPECT_TRUE(x.obbs[i].centre == y.obbs[i].centre && x.obbs[i].axis == y.obbs[i].axis &&
                    x.obbs[i].half == y.obbs[i].half)
            << name << " box " << i;
    EXPECT_TRUE(x.root_lo == y.root_lo && x.root_hi == y.root_hi && x.root_obb == y.root_obb &&
                x.root_count == y.root_count)
        << name;
    ASSERT_EQ(x.tris.size(), y.tris.size()) << name;
    for (std::size_t i = 0; i < x.tris.size(); ++i)
        ASSERT_TRUE(x.tris.corners[i].v == y.tris.corners[i].v &&
                    x.tris.corners[i].face_thin == y.tris.corners[i].face_thin)
            << name << " triangle " << i;
    EXPECT_EQ(x.tris.points, y.tris.points) << name;
}

// The 4-wide tree numbered depth first, as one walk from the root numbers
// it: each node's inner slots hold the next node and then the ends of their
// subtrees, the oriented boxes follow in that order, the parent and leaf
// tables point back, and every triangle is in one leaf. Returns the end of
// the subtree of node w, and its boxes' end in \p obb.
std::uint32_t expect_depth_first(const detail::Bvh& t, std::uint32_t w, std::size_t& obb)
{
    const detail::WideNode& node = t.nodes[w];
    EXPECT_EQ(node.obb_first, obb) << "wide node " << w;
    obb += std::size_t(__builtin_popcount(node.obb_mask));
    std::uint32_t next = w + 1;
    for (std::uint32_t s = 0; s < node.slots; ++s) {
        if (node.count[s] > 0) {
            for (std::uint32_t i = 0; i < node.count[s]; ++i) EXPECT_EQ(t.leaf_of[node.child[s] + i], 4 * w + s);
            continue;
        }
        EXPECT_EQ(node.child[s], next) << "wide node " << w << " slot " << s;
        EXPECT_EQ(t.parent_of[node.child[s]], 4 * w + s);
        next = expect_depth_first(t, node.child[s], obb);
    }
    return next;
}

}  // namespace

// The tables made from the tree (the 4-wide nodes, their oriented boxes,
// the parent and leaf tables) are written by up to 16 subtrees in parallel,
// each where a walk from the root numbers it: the same bytes on one thread
// and two, numbered depth first. The fan's slivers have oriented boxes; the
// fan and the icosphere are above the 4,096 faces from which the tree grows
// on two threads.
TEST(ClosestPoint, TablesAreTheSameForAnyThreadCountAndNumberedDepthFirst)
{
    std::vector<std::pair<std::string, Mesh>> meshes;
    meshes.emplace_back("fandisk", read_mesh(kData + "/fandisk.ply").mesh);
    meshes.emplace_back("teapot", read_mesh(kData + "/teapot.obj").mesh);
    meshes.emplace_back("fan", fan(6000));
    meshes.emplace_back("icosphere", icosphere(6).mesh);
    meshes.emplace_back("a leaf", plane_grid(2, 2, 1.0).mesh);
    const int saved = omp_get_max_threads();
    for (const auto& [name, m] : meshes) {
        omp_set_num_threads(1);
        const ClosestPointIndex one(m);
        omp_set_num_threads(2);
        const ClosestPointIndex two(m);
        const detail::Bvh& t = detail::bvh_of(two);
        expect_same_tables(detail::bvh_of(one), t, name);
        if (name == "fan") {
            EXPECT_GT(t.obbs.size(), 10u);
        }
        if (t.nodes.empty()) {
            EXPECT_EQ(t.root_count, m.n_faces()) << name;
            continue;
        }
        std::size_t obb = t.root_obb == 0 ? 1 : 0;
        EXPECT_EQ(expect_depth_first(t, 0, obb), t.nodes.size()) << name;
        EXPECT_EQ(obb, t.obbs.size()) << name;
        std::vector<int> in_leaves(m.n_faces(), 0);
        for (const detail::WideNode& node : t.nodes)
            for (std::uint32_t s = 0; s < node.slots; ++s)
                for (std::uint32_t i = 0; i < node.count[s]; ++i) ++in_leaves[node.child[s] + i];
        EXPECT_EQ(std::count(in_leaves.begin(), in_leaves.end(), 1), std::ptrdiff_t(m.n_faces())) << name;
    }
    omp_set_num_threads(saved);
}
