#include "meshdiff/roughness/neighborhood.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include "core/parallel_sort.h"
#include "geometry/simd.h"
#include "roughness/level_stream.h"
#include "roughness/morton.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace meshdiff;
using meshdiff::test::data;

namespace {

// Appends \p part to \p mesh, shifted by \p offset, as a separate component.
void append(Mesh& mesh, const Mesh& part, const Vec3& offset)
{
    const auto base = std::int32_t(mesh.n_vertices());
    for (const auto& p : part.points) mesh.points.push_back(p + offset);
    for (auto f : part.faces) mesh.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
}

// A fan of 1500 triangles around vertex 0 (valence above 1024: vertices
// reached by a whole mask word at once add their value once per word) and a
// grid beside it, joined to the rim: from level 2 on a rim centre's disk holds
// the whole rim.
Mesh hub_mesh()
{
    Mesh mesh;
    const int n = 1500;
    mesh.points.emplace_back(0.0, 0.0, 0.1);
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        mesh.points.emplace_back(std::cos(a), std::sin(a), 0.01 * std::sin(7.0 * a));
    }
    for (int i = 0; i < n; ++i) mesh.faces.push_back({0, 1 + i, 1 + (i + 1) % n});
    append(mesh, plane_grid(20, 20, 0.1).mesh, Vec3(1.5, 0, 0));
    mesh.faces.push_back({1, n + 1, n + 2});  // rim vertex 1 to the grid's first two vertices
    return mesh;
}

// \p mesh with its vertices in a random order (new id of old vertex i: a
// shuffle of 0..n-1 by \p seed), its neighbours scattered in memory.
Mesh shuffled(const Mesh& mesh, unsigned seed)
{
    const std::size_t n = mesh.n_vertices();
    std::vector<std::uint32_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0u);
    std::shuffle(perm.begin(), perm.end(), std::mt19937(seed));
    Mesh out;
    out.points.resize(n);
    for (std::size_t i = 0; i < n; ++i) out.points[perm[i]] = mesh.points[i];
    out.faces = mesh.faces;
    for (auto& f : out.faces)
        for (auto& v : f) v = int(perm[std::size_t(v)]);
    return out;
}

// Compares disk_means(..., with_sizes = true) with the definition: a breadth-
// first search (ring_distances) per centre, its defined values averaged.
// The mean of the defined values over the 1..level-ring disk of \p centre
// (NaN if none) and the disk's size, by a search from that centre alone.
std::pair<double, std::uint32_t> brute_force_disk_mean(const Adjacency& adj, const std::vector<double>& values,
                                                       std::size_t centre, int level)
{
    const auto dist = ring_distances(adj, centre, level);
    double sum = 0;
    std::uint32_t cnt = 0, size = 0;
    for (std::size_t j = 0; j < values.size(); ++j)
        if (dist[j] > 0) {
            ++size;
            if (!std::isnan(values[j])) {
                sum += values[j];
                ++cnt;
            }
        }
    return {cnt ? sum / cnt : std::numeric_limits<double>::quiet_NaN(), size};
}

void expect_brute_force_disk_means(const Mesh& mesh, const std::vector<double>& values, const std::vector<int>& levels)
{
    const Adjacency adj = vertex_adjacency(mesh);
    const DiskMeans dm = disk_means(mesh, adj, values, levels, true);
    ASSERT_EQ(dm.levels, levels);
    ASSERT_EQ(dm.mean.size(), levels.size());
    ASSERT_EQ(dm.size.size(), levels.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        for (std::size_t k = 0; k < levels.size(); ++k) {
            if (std::isnan(values[i])) {
                ASSERT_TRUE(std::isnan(dm.mean[k][i])) << "undefined centre " << i;
                ASSERT_EQ(dm.size[k][i], 0u) << "undefined centre " << i;
                continue;
            }
            const auto [mean, size] = brute_force_disk_mean(adj, values, i, levels[k]);
            ASSERT_EQ(dm.size[k][i], size) << "vertex " << i << ", level " << levels[k];
            if (std::isnan(mean)) {
                ASSERT_TRUE(std::isnan(dm.mean[k][i])) << "vertex " << i << ", level " << levels[k];
            } else {
                ASSERT_NEAR(dm.mean[k][i], mean, 1e-12 * (1 + std::abs(mean)))
                    << "vertex " << i << ", level " << levels[k];
            }
        }
    }
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace

TEST(RingNeighborhood, RegularGridHas3LLPlus1Vertices)
{
    const Shape grid = plane_grid(61, 61);
    const Adjacency adj = vertex_adjacency(grid.mesh);
    std::vector<double> ones(grid.mesh.n_vertices(), 1.0);
    const std::vector<int> levels = {1, 2, 3, 5, 10};
    const DiskMeans dm = disk_means(grid.mesh, adj, ones, levels, true);
    const std::size_t centre = 30 * 61 + 30;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const int L = levels[k];
        EXPECT_EQ(dm.size[k][centre], std::uint32_t(3 * L * (L + 1))) << "L = " << L;
        const auto dist = ring_distances(adj, centre, L);
        const auto reached = std::count_if(dist.begin(), dist.end(), [](int d) { return d > 0; });
        EXPECT_EQ(reached, 3 * L * (L + 1)) << "L = " << L;
    }
}

