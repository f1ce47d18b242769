#include "meshdiff/io/facts.h"
#include "meshdiff/roughness/roughness.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/studies/shapes.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace meshdiff;
using meshdiff::test::data;
namespace fs = std::filesystem;

namespace {

fs::path write_text(const std::string& name, const std::string& text)
{
    const fs::path d = fs::temp_directory_path() / ("meshdiff_facts_test_" + std::to_string(::getpid()));
    fs::create_directories(d);
    std::ofstream(d / name, std::ios::binary) << text;
    return d / name;
}

// An ASCII PLY of a tetrahedron (vertices 0-3, outward faces) with \p extra
// vertex and face lines appended.
std::string tetrahedron_ply(const std::string& extra_vertices, int n_extra_vertices, const std::string& extra_faces,
                            int n_extra_faces)
{
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(4 + n_extra_vertices) +
           "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
           std::to_string(4 + n_extra_faces) + "\nproperty list uchar int vertex_indices\nend_header\n" +
           "0 0 0\n2 0 0\n0 2 0\n0 0 2\n" + extra_vertices + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n" + extra_faces;
}

// Vertices 0 (0,0,0), 1 (2,0,0), 2 (0,2,0), 3 (0,0,2) and \p extra points;
// the faces of the outward tetrahedron followed by \p extra faces.
LoadedMesh by_hand(std::vector<Face> faces, std::vector<Vec3> extra = {})
{
    LoadedMesh m;
    m.mesh.points = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0, 0, 2)};
    m.mesh.points.insert(m.mesh.points.end(), extra.begin(), extra.end());
    m.mesh.faces = std::move(faces);
    return m;
}
const std::vector<Face> kTetrahedron = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

std::vector<WarningKind> kinds(const std::vector<Warning>& w)
{
    std::vector<WarningKind> k;
    for (const auto& x : w) k.push_back(x.kind);
    return k;
}

// The only warning of \p m, which must be of \p kind; its value and level checked.
void expect_only(const LoadedMesh& m, WarningKind kind, double value)
{
    const auto w = warnings(mesh_facts(m));
    ASSERT_EQ(kinds(w), std::vector<WarningKind>{kind}) << to_string(kind);
    EXPECT_EQ(w[0].value, value) << to_string(kind);
    EXPECT_EQ(w[0].level, -1) << to_string(kind);
    EXPECT_FALSE(w[0].text.empty());
}

// icosphere(4) with vertex 0 pushed out by 5% of the radius: it and its
// neighbours make most of sigma^2 at every level.
Mesh spiky_sphere()
{
    Mesh m = icosphere(4).mesh;
    m.points[0] *= 1.05;
    return m;
}

}  // namespace

TEST(MeshFacts, AgreeWithTopologyBoxAndAreaOfTheMeshAsRead)
{
    const LoadedMesh m = read_mesh(data("bunny_res3.ply"));
    const MeshFacts f = mesh_facts(m);
    EXPECT_EQ(f.input.path, m.input.path);
    EXPECT_EQ(f.input.file_vertices, 1889u);
    EXPECT_EQ(f.input.unreferenced_vertices, 2u);
    const TopologyReport t = topology_report(m.mesh);
    EXPECT_EQ(f.topology.vertices, t.vertices);
    EXPECT_EQ(f.topology.faces, t.faces);
    EXPECT_EQ(f.topology.edges, t.edges);
    EXPECT_EQ(f.topology.boundary_edges, t.boundary_edges);
    EXPECT_EQ(f.topology.non_manifold_edges, t.non_manifold_edges);
    EXPECT_EQ(f.topology.duplicate_faces, 83u);
    EXPECT_EQ(f.topology.orientation_conflicts, t.orientation_conflicts);
    EXPECT_EQ(f.box.min, bounding_box(m.mesh).min);
    EXPECT_EQ(f.box.max, bounding_box(m.mesh).max);
    EXPECT_EQ(f.area, surface_area(m.mesh));
}

