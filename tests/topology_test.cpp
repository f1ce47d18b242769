#include "meshdiff/topology.h"

#include <gtest/gtest.h>

#include "meshdiff/io.h"
#include "meshdiff/shapes.h"

#include <algorithm>
#include <vector>

using namespace meshdiff;

namespace {

std::string data(const std::string& name)
{
    return std::string(MESHDIFF_TEST_DATA_DIR) + "/" + name;
}

}  // namespace

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
