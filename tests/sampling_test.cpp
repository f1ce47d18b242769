#include "meshdiff/geometry/sampling.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include "geometry/sample_plan.h"

#include <gtest/gtest.h>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif
#include <omp.h>

#include <string>

using namespace meshdiff;

namespace {

const std::string kData = MESHDIFF_TEST_DATA_DIR;

std::size_t referenced_vertices(const Mesh& m)
{
    std::vector<char> used(m.n_vertices(), 0);
    for (const Face& t : m.faces)
        for (auto v : t) used[std::size_t(v)] = 1;
    return std::size_t(std::count(used.begin(), used.end(), 1));
}

std::string message_of(const SamplingOptions& o)
{
    try {
        validate(o);
    } catch (const InvalidArgumentError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Sampling, CountsMatchTheTargetBudget)
{
    const Mesh m = read_mesh(kData + "/bunny_res3.ply").mesh;
    for (std::size_t target : {20000u, 100000u}) {
        for (FaceSampling scheme : {FaceSampling::SimilarTriangles, FaceSampling::MonteCarlo}) {
            SamplingOptions o;
            o.samples = target;
            o.face_scheme = scheme;
            const SurfaceSamples s = sample_surface(m, o);
            EXPECT_EQ(s.target, target);
            EXPECT_EQ(s.n_vertex, referenced_vertices(m));
            EXPECT_GT(s.n_edge, 0u);
            // At about 5 samples per face the edges (density sqrt of the face
            // density, capped by the budget) take everything left.
            if (target == 100000u) {
                EXPECT_GT(s.n_face, 0u);
            }
            EXPECT_EQ(s.size(), s.n_vertex + s.n_edge + s.n_face);
            EXPECT_EQ(s.kind.size(), s.size());
            EXPECT_EQ(s.element.size(), s.size());
            // Carry-over keeps the total within a few samples of the target,
            // never above it.
            EXPECT_LE(s.size(), target);
            EXPECT_GE(s.size() + 30, target) << "scheme " << int(scheme);
        }
    }
}

TEST(Sampling, DefaultTargetIsTenSamplesPerFace)
{
    const Mesh m = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const SurfaceSamples s = sample_surface(m);
    EXPECT_EQ(s.target, 10 * m.n_faces());
    EXPECT_LE(s.size(), s.target);
    EXPECT_GE(s.size() + 30, s.target);
}

TEST(Sampling, EdgeDensityIsSquareRootOfFaceDensity)
{
    const Mesh m = icosphere(2, 1.0).mesh;
    SamplingOptions o;
    o.samples = 50000;
    const SurfaceSamples s = sample_surface(m, o);
    const double area = surface_area(m);
    const double rho = double(o.samples.value() - s.n_vertex) / area;
    EXPECT_DOUBLE_EQ(s.edge_density, std::sqrt(rho));
    EXPECT_NEAR(s.face_density, double(o.samples.value() - s.n_vertex - s.n_edge) / area, 1e-9 * s.face_density);
}

TEST(Sampling, DensityGivesAreaTimesDensitySamples)
{
    const Mesh m = plane_grid(11, 11, 0.1).mesh;  // a unit square
    SamplingOptions o;
    o.density = 5000.0;
    const SurfaceSamples s = sample_surface(m, o);
    EXPECT_EQ(s.target, 5000u);
    EXPECT_LE(s.size(), 5000u);
    EXPECT_GE(s.size(), 4970u);
}

TEST(Sampling, KindsComeInOrderAndLieOnTheirElements)
{
    const Mesh m = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const SurfaceSamples s = sample_surface(m);
    const double tol = 1e-12 * bounding_box(m).diagonal();
    for (std::size_t i = 0; i < s.size(); ++i) {
        const SampleKind expected = i < s.n_vertex              ? SampleKind::OnVertex
                                    : i < s.n_vertex + s.n_edge ? SampleKind::OnEdge
                                                                : SampleKind::OnFace;
        ASSERT_EQ(s.kind[i], expected) << i;
        const Vec3& p = s.points[i];
        if (expected == SampleKind::OnVertex) {
            ASSERT_EQ(p, m.points[s.element[i]]);
            continue;
        }
        const Face& t = m.faces[s.element[i]];
        const Vec3 &a = m.points[std::size_t(t[0])], &b = m.points[std::size_t(t[1])], &c = m.points[std::size_t(t[2])];
        if (expected == SampleKind::OnEdge) {
            const double d =
                std::min({closest_point_on_segment(p, a, b).distance, closest_point_on_segment(p, b, c).distance,
                          closest_point_on_segment(p, c, a).distance});
            ASSERT_LE(d, tol) << i;
        } else {
            ASSERT_LE(closest_point_on_triangle(p, a, b, c).distance, tol) << i;
        }
    }
}

TEST(Sampling, SimilarTrianglesPlacesTheInteriorLattice)
{
    // A right triangle of area 1/2; 3 vertices + 6 face samples: the 6 interior
    // points of the lattice of step 1/5 (k = 3).
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    m.faces = {Face{0, 1, 2}};
    SamplingOptions o;
    o.edges = false;
    o.samples = 9;
    const SurfaceSamples s = sample_surface(m, o);
    ASSERT_EQ(s.n_vertex, 3u);
    ASSERT_EQ(s.n_face, 6u);
    std::vector<Vec3> expected;
    for (int i = 1; i <= 3; ++i)
        for (int j = 1; i + j <= 4; ++j) expected.emplace_back(i / 5.0, j / 5.0, 0.0);
    for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR((s.points[3 + k] - expected[k]).norm(), 0.0, 1e-15) << k;
}

TEST(Sampling, EdgeSamplesSplitEdgesEvenly)
{
    // A 3-4-5 triangle, edges only, 12 samples: density 1 per unit length, so
    // the edges get 3, 4 and 5 points cutting them into equal parts.
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(0, 4, 0)};
    m.faces = {Face{0, 1, 2}};
    SamplingOptions o;
    o.vertices = false;
    o.faces = false;
    o.samples = 12;
    const SurfaceSamples s = sample_surface(m, o);
    EXPECT_DOUBLE_EQ(s.edge_density, 1.0);
    ASSERT_EQ(s.n_edge, 12u);
    // Edges in (lower, higher) vertex order: (0,1), (0,2), (1,2).
    for (int i = 0; i < 3; ++i) EXPECT_NEAR((s.points[std::size_t(i)] - Vec3(0.75 * (i + 1), 0, 0)).norm(), 0, 1e-15);
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR((s.points[std::size_t(3 + i)] - Vec3(0, 0.8 * (i + 1), 0)).norm(), 0, 1e-15);
    for (int i = 0; i < 5; ++i)
        EXPECT_NEAR((s.points[std::size_t(7 + i)] - Vec3(3 - 0.5 * (i + 1), 4.0 / 6 * (i + 1), 0)).norm(), 0, 1e-15);
    for (std::size_t i = 0; i < s.size(); ++i) EXPECT_EQ(s.kind[i], SampleKind::OnEdge);
}

TEST(Sampling, SimilarTrianglesIsDeterministicAndIgnoresTheSeed)
{
    const Mesh m = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    SamplingOptions o;
    const SurfaceSamples s1 = sample_surface(m, o);
    o.seed = 12345;
    const SurfaceSamples s2 = sample_surface(m, o);
    EXPECT_EQ(s1.points, s2.points);
    EXPECT_EQ(s1.element, s2.element);
}

TEST(Sampling, MonteCarloIsReproducibleForASeedAndDiffersForAnother)
{
    const Mesh m = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    SamplingOptions o;
    o.face_scheme = FaceSampling::MonteCarlo;
    o.seed = 42;
    const SurfaceSamples a = sample_surface(m, o);
    const SurfaceSamples b = sample_surface(m, o);
    o.seed = 43;
    const SurfaceSamples c = sample_surface(m, o);
    EXPECT_EQ(a.points, b.points);
    ASSERT_EQ(a.size(), c.size());  // the counts do not depend on the seed
    EXPECT_NE(a.points, c.points);
    // Only face samples are random.
    for (std::size_t i = 0; i < a.n_vertex + a.n_edge; ++i) ASSERT_EQ(a.points[i], c.points[i]);
}

TEST(Sampling, DegenerateFacesGetNoFaceSamples)
{
    Mesh m = plane_grid(4, 4, 1.0).mesh;
    const auto n = std::int32_t(m.points.size());
    m.points.emplace_back(0.0, 0.0, 1.0);
    m.points.emplace_back(1.0, 0.0, 1.0);
    m.points.emplace_back(2.0, 0.0, 1.0);
    m.faces.push_back({n, n + 1, n + 2});  // collinear: zero area
    const std::uint32_t bad = std::uint32_t(m.n_faces() - 1);
    SamplingOptions o;
    o.samples = 5000;
    const SurfaceSamples s = sample_surface(m, o);
    std::size_t on_bad_edges = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.kind[i] == SampleKind::OnFace) {
            ASSERT_NE(s.element[i], bad);
        }
        if (s.kind[i] == SampleKind::OnEdge && s.element[i] == bad) ++on_bad_edges;
    }
    EXPECT_GT(on_bad_edges, 0u);  // its edges are still part of the surface
    EXPECT_GT(s.n_face, 0u);
}