TEST(RingNeighborhood, DiskMeansMatchBruteForceWithUndefinedValues)
{
    const Shape s = torus(24, 12);
    const Adjacency adj = vertex_adjacency(s.mesh);
    std::mt19937_64 rng(7);
    std::vector<double> values(s.mesh.n_vertices());
    for (auto& v : values) v = double(rng() % 1000) / 7.0;
    for (std::size_t i = 0; i < values.size(); i += 13) values[i] = std::nan("");
    const std::vector<int> levels = {4, 1, 7};
    const DiskMeans dm = disk_means(s.mesh, adj, values, levels, true);
    for (std::size_t k = 0; k < levels.size(); ++k)
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (std::isnan(values[i])) {
                EXPECT_TRUE(std::isnan(dm.mean[k][i]));
                continue;
            }
            const auto [mean, size] = brute_force_disk_mean(adj, values, i, levels[k]);
            ASSERT_EQ(dm.size[k][i], size);
            ASSERT_NEAR(dm.mean[k][i], mean, 1e-12 * std::abs(mean));
        }
}

TEST(RingDistances, EqualTheLatticeDistanceOfEveryGridVertex)
{
    // plane_grid splits every quad along (i, j)-(i+1, j+1): a step may change
    // x, y, or both by the same sign, so the graph distance of an offset (dx,
    // dy) is max(|dx|, |dy|, |dx - dy|), also from boundary and corner sources.
    const int nx = 17, ny = 11, L = 6;
    const Shape grid = plane_grid(nx, ny);
    const Adjacency adj = vertex_adjacency(grid.mesh);
    for (const auto& [sx, sy] : {std::pair{8, 5}, std::pair{0, 0}, std::pair{16, 0}, std::pair{3, 10}}) {
        const auto dist = ring_distances(adj, std::size_t(sy * nx + sx), L);
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                const int d = std::max({std::abs(x - sx), std::abs(y - sy), std::abs((x - sx) - (y - sy))});
                ASSERT_EQ(dist[std::size_t(y * nx + x)], d <= L ? d : -1)
                    << "source (" << sx << ", " << sy << "), vertex (" << x << ", " << y << ")";
            }
    }
}

TEST(DiskMeans, AgreeWithBreadthFirstSearchOnTheBunny)
{
    // A scanned mesh with holes, non-manifold edges and duplicate faces;
    // levels unsorted and repeated.
    const Mesh mesh = read_mesh(data("bunny_res3.ply")).mesh;
    std::vector<double> values(mesh.n_vertices());
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = std::sin(40.0 * mesh.points[i].x()) + mesh.points[i].y();
    expect_brute_force_disk_means(mesh, values, {3, 1, 6, 3, 2});
}

