#include "meshdiff/core/topology.h"

#include <gtest/gtest.h>
#include <omp.h>

#include "meshdiff/core/mesh_data.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include "core/derivations.h"
#include "core/edge_map_parts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace meshdiff;

namespace {

std::string data(const std::string& name)
{
    return std::string(MESHDIFF_TEST_DATA_DIR) + "/" + name;
}

// Brute force: every (sorted) vertex pair of every face with distinct ends,
// with the lowest face that has it, ordered by the pair.
std::vector<Edge> brute_force_edges(const Mesh& mesh)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> lowest;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            auto a = std::uint32_t(mesh.faces[f][k]), b = std::uint32_t(mesh.faces[f][(k + 1) % 3]);
            if (a == b) continue;
            if (a > b) std::swap(a, b);
            const auto it = lowest.find({a, b});
            if (it == lowest.end() || it->second > f) lowest[{a, b}] = std::uint32_t(f);
        }
    std::vector<Edge> edges;
    for (const auto& [ab, f] : lowest) edges.push_back({ab.first, ab.second, f});
    return edges;
}

void expect_same_edges(const std::vector<Edge>& got, const std::vector<Edge>& want)
{
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].a, want[i].a) << i;
        EXPECT_EQ(got[i].b, want[i].b) << i;
        EXPECT_EQ(got[i].face, want[i].face) << i;
    }
}

// Brute force against EdgeMap: every half-edge 3 f + k with distinct ends,
// grouped by its sorted pair of ends (in ascending order of h); opposite
// where a group has two half-edges starting at different vertices.
void expect_edge_map_is_brute_force(const Mesh& mesh, const EdgeMap& m);

// The map from the mesh, and from its derived data (the half-edges grouped
// one vertex at a time, in parallel) at 1 and 3 threads.
void expect_edge_map_is_brute_force(const Mesh& mesh)
{
    expect_edge_map_is_brute_force(mesh, edge_map(mesh));
    const int saved = omp_get_max_threads();
    for (int threads : {1, 3}) {
        SCOPED_TRACE(threads);
        omp_set_num_threads(threads);
        const MeshData data(mesh);
        expect_edge_map_is_brute_force(mesh, edge_map(data));
        expect_same_edges(unique_edges(data), brute_force_edges(mesh));
    }
    omp_set_num_threads(saved);
}

void expect_edge_map_is_brute_force(const Mesh& mesh, const EdgeMap& m)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> groups;
    for (std::uint32_t h = 0; h < 3 * mesh.n_faces(); ++h) {
        auto a = std::uint32_t(mesh.faces[h / 3][h % 3]), b = std::uint32_t(mesh.faces[h / 3][(h + 1) % 3]);
        if (a > b) std::swap(a, b);
        if (a != b) groups[{a, b}].push_back(h);
    }
    expect_same_edges(m.edges, brute_force_edges(mesh));
    ASSERT_EQ(m.size(), groups.size());
    ASSERT_EQ(m.offset.size(), m.size() + 1);
    ASSERT_EQ(m.edge_of.size(), 3 * mesh.n_faces());
    ASSERT_EQ(m.opposite.size(), 3 * mesh.n_faces());
    std::vector<std::uint32_t> edge_of(3 * mesh.n_faces(), EdgeMap::kNone);
    std::vector<std::uint32_t> opposite(3 * mesh.n_faces(), EdgeMap::kNone);
    std::size_t e = 0, boundary = 0, non_manifold = 0, misoriented = 0;
    for (const auto& [ab, hs] : groups) {
        boundary += hs.size() == 1;
        non_manifold += hs.size() > 2;
        EXPECT_EQ(std::vector<std::uint32_t>(m.begin(e), m.end(e)), hs) << ab.first << " " << ab.second;
        EXPECT_EQ(m.count(e), hs.size());
        for (const std::uint32_t h : hs) edge_of[h] = std::uint32_t(e);
        const auto start = [&](std::uint32_t h) { return mesh.faces[h / 3][h % 3]; };
        const bool pair = hs.size() == 2 && start(hs[0]) != start(hs[1]);
        if (pair) {
            opposite[hs[0]] = hs[1];
            opposite[hs[1]] = hs[0];
        }
        EXPECT_EQ(m.misoriented(e), hs.size() == 2 && !pair) << e;
        misoriented += hs.size() == 2 && !pair;
        ++e;
    }
    EXPECT_EQ(m.boundary_edges, boundary);
    EXPECT_EQ(m.non_manifold_edges, non_manifold);
    EXPECT_EQ(m.misoriented_edges, misoriented);
    const TopologyReport r = topology_report(mesh);
    EXPECT_EQ(r.edges, m.size());
    EXPECT_EQ(r.boundary_edges, boundary);
    EXPECT_EQ(r.non_manifold_edges, non_manifold);
    EXPECT_EQ(r.orientation_conflicts, misoriented);
    EXPECT_EQ(m.edge_of, edge_of);
    EXPECT_EQ(m.opposite, opposite);
}