TEST(Sampling, InvalidOptionsThrowNamingTheField)
{
    SamplingOptions o;
    o.samples = 0;
    EXPECT_NE(message_of(o).find("samples"), std::string::npos);
    o = {};
    o.density = -1.0;
    EXPECT_NE(message_of(o).find("density"), std::string::npos);
    o.density = std::nan("");
    EXPECT_NE(message_of(o).find("density"), std::string::npos);
    o = {};
    o.samples = 10;
    o.density = 1.0;
    EXPECT_NE(message_of(o).find("density"), std::string::npos);
    o = {};
    o.vertices = o.edges = o.faces = false;
    EXPECT_NE(message_of(o).find("vertices"), std::string::npos);
    EXPECT_EQ(message_of(SamplingOptions{}), "");
    EXPECT_THROW(sample_surface(plane_grid(3, 3).mesh, o), InvalidArgumentError);
}

TEST(Sampling, InvalidMeshThrows)
{
    EXPECT_THROW(sample_surface(Mesh{}), InvalidMeshError);
}

TEST(Sampling, SamplesMadeInPiecesAreTheSamplesBitForBit)
{
    // detail::SampleMaker makes any range of sample indices: pieces of odd
    // sizes, ending inside vertex, edge and face runs (faces of about 1000
    // samples), give the samples of sample_surface().
    const Mesh m = icosphere(0).mesh;
    for (const FaceSampling scheme : {FaceSampling::SimilarTriangles, FaceSampling::MonteCarlo})
        for (const bool edges : {true, false}) {
            SamplingOptions o;
            o.face_scheme = scheme;
            o.edges = edges;
            o.samples = 20000;
            o.seed = 3;
            const SurfaceSamples all = sample_surface(m, o);
            const detail::SamplePlan plan = detail::plan_samples(MeshData(m), o);
            ASSERT_EQ(plan.size(), all.size());
            EXPECT_EQ(plan.counts.n_edge, all.n_edge);
            EXPECT_EQ(plan.counts.n_face, all.n_face);
            for (const std::size_t piece : {1, 7, 333, 4096}) {
                detail::SampleMaker maker(m, plan);
                std::vector<Vec3> p(piece);
                std::vector<SampleKind> kind(piece);
                std::vector<std::uint32_t> element(piece);
                for (std::size_t begin = 0; begin < all.size(); begin += piece) {
                    const std::size_t end = std::min(all.size(), begin + piece);
                    maker.make(begin, end, p.data(), kind.data(), element.data());
                    for (std::size_t i = begin; i < end; ++i) {
                        ASSERT_EQ(p[i - begin], all.points[i]) << "piece " << piece << ", sample " << i;
                        ASSERT_EQ(kind[i - begin], all.kind[i]) << i;
                        ASSERT_EQ(element[i - begin], all.element[i]) << i;
                    }
                }
            }
            // Out of order too (the random stream is drawn again from the start).
            detail::SampleMaker maker(m, plan);
            Vec3 p;
            SampleKind kind;
            std::uint32_t element;
            for (const std::size_t i : {all.size() - 1, all.size() / 2, all.n_vertex, std::size_t(0)}) {
                maker.make(i, i + 1, &p, &kind, &element);
                EXPECT_EQ(p, all.points[i]) << i;
                EXPECT_EQ(element, all.element[i]) << i;
            }
        }
}