TEST(DiskMeans, AgreeWithBreadthFirstSearchAcrossComponentsAndUndefinedValues)
{
    // Four components (one an isolated vertex, one entirely undefined) and a
    // vertex whose neighbours are all undefined: its mean is NaN, its size is not 0.
    Mesh mesh = icosphere(2).mesh;
    append(mesh, torus(16, 8).mesh, Vec3(3, 0, 0));
    const std::size_t grid_first = mesh.n_vertices();
    append(mesh, plane_grid(12, 9, 0.2).mesh, Vec3(0, 3, 0));
    const std::size_t dark_first = mesh.n_vertices();
    append(mesh, icosphere(1).mesh, Vec3(0, 0, 3));
    mesh.points.emplace_back(-3, 0, 0);
    std::mt19937_64 rng(5);
    std::vector<double> values(mesh.n_vertices());
    for (auto& v : values) v = double(rng() % 4096) / 64.0 - 30.0;
    for (std::size_t i = 0; i < values.size(); i += 7) values[i] = std::nan("");
    for (std::size_t i = dark_first; i + 1 < values.size(); ++i) values[i] = std::nan("");
    const std::size_t lonely = grid_first + 4 * 12 + 5;  // interior grid vertex
    const Adjacency adj = vertex_adjacency(mesh);
    values[lonely] = 1.0;
    for (auto it = adj.begin(lonely); it != adj.end(lonely); ++it) values[*it] = std::nan("");
    expect_brute_force_disk_means(mesh, values, {2, 5, 2, 1});

    const DiskMeans dm = disk_means(mesh, adj, values, {1}, true);
    EXPECT_TRUE(std::isnan(dm.mean[0][lonely]));
    EXPECT_EQ(dm.size[0][lonely], 6u);
    EXPECT_TRUE(std::isnan(dm.mean[0].back())) << "the isolated vertex has no neighbour";
    EXPECT_EQ(dm.size[0].back(), 0u);
}

TEST(DiskMeans, SizesAreFilledOnlyWhenAskedForAndChangeNoMean)
{
    const Shape s = torus(20, 10);
    const Adjacency adj = vertex_adjacency(s.mesh);
    const DiskMeans without = disk_means(s.mesh, adj, s.exact_H, {2, 1});
    const DiskMeans with = disk_means(s.mesh, adj, s.exact_H, {2, 1}, true);
    EXPECT_TRUE(without.size.empty());
    ASSERT_EQ(with.size.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) EXPECT_TRUE(bitwise_equal(without.mean[k], with.mean[k]));
    // Every torus vertex has valence 6: 6 within one ring, 18 within two.
    EXPECT_EQ(with.size[0], std::vector<std::uint32_t>(s.mesh.n_vertices(), 18u));
    EXPECT_EQ(with.size[1], std::vector<std::uint32_t>(s.mesh.n_vertices(), 6u));
}

TEST(DiskMeans, BitwiseIdenticalForOneAndTwoThreads)
{
    const Mesh mesh = read_mesh(data("fandisk.ply")).mesh;  // 6475 vertices: about 50 batches
    const Adjacency adj = vertex_adjacency(mesh);
    std::vector<double> values(mesh.n_vertices());
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = i % 11 == 0 ? std::nan("") : std::cos(7.0 * mesh.points[i].z()) / 3.0 + 1e-3 * double(i);
    const std::vector<int> levels = {1, 4, 9};
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const DiskMeans one = disk_means(mesh, adj, values, levels, true);
    omp_set_num_threads(2);
    const DiskMeans two = disk_means(mesh, adj, values, levels, true);
    omp_set_num_threads(saved);
    for (std::size_t k = 0; k < levels.size(); ++k) {
        EXPECT_TRUE(bitwise_equal(one.mean[k], two.mean[k])) << "level " << levels[k];
        EXPECT_EQ(one.size[k], two.size[k]) << "level " << levels[k];
    }
}

TEST(DiskMeans, RejectLevelsBelowOneAndMismatchedSizes)
{
    const Shape s = icosphere(1);
    const Adjacency adj = vertex_adjacency(s.mesh);
    const std::vector<double> values(s.mesh.n_vertices(), 1.0);
    EXPECT_THROW(disk_means(s.mesh, adj, values, {1, 0}), InvalidArgumentError);
    EXPECT_THROW(disk_means(s.mesh, adj, values, {-2}), InvalidArgumentError);
    EXPECT_THROW(disk_means(s.mesh, adj, {1.0, 2.0}, {1}), InvalidArgumentError);
    EXPECT_THROW(disk_means(icosphere(2).mesh, adj, values, {1}), InvalidArgumentError);
    EXPECT_NO_THROW(disk_means(s.mesh, adj, values, {1, 100}));
}