// Brute force: the vertices whose incident faces (linked when they share a
// vertex other than the centre) form more than one fan, every pair tested.
std::size_t brute_force_non_manifold_vertices(const Mesh& mesh)
{
    std::size_t count = 0;
    for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
        std::vector<std::size_t> faces;
        for (std::size_t f = 0; f < mesh.n_faces(); ++f)
            for (auto c : mesh.faces[f])
                if (std::size_t(c) == v) faces.push_back(f);  // once per corner, as vertex_faces()
        std::vector<std::size_t> root(faces.size());
        for (std::size_t a = 0; a < root.size(); ++a) root[a] = a;
        auto find = [&](std::size_t x) {
            while (root[x] != x) x = root[x];
            return x;
        };
        for (std::size_t a = 0; a < faces.size(); ++a)
            for (std::size_t b = a + 1; b < faces.size(); ++b) {
                bool share = false;
                for (auto x : mesh.faces[faces[a]])
                    for (auto y : mesh.faces[faces[b]]) share = share || (x == y && std::size_t(x) != v);
                if (share) root[find(a)] = find(b);
            }
        std::size_t fans = 0;
        for (std::size_t a = 0; a < root.size(); ++a) fans += find(a) == a ? 1 : 0;
        if (fans > 1) ++count;
    }
    return count;
}

// Appends a fan of \p n triangles around \p hub on a circle of radius r at
// height z; closed (a disc) or open (a fan with a gap).
void add_fan(Mesh& m, std::int32_t hub, int n, double r, double z, bool closed)
{
    const auto first = std::int32_t(m.points.size());
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        m.points.emplace_back(r * std::cos(a), r * std::sin(a), z);
    }
    for (int i = 0; i < (closed ? n : n - 1); ++i) m.faces.push_back({hub, first + i, first + (i + 1) % n});
}

}  // namespace

TEST(Topology, NonManifoldVertexCountOfHubsEqualsTheBruteForce)
{
    // Vertex 0: two fans of 40 and 30 triangles touching only there (non-
    // manifold). Vertex 1: one closed fan of 50 (manifold), then the same with
    // a third fan of 20 joined to the first through a shared rim vertex
    // (manifold: the faces are linked). Above 16 faces a vertex's fans are
    // found by grouping, below by testing every pair.
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(5, 0, 0)};
    add_fan(m, 0, 40, 1.0, 0.5, true);
    add_fan(m, 0, 30, 1.0, -0.5, false);
    const std::int32_t hub1 = 1;
    const auto before = std::int32_t(m.points.size());
    add_fan(m, hub1, 50, 1.0, 0.2, true);
    for (auto i = before; i < std::int32_t(m.points.size()); ++i) m.points[std::size_t(i)].x() += 5.0;
    EXPECT_EQ(topology_report(m).non_manifold_vertices, 1u);
    EXPECT_EQ(brute_force_non_manifold_vertices(m), 1u);

    // A third fan at vertex 1, sharing rim vertex `before` with the first.
    const auto third = std::int32_t(m.points.size());
    add_fan(m, hub1, 20, 0.5, 1.0, false);
    for (auto i = third; i < std::int32_t(m.points.size()); ++i) m.points[std::size_t(i)].x() += 5.0;
    m.faces.push_back({hub1, third + 19, before});
    EXPECT_EQ(topology_report(m).non_manifold_vertices, brute_force_non_manifold_vertices(m));
    EXPECT_EQ(topology_report(m).non_manifold_vertices, 1u);

    // Now a fourth, separate fan at vertex 1: both hubs are non-manifold; and
    // a small bowtie (2 + 2 faces) for the pairwise path.
    add_fan(m, hub1, 25, 0.3, -1.0, false);
    const auto bow = std::int32_t(m.points.size());
    m.points.insert(m.points.end(),
                    {Vec3(9, 0, 0), Vec3(10, 1, 0), Vec3(10, 0, 1), Vec3(8, 1, 0), Vec3(8, 0, 1), Vec3(10, -1, 0)});
    m.faces.insert(m.faces.end(), {{bow, bow + 1, bow + 2}, {bow, bow + 2, bow + 5}, {bow, bow + 3, bow + 4}});
    const auto t = topology_report(m);
    EXPECT_EQ(t.non_manifold_vertices, brute_force_non_manifold_vertices(m));
    EXPECT_EQ(t.non_manifold_vertices, 3u);
}