TEST(Warnings, NoneForACleanIcosphereAndItsProfile)
{
    LoadedMesh m;
    m.mesh = icosphere(3).mesh;
    const auto p = roughness_profile(m.mesh);
    EXPECT_TRUE(warnings(mesh_facts(m), &p).empty());
}

TEST(Warnings, UnreferencedVerticesAndRepeatedCornerFacesAsReadCountTheDropped)
{
    expect_only(read_mesh(write_text("unreferenced.ply", tetrahedron_ply("5 5 5\n6 6 6\n", 2, "", 0))),
                WarningKind::UnreferencedVertices, 2.0);
    expect_only(read_mesh(write_text("repeated.ply", tetrahedron_ply("", 0, "3 0 0 1\n3 2 3 3\n3 1 2 1\n", 3))),
                WarningKind::RepeatedCornerFaces, 3.0);
}

TEST(Warnings, EachTopologicalDefectOnAClosedTetrahedronVariant)
{
    // A second tetrahedron on the edge (0, 1): that edge has four faces.
    auto faces = kTetrahedron;
    faces.insert(faces.end(), {{0, 4, 1}, {0, 1, 5}, {0, 5, 4}, {1, 4, 5}});
    expect_only(by_hand(faces, {Vec3(1, -2, -2), Vec3(1, -1, -3)}), WarningKind::NonManifold, 1.0);
    // One face flipped: its three edges are walked twice in the same direction.
    faces = kTetrahedron;
    faces[3] = {1, 3, 2};
    expect_only(by_hand(faces), WarningKind::OrientationConflicts, 3.0);
    // Face (0, 2, 1) split at the midpoint 4 of the edge (0, 1) and closed by the
    // zero-area sliver (1, 0, 4) along that edge: closed, manifold, one zero-area face.
    faces = kTetrahedron;
    faces[0] = {0, 2, 4};
    faces.insert(faces.end(), {{4, 2, 1}, {1, 0, 4}});
    expect_only(by_hand(faces, {Vec3(1, 0, 0)}), WarningKind::DegenerateFaces, 1.0);
    // A doubly covered triangle: each edge has its two faces, in opposite directions.
    auto triangle = [](std::vector<Face> f) {
        LoadedMesh m = by_hand(std::move(f));
        m.mesh.points.pop_back();  // vertex 3 is in no face
        return m;
    };
    expect_only(triangle({{0, 1, 2}, {0, 2, 1}}), WarningKind::DuplicateFaces, 1.0);
    expect_only(triangle({{0, 1, 2}}), WarningKind::OpenSurface, 3.0);
    // A vertex in no face (read_mesh drops such vertices; a mesh built in code keeps them).
    expect_only(by_hand(kTetrahedron, {Vec3(5, 5, 5)}), WarningKind::IsolatedVertices, 1.0);
    // Two disjoint tetrahedra.
    faces = kTetrahedron;
    for (const Face& t : kTetrahedron) faces.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
    expect_only(by_hand(faces, {Vec3(5, 0, 0), Vec3(7, 0, 0), Vec3(5, 2, 0), Vec3(5, 0, 2)}), WarningKind::Components,
                2.0);
}

TEST(Warnings, NonManifoldVertexAloneHasValueZeroEdges)
{
    // Two tetrahedra touching at vertex 0 only: two fans, no non-manifold edge.
    auto faces = kTetrahedron;
    faces.insert(faces.end(), {{0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}});
    expect_only(by_hand(faces, {Vec3(-2, 0, 0), Vec3(0, -2, 0), Vec3(0, 0, -2)}), WarningKind::NonManifold, 0.0);
}