TEST(DiskMeans, AgreeWithBreadthFirstSearchAroundAHub)
{
    // Around a hub (hub_mesh()); some values undefined, so that sizes and
    // counts differ.
    const Mesh mesh = hub_mesh();
    ASSERT_GT(vertex_adjacency(mesh).degree(0), 1024u);
    std::mt19937_64 rng(11);
    std::vector<double> values(mesh.n_vertices());
    for (auto& v : values) v = double(rng() % 4096) / 64.0 - 30.0;
    for (std::size_t i = 5; i < values.size(); i += 13) values[i] = std::nan("");
    expect_brute_force_disk_means(mesh, values, {1, 2, 4, 3});
    // All defined (one counter per centre).
    for (auto& v : values)
        if (std::isnan(v)) v = 0.5;
    expect_brute_force_disk_means(mesh, values, {2, 1});
}

TEST(DiskMeans, AgreeWithBreadthFirstSearchOnAShuffledVertexOrder)
{
    // Neighbours scattered in memory: the search runs on a copy renumbered in
    // Morton order (see disk_means()); its means are those of a search of each
    // centre, for a sample of centres.
    const Mesh mesh = shuffled(torus_irregular(20000, 1.0, 0.3, 7).mesh, 11);
    const std::size_t n = mesh.n_vertices();
    std::vector<double> values(n);
    for (std::size_t i = 0; i < n; ++i)
        values[i] = std::sin(9.0 * mesh.points[i].x()) + mesh.points[i].z() + (i % 97 == 0 ? NAN : 0.0);

    const Adjacency adj = vertex_adjacency(mesh);
    std::size_t far = 0;
    for (std::size_t v = 0; v < n; ++v)
        for (auto it = adj.begin(v); it != adj.end(v); ++it) far += (*it > v ? *it - v : v - *it) > 4096;
    ASSERT_GT(far, adj.index.size() / 2) << "the order is not scattered enough to take the renumbered path";

    const std::vector<int> levels{4, 1, 9};
    const DiskMeans dm = disk_means(mesh, adj, values, levels, true);
    std::mt19937 pick(5);
    for (int trial = 0; trial < 300; ++trial) {
        const std::size_t c = pick() % n;
        for (std::size_t k = 0; k < levels.size(); ++k) {
            if (std::isnan(values[c])) {
                EXPECT_TRUE(std::isnan(dm.mean[k][c]));
                continue;
            }
            const auto [mean, size] = brute_force_disk_mean(adj, values, c, levels[k]);
            ASSERT_EQ(dm.size[k][c], size) << "vertex " << c << ", level " << levels[k];
            ASSERT_NEAR(dm.mean[k][c], mean, 1e-12 * (1 + std::abs(mean))) << "vertex " << c << ", level " << levels[k];
        }
    }
}

namespace {

// Values with every mantissa bit in play (so that the order of additions
// shows in the sums) and no libm: [1, 2) from an integer hash, NaN for some.
double hashed_value(std::uint64_t i)
{
    std::uint64_t x = (i + 1) * 0x9E3779B97F4A7C15ULL;
    x ^= x >> 29;
    x *= 0xBF58476D1CE4E5B9ULL;
    x ^= x >> 32;
    return 1.0 + double(x >> 12) * 0x1p-52;
}

// Allows or forbids the vector kernels for the scope (geometry/simd.h).
class KernelChoice
{
public:
    explicit KernelChoice(bool allow) : before_(detail::allow_vector_kernels(allow)) {}
    ~KernelChoice() { detail::allow_vector_kernels(before_); }
    KernelChoice(const KernelChoice&) = delete;
    KernelChoice& operator=(const KernelChoice&) = delete;

private:
    bool before_;
};

std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t n)
{
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 0x100000001B3ULL;
    return h;
}

// FNV-1a of the bits of every level's means and sizes, in level order.
std::uint64_t hash_of_means(const DiskMeans& dm)
{
    std::uint64_t h = 0xCBF29CE484222325ULL;
    for (std::size_t k = 0; k < dm.levels.size(); ++k) {
        h = fnv1a(h, dm.mean[k].data(), dm.mean[k].size() * sizeof(double));
        h = fnv1a(h, dm.size[k].data(), dm.size[k].size() * sizeof(std::uint32_t));
    }
    return h;
}

}  // namespace