TEST(Topology, ClosedManifoldSphere)
{
    const auto t = topology_report(icosphere(3).mesh);
    EXPECT_EQ(t.vertices, 642u);
    EXPECT_EQ(t.edges, 1920u);
    EXPECT_EQ(t.components, 1u);
    EXPECT_TRUE(t.closed());
    EXPECT_EQ(t.non_manifold_edges + t.non_manifold_vertices + t.degenerate_faces + t.duplicate_faces +
                  t.orientation_conflicts,
              0u);
    EXPECT_EQ(std::int64_t(t.vertices) - std::int64_t(t.edges) + std::int64_t(t.faces), 2);
}

TEST(Topology, CountsTheDefectsOfRealMeshes)
{
    // Counts from the independent checker of tests/data/PROVENANCE.md.
    const auto res4 = topology_report(read_mesh(data("bunny_res4_ascii.ply")).mesh);
    EXPECT_EQ(res4.non_manifold_edges, 70u);
    EXPECT_EQ(res4.non_manifold_vertices, 4u);
    EXPECT_EQ(res4.duplicate_faces, 40u);
    EXPECT_EQ(res4.boundary_edges, 26u);
    const auto hemi = topology_report(read_mesh(data("hemisphere.ply")).mesh);
    EXPECT_EQ(hemi.boundary_edges, 120u);
    EXPECT_EQ(hemi.boundary_loops, 1u);
    const auto teapot = topology_report(read_mesh(data("teapot.obj")).mesh);
    EXPECT_EQ(teapot.components, 4u);
    EXPECT_EQ(teapot.boundary_edges, 1036u);
    EXPECT_EQ(topology_report(read_mesh(data("torus_R1_r025.ply")).mesh).edges, 3u * 2304u);
}

TEST(Topology, DegenerateDuplicateAndFlippedFaces)
{
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0), Vec3(1, 1, 0)};
    m.faces = {{0, 1, 2}, {0, 1, 3}, {2, 1, 0}, {1, 4, 2}};  // collinear, reversed duplicate
    const auto t = topology_report(m);
    EXPECT_EQ(t.degenerate_faces, 1u);
    EXPECT_EQ(t.duplicate_faces, 1u);
    EXPECT_GE(t.orientation_conflicts + t.non_manifold_edges, 1u);
    EXPECT_EQ(degenerate_face_mask(m), (std::vector<char>{0, 1, 0, 0}));
}

TEST(Topology, FacesWithAllCornersEqualAreCountedNotOverrun)
{
    // A mesh built in code may hold faces that read_mesh() would drop: here
    // {1, 1, 1} (one vertex three times) and {0, 0, 2}. The fan count of
    // vertices 0 and 1 must not read past the corners it collected.
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
    m.faces = {{0, 1, 2}, {1, 1, 1}, {0, 0, 2}, {1, 3, 2}, {3, 3, 3}};
    const auto t = topology_report(m);
    EXPECT_EQ(t.faces, 5u);
    EXPECT_EQ(t.degenerate_faces, 3u);
    EXPECT_EQ(t.isolated_vertices, 0u);
    EXPECT_EQ(t.components, 1u);
    // A lone {0, 0, 0}: one degenerate face, no edge of its own.
    Mesh lone;
    lone.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    lone.faces = {{0, 0, 0}};
    const auto l = topology_report(lone);
    EXPECT_EQ(l.degenerate_faces, 1u);
    EXPECT_EQ(l.isolated_vertices, 2u);
    EXPECT_EQ(l.non_manifold_vertices, 0u);
}