TEST(Sampling, PlanDroppingItsVertexAndEdgeListsFreesThemAndStillMakesTheFaceSamples)
{
    // The surface distance drops the plan's vertex and edge lists once their
    // samples are made (3M edges and their offsets: 60 MB): their storage
    // is given back, and the face samples are made as before.
    const Mesh m = icosphere(3).mesh;
    SamplingOptions o;
    o.samples = 20000;
    const SurfaceSamples all = sample_surface(m, o);
    detail::SamplePlan plan = detail::plan_samples(MeshData(m), o);
    ASSERT_GT(plan.edges.capacity(), 0u);
    plan.drop_vertices_and_edges();
    EXPECT_EQ(plan.vertices.capacity(), 0u);
    EXPECT_EQ(plan.edges.capacity(), 0u);
    EXPECT_EQ(plan.edge_offset.capacity(), 0u);
    detail::SampleMaker maker(m, plan);
    const std::size_t first = all.n_vertex + all.n_edge;
    std::vector<Vec3> p(all.size() - first);
    std::vector<SampleKind> kind(p.size());
    std::vector<std::uint32_t> element(p.size());
    maker.make(first, all.size(), p.data(), kind.data(), element.data());
    for (std::size_t i = first; i < all.size(); ++i) ASSERT_EQ(p[i - first], all.points[i]) << i;
}