TEST(Warnings, UndefinedCurvatureCountsTheVerticesOfTheProfile)
{
    // Meyer's cotangent H is undefined on the 2 (5 + 4) - 4 = 14 boundary vertices of a 5 x 4 grid.
    LoadedMesh m;
    m.mesh = plane_grid(5, 4).mesh;
    ProfileOptions o;
    o.levels = {1};
    o.curvature.method = CurvatureMethod::MeyerCotangent;
    const auto p = roughness_profile(m.mesh, o);
    ASSERT_EQ(p.curvature_undefined, 14u);
    const auto w = warnings(mesh_facts(m), &p);
    ASSERT_EQ(kinds(w), (std::vector<WarningKind>{WarningKind::OpenSurface, WarningKind::UndefinedCurvature}));
    EXPECT_EQ(w[1].value, 14.0);
    EXPECT_EQ(w[1].level, -1);
}

TEST(Warnings, SteepJetFitsWarnWhereTheJetStopsGrowingWithTheNoise)
{
    // issue 28: the jet's sigma_1 on the paper's geodesic sphere (F = 20, edge
    // about 0.063 of the radius) grows with radial noise up to about 0.6 of an
    // edge (4%), then saturates (measured 10.5 at 4%, 9.5 at 8%, 9.0 at 14%:
    // docs/accuracy.md). The steep-fits warning marks that regime: none below,
    // above kJetSteepShare at 8% (measured 0.6% of the fits at 4%, 42% at 8%).
    ProfileOptions o;
    o.levels = {1};
    o.global = false;
    ASSERT_EQ(o.curvature.method, CurvatureMethod::Jet);
    double previous = 0.0;
    for (double noise : {0.005, 0.01, 0.02, 0.04}) {
        LoadedMesh m;
        m.mesh = noisy_sphere(geodesic_sphere(20), noise, 1).mesh;
        const auto p = roughness_profile(m.mesh, o);
        EXPECT_GT(p.levels[0].sigma, 1.3 * previous) << noise;
        previous = p.levels[0].sigma;
        EXPECT_TRUE(warnings(mesh_facts(m), &p).empty()) << noise;
    }
    LoadedMesh m;
    m.mesh = noisy_sphere(geodesic_sphere(20), 0.08, 1).mesh;
    const auto p = roughness_profile(m.mesh, o);
    const auto w = warnings(mesh_facts(m), &p);
    ASSERT_EQ(kinds(w), std::vector<WarningKind>{WarningKind::SteepFits});
    EXPECT_GT(w[0].value, kJetSteepShare);
    EXPECT_DOUBLE_EQ(w[0].value, double(p.curvature_steep) / double(m.mesh.n_vertices()));
    // The paper's estimator has no such counter and keeps growing.
    o.curvature.method = CurvatureMethod::GoldfeatherCubic;
    const auto g = roughness_profile(m.mesh, o);
    EXPECT_EQ(g.curvature_steep, 0u);
    EXPECT_TRUE(warnings(mesh_facts(m), &g).empty());
}

TEST(Warnings, OutliersDominateAtEveryLevelWhereOneSpikeMakesMostOfSigma2)
{
    LoadedMesh m;
    m.mesh = spiky_sphere();
    ProfileOptions o;
    o.levels = {1, 2, 4};
    const auto p = roughness_profile(m.mesh, o);
    std::vector<const LevelRoughness*> levels;
    for (const auto& l : p.levels) levels.push_back(&l);
    levels.push_back(&p.global);
    const auto w = warnings(mesh_facts(m), &p);
    ASSERT_EQ(w.size(), levels.size());  // every level, the global one last
    for (std::size_t k = 0; k < w.size(); ++k) {
        EXPECT_GT(levels[k]->top_share, 0.5) << k;
        EXPECT_EQ(levels[k]->worst_vertices.front(), 0u) << k;
        EXPECT_EQ(w[k].kind, WarningKind::OutliersDominate) << k;
        EXPECT_EQ(w[k].level, levels[k]->level) << k;
        EXPECT_EQ(w[k].value, levels[k]->top_share) << k;
    }
    EXPECT_EQ(w.back().level, 0);
}