TEST(Adjacency, SortedUniqueNeighboursOnTheTorus)
{
    const Shape s = torus(12, 8);
    const Adjacency a = vertex_adjacency(s.mesh);
    for (std::size_t v = 0; v < a.size(); ++v) {
        EXPECT_EQ(a.degree(v), 6u);
        EXPECT_TRUE(std::is_sorted(a.begin(v), a.end(v)));
        EXPECT_EQ(std::adjacent_find(a.begin(v), a.end(v)), a.end(v));
    }
    const Adjacency vf = vertex_faces(s.mesh);
    for (std::size_t v = 0; v < vf.size(); ++v) EXPECT_EQ(vf.degree(v), 6u);
}

// Brute force: per vertex, the set of the other ends of the face edges it is
// an end of (an edge whose two ends are equal is none).
std::vector<std::vector<std::uint32_t>> brute_force_neighbours(const Mesh& mesh)
{
    std::vector<std::set<std::uint32_t>> sets(mesh.n_vertices());
    for (const Face& t : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const auto a = std::uint32_t(t[k]), b = std::uint32_t(t[(k + 1) % 3]);
            if (a == b) continue;
            sets[a].insert(b);
            sets[b].insert(a);
        }
    std::vector<std::vector<std::uint32_t>> rows;
    for (const auto& s : sets) rows.emplace_back(s.begin(), s.end());
    return rows;
}

void expect_adjacency(const Adjacency& a, const std::vector<std::vector<std::uint32_t>>& want)
{
    ASSERT_EQ(a.size(), want.size());
    ASSERT_EQ(a.offset.back(), a.index.size());
    for (std::size_t v = 0; v < want.size(); ++v)
        EXPECT_EQ(std::vector<std::uint32_t>(a.begin(v), a.end(v)), want[v]) << "vertex " << v;
}

TEST(Adjacency, EqualsTheBruteForceWithDuplicateRepeatedCornerAndNonManifoldFaces)
{
    // bunny_res4: 40 duplicate faces; the small mesh: a face that repeats a
    // corner, one with all corners equal, an edge of three faces, an isolated
    // vertex (5) and a hub of 300 faces (vertex 6, past a small row's sort).
    Mesh small;
    small.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                    Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(3, 0, 0)};
    small.faces = {{3, 1, 3}, {0, 1, 2}, {0, 2, 3}, {2, 1, 0}, {4, 4, 4}, {0, 1, 4}};
    for (std::int32_t k = 0; k < 300; ++k) {
        small.points.push_back(Vec3(3 + std::cos(k * 0.02), std::sin(k * 0.02), 0));
        small.points.push_back(Vec3(3 + std::cos(k * 0.02 + 0.01), std::sin(k * 0.02 + 0.01), 0));
        const auto a = std::int32_t(small.points.size()) - 2;
        small.faces.push_back({6, a + 1, a});  // rows out of order: the row of 6 is sorted here
    }
    for (const Mesh& m : {read_mesh(data("bunny_res4_ascii.ply")).mesh, small}) {
        const auto want = brute_force_neighbours(m);
        expect_adjacency(vertex_adjacency(m), want);
        expect_adjacency(vertex_adjacency(m, vertex_faces(m)), want);
    }
    EXPECT_EQ(vertex_adjacency(small).degree(6), 600u);
    EXPECT_EQ(vertex_adjacency(small).degree(5), 0u);
    Mesh other = small;
    other.points.pop_back();  // the incidence of a mesh with one more vertex is refused
    EXPECT_THROW(vertex_adjacency(other, vertex_faces(small)), InvalidArgumentError);
}