TEST(DiskMeans, SummationOrderIsPinned)
{
    // Every profile is bitwise reproducible from release to release: the ring
    // sums add their values in one fixed order (METHOD.md leaves the order
    // free; meshdiff pins it). This hash of the means' bits was recorded when
    // the order was fixed, and the report corpus checks the same on whole
    // reports; a change of the search that reorders a sum fails here. Inputs
    // with no libm in them (a mesh read from a file, hashed values), so the
    // hash is the same on every IEEE-754 platform.
    const Mesh mesh = read_mesh(data("fandisk.ply")).mesh;
    const Adjacency adj = vertex_adjacency(mesh);
    std::vector<double> values(mesh.n_vertices());
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = i % 13 == 4 ? std::nan("") : hashed_value(i);
    const std::vector<int> levels = {1, 4, 9, 20};
    for (const bool vector_kernels : {false, true}) {  // the AVX-512 sums where the CPU has them
        const KernelChoice choice(vector_kernels);
        const std::uint64_t h = hash_of_means(disk_means(mesh, adj, values, levels, true));
        EXPECT_EQ(h, 0x9DA721C464C449D9ULL) << std::hex << h << (vector_kernels ? " (vector kernels)" : "");
    }
}

TEST(DiskMeans, SummationOrderIsPinnedWithEveryValueDefined)
{
    // The same with no NaN among the values: the search's other path (one
    // counter per centre; the vectorised sums where the CPU has AVX-512).
    // Hashes of fandisk and of a bunny.
    auto hash_of = [](const Mesh& mesh) {
        const Adjacency adj = vertex_adjacency(mesh);
        std::vector<double> values(mesh.n_vertices());
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = hashed_value(i) - 1.5;
        const std::vector<int> levels = {1, 2, 4, 9, 20};
        return hash_of_means(disk_means(mesh, adj, values, levels, true));
    };
    const Mesh fandisk = read_mesh(data("fandisk.ply")).mesh, bunny = read_mesh(data("bunny_res3.ply")).mesh;
    for (const bool vector_kernels : {false, true}) {
        const KernelChoice choice(vector_kernels);
        EXPECT_EQ(hash_of(fandisk), 0x0887E75001D60906ULL) << (vector_kernels ? "vector kernels" : "");
        EXPECT_EQ(hash_of(bunny), 0x4421E46DFB5A7014ULL) << (vector_kernels ? "vector kernels" : "");
    }
}

TEST(DiskMeans, VectorSumsAreTheScalarSumsBitForBit)
{
    // The AVX-512 settle loop against the scalar one, on closed and open
    // meshes, with and without NaN values, every level 1..20: the same bits.
    if (!detail::cpu_has_avx512()) GTEST_SKIP() << "this CPU has no AVX-512: the scalar sums only";
    std::vector<int> levels(20);
    std::iota(levels.begin(), levels.end(), 1);
    for (const char* name : {"fandisk.ply", "bunny_res3.ply", "sphere_irregular_3072.ply", "hemisphere.ply"}) {
        const Mesh mesh = read_mesh(data(name)).mesh;
        const Adjacency adj = vertex_adjacency(mesh);
        for (const int nan_every : {0, 7, 2}) {
            std::vector<double> values(mesh.n_vertices());
            for (std::size_t i = 0; i < values.size(); ++i)
                values[i] = nan_every && i % std::size_t(nan_every) == 1 ? std::nan("") : 3.0 * hashed_value(i) - 4.5;
            DiskMeans scalar, vector;
            {
                const KernelChoice choice(false);
                scalar = disk_means(mesh, adj, values, levels, true);
            }
            {
                const KernelChoice choice(true);
                vector = disk_means(mesh, adj, values, levels, true);
            }
            for (std::size_t k = 0; k < levels.size(); ++k) {
                ASSERT_EQ(scalar.size[k], vector.size[k]) << name << ", level " << levels[k];
                ASSERT_EQ(0, std::memcmp(scalar.mean[k].data(), vector.mean[k].data(), sizeof(double) * values.size()))
                    << name << ", NaN every " << nan_every << ", level " << levels[k];
            }
        }
    }
}