TEST(Warnings, NoDefinedDAtEveryLevelWhenOneVertexAloneHasH)
{
    // H defined at one vertex only: no vertex has a neighbour (or another
    // vertex, globally) with defined H, so no D anywhere.
    LoadedMesh m;
    m.mesh = icosphere(1).mesh;
    std::vector<double> H(m.mesh.n_vertices(), std::numeric_limits<double>::quiet_NaN());
    H[5] = 1.0;
    ProfileOptions o;
    o.levels = {1, 3};
    const auto p = roughness_profile_from_curvature(m.mesh, H, o);
    const auto w = warnings(mesh_facts(m), &p);
    ASSERT_EQ(kinds(w), (std::vector<WarningKind>{WarningKind::UndefinedCurvature, WarningKind::NoDefinedD,
                                                  WarningKind::NoDefinedD, WarningKind::NoDefinedD}));
    EXPECT_EQ(w[0].value, double(m.mesh.n_vertices() - 1));
    const int want_levels[] = {1, 3, 0};
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(w[k + 1].level, want_levels[k]);
        EXPECT_EQ(w[k + 1].value, 0.0);
    }
}

TEST(Warnings, NoDefinedDAtARadiusBelowTheEdgeLength)
{
    // icosphere(2): unit-scaled edges about 0.15; radius 0.05 holds no neighbour, 0.5 does.
    LoadedMesh m;
    m.mesh = icosphere(2).mesh;
    ProfileOptions o;
    o.levels = {1};
    o.radii = {0.05, 0.5};
    const auto p = roughness_profile(m.mesh, o);
    const auto w = warnings(mesh_facts(m), &p);
    ASSERT_EQ(kinds(w), (std::vector<WarningKind>{WarningKind::NoDefinedD}));
    EXPECT_EQ(w[0].level, -1);
    EXPECT_EQ(w[0].radius, 0.05);
    EXPECT_NE(w[0].text.find("radius 0.05"), std::string::npos) << w[0].text;
    o.radii = {};
    const auto q = roughness_profile(m.mesh, o);
    EXPECT_TRUE(warnings(mesh_facts(m), &q).empty());
}

TEST(Warnings, CappedNeighbourhoodsNameTheCountAndTheFirstVertices)
{
    // A fan of 300 triangles: every rim vertex widens to a 2-ring of 300
    // vertices, above kMaxFitNeighbors.
    LoadedMesh m;
    m.mesh.points.emplace_back(0.0, 0.0, 0.1);
    for (int i = 0; i < 300; ++i)
        m.mesh.points.emplace_back(std::cos(i * M_PI / 150), std::sin(i * M_PI / 150), 0.01 * std::sin(i * M_PI / 50));
    for (int i = 0; i < 300; ++i) m.mesh.faces.push_back({0, 1 + i, 1 + (i + 1) % 300});
    ProfileOptions o;
    o.levels = {1};
    const auto p = roughness_profile(m.mesh, o);
    EXPECT_EQ(p.curvature_capped, 300u);
    EXPECT_EQ(p.curvature_capped_vertices, (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
    const auto w = warnings(mesh_facts(m), &p);
    ASSERT_EQ(kinds(w), (std::vector<WarningKind>{WarningKind::OpenSurface, WarningKind::CappedNeighbourhoods}));
    EXPECT_EQ(w[1].value, 300.0);
    EXPECT_EQ(w[1].level, -1);
    EXPECT_NE(w[1].text.find("300 curvature fits"), std::string::npos) << w[1].text;
    EXPECT_NE(w[1].text.find("256 in all; vertices 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, ...)"), std::string::npos)
        << w[1].text;
    // Without a capped fit there is no such warning (NoneForACleanIcosphereAndItsProfile).
}

TEST(WarningKind, NamesRoundTrip)
{
    for (const auto& entry : EnumNames<WarningKind>::names) {
        EXPECT_EQ(parse_enum<WarningKind>(to_string(entry.value)), entry.value);
        EXPECT_EQ(to_string(parse_enum<WarningKind>(entry.name)), entry.name);
    }
    EXPECT_EQ(to_string(WarningKind::OutliersDominate), "outliers-dominate");
    EXPECT_EQ(parse_enum<WarningKind>("no-defined-d"), WarningKind::NoDefinedD);
}