TEST(Adjacency, IsTheSameForAnyThreadCount)
{
    const Mesh m = read_mesh(data("bunny_res3.ply")).mesh;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const Adjacency one = vertex_adjacency(m);
    omp_set_num_threads(3);  // rows cut differently between the threads
    const Adjacency three = vertex_adjacency(m);
    omp_set_num_threads(saved);
    EXPECT_EQ(one.offset, three.offset);
    EXPECT_EQ(one.index, three.index);
    expect_adjacency(one, brute_force_neighbours(m));
}

TEST(UniqueEdges, EqualBruteForceOnAMeshWithDuplicateFaces)
{
    const Mesh m = read_mesh(data("bunny_res4_ascii.ply")).mesh;
    ASSERT_EQ(topology_report(m).duplicate_faces, 40u);  // the duplicates whose edges must appear once
    const auto edges = unique_edges(m);
    expect_same_edges(edges, brute_force_edges(m));
    EXPECT_EQ(edges.size(), topology_report(m).edges);
}

TEST(UniqueEdges, KeepTheDistinctEdgeOfARepeatedCornerFace)
{
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    // Face 0 repeats corner 3: its edge (1, 3) has no other face; (3, 3) is no edge.
    m.faces = {{3, 1, 3}, {0, 1, 2}, {0, 2, 3}, {2, 1, 0}};
    const auto edges = unique_edges(m);
    expect_same_edges(edges, brute_force_edges(m));
    const std::vector<Edge> want = {{0, 1, 1}, {0, 2, 1}, {0, 3, 2}, {1, 2, 1}, {1, 3, 0}, {2, 3, 2}};
    expect_same_edges(edges, want);
}

TEST(DegenerateFaceMask, FlipsAtKDegenerateAreaTimesTheSquaredDiagonal)
{
    // A unit tetrahedron fixes the box ([0, 1]^3); a thin triangle on the edge
    // (0, 1) with apex height h has |cross| = h (base 1).
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.5, 0, 0)};
    m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 1, 4}};
    const double diag = bounding_box(m).diagonal();
    const double eps = kDegenerateArea * diag * diag;
    for (const double factor : {1.0 + 1e-6, 1.0 - 1e-6}) {
        m.points[4].y() = eps * factor;
        ASSERT_EQ(bounding_box(m).diagonal(), diag);
        ASSERT_NEAR(face_cross(m, 4).norm(), eps * factor, 1e-9 * eps);
        const auto mask = degenerate_face_mask(m);
        EXPECT_EQ(mask, (std::vector<char>{0, 0, 0, 0, char(factor < 1.0)})) << factor;
        EXPECT_EQ(topology_report(m).degenerate_faces, factor < 1.0 ? 1u : 0u);
    }
}

// Random faces over few vertices (so that many repeat, in any corner order,
// some with repeated corners): the duplicate count equals a brute-force sort
// of the sorted corner triples.
TEST(Topology, DuplicateFacesMatchABruteForceCount)
{
    std::mt19937 rng(7);
    for (int round = 0; round < 20; ++round) {
        Mesh m;
        const int nv = 4 + round;
        for (int i = 0; i < nv; ++i) m.points.emplace_back(i, (i * 7) % 5, (i * 3) % 4);
        std::uniform_int_distribution<int> vertex(0, nv - 1);
        for (int f = 0; f < 200; ++f) m.faces.push_back({vertex(rng), vertex(rng), vertex(rng)});
        std::vector<std::array<int, 3>> sorted(m.faces.begin(), m.faces.end());
        for (auto& t : sorted) std::sort(t.begin(), t.end());
        std::sort(sorted.begin(), sorted.end());
        std::size_t expected = 0;
        for (std::size_t i = 1; i < sorted.size(); ++i) expected += sorted[i] == sorted[i - 1];
        EXPECT_EQ(topology_report(m).duplicate_faces, expected) << round;
    }
}

TEST(EdgeMap, ClosedTetrahedronPairsEveryHalfEdge)
{
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    expect_edge_map_is_brute_force(m);
    const EdgeMap e = edge_map(m);
    ASSERT_EQ(e.size(), 6u);
    for (std::size_t k = 0; k < e.size(); ++k) {
        EXPECT_EQ(e.count(k), 2u);
        EXPECT_FALSE(e.misoriented(k));
    }
    for (std::uint32_t h = 0; h < 12; ++h) {
        ASSERT_NE(e.opposite[h], EdgeMap::kNone);
        EXPECT_EQ(e.opposite[e.opposite[h]], h);
        EXPECT_EQ(e.edge_of[e.opposite[h]], e.edge_of[h]);
    }
    // Half-edge 0 of face 0 runs 0 -> 2; face 2 runs 2 -> 0 from its corner 2.
    EXPECT_EQ(e.opposite[0], 8u);
}