TEST(Sampling, PlanGivesBackTheMadeFrontOfItsEdgeListAndStillMakesTheRest)
{
    // The surface distance gives back the pages of the edge list whose
    // samples are made (discard_made()): they leave memory (mincore), and
    // the samples after them are made as before, chunk after chunk.
    const Mesh m = icosphere(6).mesh;  // 123K edges: 1.4 MB of edge list
    SamplingOptions o;
    o.samples = 1000000;
    const SurfaceSamples all = sample_surface(m, o);
    detail::SamplePlan plan = detail::plan_samples(MeshData(m), o);
    ASSERT_GT(plan.counts.n_edge, 100000u);
    detail::SampleMaker maker(m, plan);
    const std::size_t chunk = 50000;
    std::vector<Vec3> p(chunk);
    std::vector<SampleKind> kind(chunk);
    std::vector<std::uint32_t> element(chunk);
    for (std::size_t begin = 0; begin < all.size(); begin += chunk) {
        const std::size_t end = std::min(all.size(), begin + chunk);
        maker.make(begin, end, p.data(), kind.data(), element.data());
        for (std::size_t i = begin; i < end; ++i)
            ASSERT_TRUE(p[i - begin] == all.points[i] && kind[i - begin] == all.kind[i] &&
                        element[i - begin] == all.element[i])
                << i;
        plan.discard_made(end);
    }
#if defined(__linux__)
    // Past the edge samples, the edge list's whole pages are not resident.
    const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
    const auto lo = (std::uintptr_t(plan.edges.data()) + page - 1) / page * page;
    const auto hi = std::uintptr_t(plan.edges.data() + plan.edges.size()) / page * page;
    ASSERT_GT(hi, lo + 100 * page);
    std::vector<unsigned char> resident((hi - lo) / page);
    ASSERT_EQ(mincore(reinterpret_cast<void*>(lo), hi - lo, resident.data()), 0);
    for (std::size_t i = 0; i < resident.size(); ++i) EXPECT_EQ(resident[i] & 1, 0) << "page " << i;
#endif
}

// The plan's face areas and edge lengths are computed in parallel and summed
// in order: the same samples and densities at any thread count.
TEST(Sampling, IsTheSameAtAnyThreadCount)
{
    Mesh m = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const auto n = std::int32_t(m.points.size());
    m.points.emplace_back(0.0, 0.0, 1.0);
    m.points.emplace_back(1.0, 0.0, 1.0);
    m.points.emplace_back(2.0, 0.0, 1.0);
    m.faces.push_back({n, n + 1, n + 2});  // a degenerate face
    const int threads = omp_get_max_threads();
    for (const FaceSampling scheme : {FaceSampling::SimilarTriangles, FaceSampling::MonteCarlo}) {
        SamplingOptions o;
        o.samples = 30000;
        o.face_scheme = scheme;
        omp_set_num_threads(1);
        const SurfaceSamples one = sample_surface(m, o);
        omp_set_num_threads(3);
        const SurfaceSamples three = sample_surface(m, o);
        EXPECT_EQ(one.points, three.points);
        EXPECT_EQ(one.element, three.element);
        EXPECT_TRUE(one.kind == three.kind);
        EXPECT_EQ(one.edge_density, three.edge_density);
        EXPECT_EQ(one.face_density, three.face_density);
        EXPECT_GT(one.n_edge, 0u);
        EXPECT_GT(one.n_face, 0u);
    }
    omp_set_num_threads(threads);
}