// The ranked head (the largest |D| first, ties by vertex id, NaN left out)
// against a full sort: ties at the capacity's boundary, NaN, every capacity
// from none to more than the defined values, with and without weights.
TEST(RankedHead, EqualsAFullSortWithTiesNaNAndEveryCapacity)
{
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> level(-6, 6);
    std::vector<double> D(300), w(300);
    for (std::size_t i = 0; i < D.size(); ++i) {
        D[i] = i % 7 == 3 ? std::numeric_limits<double>::quiet_NaN() : 0.25 * level(rng);  // many ties, +-0
        w[i] = 1.0 + double(i % 5);
    }
    std::vector<std::uint32_t> ids;
    for (std::size_t i = 0; i < D.size(); ++i)
        if (!std::isnan(D[i])) ids.push_back(std::uint32_t(i));
    std::sort(ids.begin(), ids.end(), [&](std::uint32_t x, std::uint32_t y) {
        const double ax = std::abs(D[x]), ay = std::abs(D[y]);
        return ax != ay ? ax > ay : x < y;
    });
    const std::vector<double>* none = nullptr;
    for (const std::vector<double>* weights : {none, static_cast<const std::vector<double>*>(&w)})
        for (std::size_t capacity = 0; capacity <= ids.size() + 2; ++capacity) {
            const std::vector<detail::RankedD> head = detail::ranked_head(D, weights, capacity);
            ASSERT_EQ(head.size(), std::min(capacity, ids.size())) << capacity;
            for (std::size_t j = 0; j < head.size(); ++j) {
                ASSERT_EQ(head[j].id, ids[j]) << "capacity " << capacity << ", rank " << j;
                ASSERT_EQ(head[j].a, std::abs(D[ids[j]]));
                ASSERT_EQ(head[j].w, weights ? w[ids[j]] : 1.0);
            }
        }
    EXPECT_TRUE(
        detail::ranked_head(std::vector<double>(4, std::numeric_limits<double>::quiet_NaN()), nullptr, 3).empty());
}

namespace {

// disk_means_batches() with \p second: both sets of means, per level and vertex.
std::pair<std::vector<std::vector<double>>, std::vector<std::vector<double>>> means_of_two(
    const Mesh& mesh, const Adjacency& adj, const std::vector<double>& values, const std::vector<double>& second,
    const std::vector<int>& levels)
{
    const std::size_t n = mesh.n_vertices();
    std::vector<std::vector<double>> first(levels.size(), std::vector<double>(n, std::nan(""))), other = first;
    detail::disk_means_batches(MeshData(mesh), adj, values, &second, levels, false,
                               [&](const detail::DiskMeansBatch& b) {
                                   for (std::size_t li = 0; li < levels.size(); ++li)
                                       for (std::size_t k = 0; k < b.count; ++k) {
                                           first[li][b.centres[k]] = b.mean[li * b.stride + k];
                                           other[li][b.centres[k]] = b.mean2[li * b.stride + k];
                                       }
                               });
    return {first, other};
}

}  // namespace