TEST(EdgeMap, BoundaryNonManifoldAndMisorientedEdges)
{
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)};
    // Three faces on the edge (0, 1); faces 2 and 3 both run 1 -> 4.
    m.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {2, 1, 4}};
    expect_edge_map_is_brute_force(m);
    const EdgeMap e = edge_map(m);
    ASSERT_EQ(e.edges[0].a, 0u);
    ASSERT_EQ(e.edges[0].b, 1u);
    EXPECT_EQ(std::vector<std::uint32_t>(e.begin(0), e.end(0)), (std::vector<std::uint32_t>{0, 3, 6}));
    EXPECT_EQ(e.opposite[0], EdgeMap::kNone);
    const auto it = std::find_if(e.edges.begin(), e.edges.end(), [](const Edge& x) { return x.a == 1 && x.b == 4; });
    ASSERT_NE(it, e.edges.end());
    EXPECT_TRUE(e.misoriented(std::size_t(it - e.edges.begin())));
    const TopologyReport r = topology_report(m);
    EXPECT_EQ(r.edges, e.size());
    EXPECT_EQ(r.non_manifold_edges, 1u);
    EXPECT_EQ(r.orientation_conflicts, 1u);
    EXPECT_EQ(r.boundary_edges, 5u);  // (0, 2), (0, 3), (1, 3), (0, 4), (2, 4)
}

TEST(EdgeMap, CollapsedCornerAndRepeatedFace)
{
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    // Face 0 repeats corner 3: 3 -> 1 and 1 -> 3 are opposite, 3 -> 3 is on
    // no edge. Face 4 repeats face 1 (misoriented pairs), face 5 reverses it.
    m.faces = {{3, 1, 3}, {0, 1, 2}, {0, 2, 3}, {2, 1, 0}, {0, 1, 2}, {2, 1, 0}};
    expect_edge_map_is_brute_force(m);
    const EdgeMap e = edge_map(m);
    EXPECT_EQ(e.edge_of[2], EdgeMap::kNone);
    EXPECT_EQ(e.opposite[0], 1u);
    EXPECT_EQ(e.opposite[1], 0u);
    EXPECT_EQ(e.edge_of[0], e.edge_of[1]);
    // (0, 1): faces 1, 3, 4, 5 -> four half-edges, non-manifold.
    EXPECT_EQ(e.count(e.edge_of[3]), 4u);
    Mesh all_same;
    all_same.points = m.points;
    all_same.faces = {{1, 1, 1}};
    const EdgeMap none = edge_map(all_same);
    EXPECT_EQ(none.size(), 0u);
    EXPECT_EQ(none.offset, std::vector<std::uint32_t>{0});
    EXPECT_EQ(none.edge_of, std::vector<std::uint32_t>(3, EdgeMap::kNone));
    EXPECT_EQ(edge_map(Mesh{}).size(), 0u);
}

// Random faces over few vertices: every kind of edge at once (boundary,
// non-manifold, misoriented, repeated faces, repeated corners), and a real
// mesh with duplicate faces.
TEST(EdgeMap, EqualsTheBruteForce)
{
    std::mt19937 rng(11);
    for (int round = 0; round < 20; ++round) {
        Mesh m;
        const int nv = 3 + round;
        for (int i = 0; i < nv; ++i) m.points.emplace_back(i, (i * 7) % 5, (i * 3) % 4);
        std::uniform_int_distribution<int> vertex(0, nv - 1);
        for (int f = 0; f < 5 * nv; ++f) m.faces.push_back({vertex(rng), vertex(rng), vertex(rng)});
        SCOPED_TRACE(round);
        expect_edge_map_is_brute_force(m);
    }
    expect_edge_map_is_brute_force(read_mesh(data("bunny_res4_ascii.ply")).mesh);
    expect_edge_map_is_brute_force(torus(12, 8).mesh);
}

TEST(Topology, EdgeMapPartsAreTheFullMapsParts)
{
    // The parts build_edge_map() fills are the full map's, bit for bit, and
    // the others are left empty: on a closed mesh, on meshes with boundaries,
    // non-manifold edges, duplicate faces and collapsed corners, with and
    // without the incidence. The edge list from the incidence alone
    // (unique_edges() of a MeshData) is the full map's too.
    Mesh odd;
    odd.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0), Vec3(1, 1, 0)};
    odd.faces = {{0, 1, 2}, {0, 1, 3}, {2, 1, 0}, {1, 4, 2}, {1, 1, 4}, {3, 4, 3}, {4, 2, 0}, {0, 2, 4}};
    // A book: 300 pages on the edge (0, 1), some turned the other way (the
    // incidence would read all pages for each of their 600 half-edges: the
    // sorted half-edges are used instead, the same values).
    Mesh book;
    book.points = {Vec3(0, 0, 0), Vec3(0, 0, 1)};
    for (int k = 0; k < 300; ++k) {
        book.points.emplace_back(std::cos(0.02 * k), std::sin(0.02 * k), 0.5);
        book.faces.push_back(k % 3 ? Face{0, 1, k + 2} : Face{1, 0, k + 2});
    }
    for (const Mesh& m : {read_mesh(data("torus_R1_r025.ply")).mesh, read_mesh(data("bunny_res4_ascii.ply")).mesh,
                          read_mesh(data("teapot.obj")).mesh, odd, book}) {
        const MeshData md(m);
        const EdgeMap all = edge_map(m);
        ASSERT_FALSE(all.opposite.empty());
        for (const Adjacency* vf : {static_cast<const Adjacency*>(nullptr), &md.vertex_faces()}) {
            const EdgeMap o = detail::build_edge_map(m, detail::EdgeMapParts::Opposite, vf);
            EXPECT_EQ(o.opposite, all.opposite);
            EXPECT_TRUE(o.edges.empty() && o.offset.empty() && o.half_edge.empty() && o.edge_of.empty());
            const EdgeMap e = detail::build_edge_map(m, detail::EdgeMapParts::Edges, vf);
            if (vf) {  // the edge list alone, from the incidence
                const std::vector<Edge> u = unique_edges(md);
                ASSERT_EQ(u.size(), all.edges.size());
                for (std::size_t i = 0; i < u.size(); ++i)
                    EXPECT_TRUE(u[i].a == all.edges[i].a && u[i].b == all.edges[i].b && u[i].face == all.edges[i].face)
                        << i;
            }
            EXPECT_TRUE(e.opposite.empty() && e.edge_of.empty());
            EXPECT_EQ(e.offset, all.offset);
            EXPECT_EQ(e.half_edge, all.half_edge);
            ASSERT_EQ(e.edges.size(), all.edges.size());
            for (std::size_t i = 0; i < e.edges.size(); ++i)
                EXPECT_TRUE(e.edges[i].a == all.edges[i].a && e.edges[i].b == all.edges[i].b &&
                            e.edges[i].face == all.edges[i].face);
            for (const EdgeMap* p : {&o, &e}) {
                EXPECT_EQ(p->boundary_edges, all.boundary_edges);
                EXPECT_EQ(p->non_manifold_edges, all.non_manifold_edges);
                EXPECT_EQ(p->misoriented_edges, all.misoriented_edges);
            }
        }
    }
}

TEST(MeshData, AReleasedIncidenceIsDerivedAgainTheSame)
{
    const Mesh m = read_mesh(data("bunny_res4_ascii.ply")).mesh;
    const MeshData md(m);
    detail::start_derivation_log();
    const Adjacency first = md.vertex_faces();
    md.vertex_faces();
    detail::release_vertex_faces(md);
    const Adjacency& again = md.vertex_faces();
    const detail::DerivationCounts counts = detail::stop_derivation_log();
    EXPECT_EQ(again.offset, first.offset);
    EXPECT_EQ(again.index, first.index);
    int derived = 0;
    for (const auto& [key, n] : counts)
        if (key.second == detail::Derived::VertexFaces) derived += n;
    EXPECT_EQ(derived, 2);  // once, then once after the release
}