// Two sets of values over one ring search (a profile's H and the local
// difference's change of H): where both are defined at the same vertices, each
// set's means are its own search's to the last bit, with either kernel, at 1
// and 3 threads, with whole-word sums around a hub and on a renumbered copy;
// where the second is defined at fewer vertices, its means differ from its own
// search's in the rounding only, and are NaN exactly where those are.
TEST(DiskMeans, SecondValuesShareTheSearchBitForBit)
{
    const std::vector<int> levels = {1, 2, 3, 5, 8, 13, 20};
    struct Case
    {
        std::string name;
        Mesh mesh;
    };
    std::vector<Case> cases;
    for (const char* name : {"fandisk.ply", "hemisphere.ply"}) cases.push_back({name, read_mesh(data(name)).mesh});
    cases.push_back({"hub", hub_mesh()});
    cases.push_back({"shuffled torus", shuffled(torus_irregular(12000, 1.0, 0.3, 7).mesh, 3)});
    const int saved = omp_get_max_threads();
    for (const Case& c : cases) {
        const Mesh& mesh = c.mesh;
        const Adjacency adj = vertex_adjacency(mesh);
        const std::size_t n = mesh.n_vertices();
        if (c.name == "shuffled torus") {
            std::size_t far = 0;
            for (std::size_t v = 0; v < n; ++v)
                for (auto it = adj.begin(v); it != adj.end(v); ++it) far += (*it > v ? *it - v : v - *it) > 4096;
            ASSERT_GT(far, adj.index.size() / 4) << "the order is not scattered enough to take the renumbered path";
        }
        for (const bool vector : {false, true}) {
            if (vector && !detail::cpu_has_avx512()) continue;
            const KernelChoice choice(vector);
            for (const int nan_every : {0, 7}) {
                std::vector<double> values(n), same(n), fewer(n);
                for (std::size_t i = 0; i < n; ++i) {
                    const bool undefined = nan_every && i % std::size_t(nan_every) == 1;
                    values[i] = undefined ? std::nan("") : 3.0 * hashed_value(i) - 4.5;
                    same[i] = undefined ? std::nan("") : 2.0 * hashed_value(i + n) - 0.5;
                    fewer[i] = i % 5 == 2 ? std::nan("") : same[i];
                }
                const DiskMeans own = disk_means(mesh, adj, values, levels, false);
                const DiskMeans own_same = disk_means(mesh, adj, same, levels, false);
                const DiskMeans own_fewer = disk_means(mesh, adj, fewer, levels, false);
                for (const int threads : {1, 3}) {
                    SCOPED_TRACE(testing::Message() << c.name << (vector ? ", AVX-512" : ", scalar") << ", NaN every "
                                                    << nan_every << ", " << threads << " threads");
                    omp_set_num_threads(threads);
                    const auto [first, second] = means_of_two(mesh, adj, values, same, levels);
                    const auto [first_f, second_f] = means_of_two(mesh, adj, values, fewer, levels);
                    omp_set_num_threads(saved);
                    for (std::size_t k = 0; k < levels.size(); ++k) {
                        ASSERT_TRUE(bitwise_equal(first[k], own.mean[k])) << "level " << levels[k];
                        ASSERT_TRUE(bitwise_equal(first_f[k], own.mean[k])) << "level " << levels[k];
                        ASSERT_TRUE(bitwise_equal(second[k], own_same.mean[k])) << "level " << levels[k];
                        for (std::size_t i = 0; i < n; ++i) {
                            if (std::isnan(fewer[i])) continue;
                            const double want = own_fewer.mean[k][i], got = second_f[k][i];
                            ASSERT_EQ(std::isnan(want), std::isnan(got)) << "vertex " << i << ", level " << levels[k];
                            if (!std::isnan(want)) {
                                ASSERT_NEAR(got, want, 1e-13 * (1.0 + std::abs(want)))
                                    << "vertex " << i << ", level " << levels[k];
                            }
                        }
                    }
                }
            }
        }
    }
}

// The sort of distinct elements on the threads (pieces sorted, then merged,
// the last merge handing them out) gives std::sort's order at any thread
// count (one to five pieces), above and below the size from which it splits;
// the Morton order of the ring search's batches, made with
// it, is the sorted (code, id) pairs of a serial loop.
TEST(ParallelSort, DistinctElementsComeOutAsStdSortsAtAnyThreadCount)
{
    std::mt19937_64 rng(11);
    const int saved = omp_get_max_threads();
    for (const std::size_t n : {std::size_t(0), std::size_t(1000), std::size_t(300001)}) {
        std::vector<std::pair<std::uint64_t, std::uint32_t>> v(n);
        for (std::size_t i = 0; i < n; ++i) v[i] = {rng() % 5000, std::uint32_t(i)};  // many equal codes, ids apart
        std::vector<std::pair<std::uint64_t, std::uint32_t>> expected = v;
        std::sort(expected.begin(), expected.end());
        for (const int threads : {1, 2, 3, 4, 5}) {
            omp_set_num_threads(threads);
            auto pieces = v;
            std::vector<std::pair<std::uint64_t, std::uint32_t>> got;
            detail::for_each_sorted_distinct(pieces, [&](const auto& x) { got.push_back(x); });
            EXPECT_TRUE(got == expected) << n << " elements, " << threads << " threads";
        }
    }
    const Mesh m = icosphere(7).mesh;  // 163,842 vertices
    const BoundingBox box = bounding_box(m);
    const Vec3 ext = (box.max - box.min).cwiseMax(Vec3::Constant(1e-300));
    const double cells = double((1u << 21) - 1);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
    for (std::size_t i = 0; i < m.n_vertices(); ++i) {
        const Vec3 q = (m.points[i] - box.min).cwiseQuotient(ext) * cells;
        keys.push_back({detail::spread_bits(std::uint64_t(q.x())) | detail::spread_bits(std::uint64_t(q.y())) << 1 |
                            detail::spread_bits(std::uint64_t(q.z())) << 2,
                        std::uint32_t(i)});
    }
    std::sort(keys.begin(), keys.end());
    for (const int threads : {1, 2, 3}) {
        omp_set_num_threads(threads);
        const std::vector<std::uint32_t> order = detail::morton_order(m, box);
        ASSERT_EQ(order.size(), keys.size());
        for (std::size_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], keys[i].second) << i << ", " << threads;
    }
    omp_set_num_threads(saved);
}

// A level's streamed statistics are those of a loop over that level's
// centres in batch order, to the last bit: each level's compensated sums take
// the batch's centres in their order (the levels of a centre are folded
// together, their sums interleaved), its head the same vertices; weighted and
// unweighted, with undefined means at some levels.
TEST(LevelStream, EachLevelsSumsAreThoseOfItsOwnLoopBitForBit)
{
    constexpr std::size_t kLevels = 5, kStride = 128, kBatches = 3, n = kBatches * 100;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> values(n), weights(n);
    for (std::size_t v = 0; v < n; ++v) {
        values[v] = u(rng);
        weights[v] = 0.5 + u(rng) * u(rng);
    }
    // Batch b: centres 100 b .. 100 b + 99 in a shuffled order, means per level.
    std::vector<std::vector<std::uint32_t>> centres(kBatches);
    std::vector<std::vector<double>> means(kBatches, std::vector<double>(kLevels * kStride));
    for (std::size_t b = 0; b < kBatches; ++b) {
        for (std::uint32_t k = 0; k < 100; ++k) centres[b].push_back(std::uint32_t(100 * b + k));
        std::shuffle(centres[b].begin(), centres[b].end(), rng);
        for (std::size_t li = 0; li < kLevels; ++li)
            for (std::size_t k = 0; k < 100; ++k)
                means[b][li * kStride + k] =
                    (k + li) % 13 == 0 ? std::numeric_limits<double>::quiet_NaN() : u(rng) * 0.1 * double(li + 1);
    }
    for (const bool weighted : {false, true}) {
        detail::LevelStream stream(kLevels, kBatches, 10, values, weighted ? &weights : nullptr);
        for (std::size_t b = 0; b < kBatches; ++b) {
            detail::DiskMeansBatch batch;
            batch.index = b;
            batch.worker = 0;
            batch.centres = centres[b].data();
            batch.count = 100;
            batch.mean = means[b].data();
            batch.stride = kStride;
            stream.add(batch);
        }
        for (std::size_t li = 0; li < kLevels; ++li) {
            // The reference: per batch, the level's centres in order; the batches' sums then in batch order.
            detail::CompensatedSum total, wtotal;
            std::size_t used = 0;
            std::vector<std::pair<double, std::uint32_t>> all;
            for (std::size_t b = 0; b < kBatches; ++b) {
                detail::CompensatedSum t, w;
                for (std::size_t k = 0; k < 100; ++k) {
                    const std::uint32_t c = centres[b][k];
                    const double d = values[c] - means[b][li * kStride + k];
                    if (std::isnan(d)) continue;
                    const double wc = weighted ? weights[c] : 1.0;
                    t.add(wc * d * d);
                    w.add(wc);
                    ++used;
                    all.push_back({std::abs(d), c});
                }
                total.add(t.s);
                total.add(t.c);
                wtotal.add(w.s);
                wtotal.add(w.c);
            }
            const detail::LevelSums s = stream.sums(li);
            EXPECT_EQ(s.used, used) << li;
            EXPECT_EQ(std::memcmp(&s.total, &total, sizeof total), 0) << "level " << li << " weighted " << weighted;
            EXPECT_EQ(std::memcmp(&s.wtotal, &wtotal, sizeof wtotal), 0) << "level " << li << " weighted " << weighted;
            std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) {
                return x.first != y.first ? x.first > y.first : x.second < y.second;
            });
            ASSERT_EQ(s.head.size(), std::size_t(10));
            for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(s.head[i].id, all[i].second) << li;
        }
    }
}
