#include "meshdiff/distance/surface_distance.h"

#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include "distance/surface_distance_chunks.h"
#include "distance/two_directions.h"
#include "geometry/morton_code.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>
#include <string>

using namespace meshdiff;

namespace {

const std::string kData = MESHDIFF_TEST_DATA_DIR;

Mesh transformed(Mesh m, double scale, const Eigen::Matrix3d& rotation, const Vec3& shift)
{
    for (Vec3& p : m.points) p = scale * (rotation * p) + shift;
    return m;
}

// The options of a surface distance with sampling \p sampling, certifying
// with \p hausdorff and summarising with \p summary.
DistanceOptions distance_options(const SamplingOptions& sampling = {},
                                 const std::optional<HausdorffOptions>& hausdorff = std::nullopt,
                                 const SummaryOptions& summary = {})
{
    DistanceOptions o;
    o.sampling = sampling;
    o.hausdorff = hausdorff;
    o.summary = summary;
    return o;
}

bool same_bits(double x, double y)
{
    return std::memcmp(&x, &y, sizeof(double)) == 0;
}

void expect_identical(const DistanceStats& x, const DistanceStats& y)
{
    EXPECT_TRUE(same_bits(x.min, y.min));
    EXPECT_TRUE(same_bits(x.max, y.max));
    EXPECT_TRUE(same_bits(x.mean, y.mean));
    EXPECT_TRUE(same_bits(x.rms, y.rms));
    EXPECT_TRUE(same_bits(x.stddev, y.stddev));
    EXPECT_TRUE(same_bits(x.p50, y.p50));
    EXPECT_TRUE(same_bits(x.p95, y.p95));
    EXPECT_TRUE(same_bits(x.p99, y.p99));
    EXPECT_EQ(x.n_vertex, y.n_vertex);
    EXPECT_EQ(x.n_edge, y.n_edge);
    EXPECT_EQ(x.n_face, y.n_face);
}

// Smallest distance from the origin to the surface of a convex polyhedron
// around it: the smallest distance to a face plane.
double inner_radius(const Mesh& m)
{
    double r = INFINITY;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
        const Vec3 n = face_cross(m, f).normalized();
        r = std::min(r, std::abs(n.dot(m.points[std::size_t(m.faces[f][0])])));
    }
    return r;
}

}  // namespace

TEST(SurfaceDistance, PlaneAgainstOffsetCopyGivesTheOffset)
{
    // Two grids of the same square at different resolutions, 0.125 apart.
    const double d = 0.125;
    const Mesh a = plane_grid(11, 11, 0.1).mesh;
    Mesh b = plane_grid(8, 8, 1.0 / 7.0).mesh;
    for (Vec3& p : b.points) p.z() += d;
    const SurfaceDistance r = surface_distance(a, b);
    for (const DistanceStats* s : {&r.forward, &r.backward}) {
        EXPECT_NEAR(s->min, d, 1e-14);
        EXPECT_NEAR(s->max, d, 1e-14);
        EXPECT_NEAR(s->mean, d, 1e-14);
        EXPECT_NEAR(s->rms, d, 1e-14);
        EXPECT_NEAR(s->stddev, 0.0, 1e-14);
        EXPECT_NEAR(s->p99, d, 1e-14);
    }
    EXPECT_NEAR(r.hausdorff, d, 1e-14);
}

TEST(SurfaceDistance, ConcentricSpheresGiveTheRadiusDifferenceWithinTheSagitta)
{
    const double r1 = 1.0, r2 = 1.5;
    const Mesh inner = icosphere(3, r1).mesh;
    const Mesh outer = icosphere(2, r2).mesh;
    const double sag1 = r1 - inner_radius(inner);
    const double sag2 = r2 - inner_radius(outer);
    ASSERT_GT(sag1, 0.0);
    const SurfaceDistance r = surface_distance(inner, outer);
    // A point of the inner mesh has radius in [r1 - sag1, r1]; the outer
    // surface lies between radii r2 - sag2 and r2 around it.
    for (const DistanceStats* s : {&r.forward, &r.backward}) {
        EXPECT_GE(s->min, r2 - r1 - sag2 - 1e-12);
        EXPECT_LE(s->max, r2 - r1 + sag1 + 1e-12);
        EXPECT_NEAR(s->mean, r2 - r1, std::max(sag1, sag2));
    }
    // The outer vertices are on the sphere of radius r2, so the largest
    // backward distance is at least r2 - r1.
    EXPECT_GE(r.backward.max, r2 - r1 - 1e-12);
}

TEST(SurfaceDistance, MeshAgainstItselfIsZeroAtVerticesAndRoundingElsewhere)
{
    const Mesh m = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    SamplingOptions vertices_only;
    vertices_only.edges = vertices_only.faces = false;
    const SurfaceDistance v = surface_distance(m, m, distance_options(vertices_only));
    EXPECT_EQ(v.forward.max, 0.0);
    EXPECT_EQ(v.backward.max, 0.0);
    EXPECT_EQ(v.hausdorff, 0.0);

    const SurfaceDistance all = surface_distance(m, m);
    double coordinate_scale = 0.0;
    for (const Vec3& p : m.points) coordinate_scale = std::max(coordinate_scale, p.cwiseAbs().maxCoeff());
    EXPECT_LE(all.hausdorff, 1e-15 * coordinate_scale);
    EXPECT_EQ(all.forward.min, 0.0);
}

TEST(SurfaceDistance, SymmetricIsTheMaxOfBothDirections)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const SurfaceDistance r = surface_distance(a, b);
    EXPECT_NE(r.forward.max, r.backward.max);  // not symmetric per direction
    EXPECT_EQ(r.hausdorff, std::max(r.forward.max, r.backward.max));
    EXPECT_GT(r.hausdorff, 0.0);
}

TEST(SurfaceDistance, SwappingTheMeshesSwapsTheDirections)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const SurfaceDistance ab = surface_distance(a, b);
    const SurfaceDistance ba = surface_distance(b, a);
    expect_identical(ab.forward, ba.backward);
    expect_identical(ab.backward, ba.forward);
    EXPECT_EQ(ab.diagonal, bounding_box(a).diagonal());
    EXPECT_EQ(ba.diagonal, bounding_box(b).diagonal());
}

TEST(SurfaceDistance, DefaultBudgetIsTenTimesTheLargerFaceCount)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const SurfaceDistance r = surface_distance(a, b);
    const std::size_t target = 10 * std::max(a.n_faces(), b.n_faces());
    for (const DistanceStats* s : {&r.forward, &r.backward}) {
        EXPECT_LE(s->n_samples(), target);
        EXPECT_GE(s->n_samples() + 30, target);
    }
    EXPECT_EQ(r.forward.n_vertex, a.n_vertices());
    EXPECT_EQ(r.backward.n_vertex, b.n_vertices());

    SamplingOptions o;
    o.samples = 12345;
    const SurfaceDistance r2 = surface_distance(a, b, distance_options(o));
    EXPECT_LE(r2.forward.n_samples(), 12345u);
    EXPECT_GE(r2.forward.n_samples() + 30, 12345u);
    EXPECT_GE(r2.backward.n_samples() + 30, 12345u);
}

TEST(SurfaceDistance, ResultsAreIdenticalForOneAndTwoThreads)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const SurfaceDistance one = surface_distance(a, b);
    omp_set_num_threads(2);
    const SurfaceDistance two = surface_distance(a, b);
    omp_set_num_threads(saved);
    expect_identical(one.forward, two.forward);
    expect_identical(one.backward, two.backward);
    EXPECT_TRUE(same_bits(one.hausdorff, two.hausdorff));
}

TEST(SurfaceDistance, ScalingBothMeshesScalesDistances)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const SurfaceDistance r = surface_distance(a, b);
    const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
    // A power of two scales every floating-point operation exactly.
    const SurfaceDistance r4 =
        surface_distance(transformed(a, 4.0, id, Vec3::Zero()), transformed(b, 4.0, id, Vec3::Zero()));
    EXPECT_EQ(r4.forward.max, 4.0 * r.forward.max);
    EXPECT_EQ(r4.backward.mean, 4.0 * r.backward.mean);
    EXPECT_EQ(r4.hausdorff, 4.0 * r.hausdorff);
    // Any other factor: equal up to rounding, relative values unchanged.
    const double s = 3.7;
    const SurfaceDistance rs =
        surface_distance(transformed(a, s, id, Vec3::Zero()), transformed(b, s, id, Vec3::Zero()));
    EXPECT_NEAR(rs.hausdorff, s * r.hausdorff, 1e-9 * s * r.hausdorff);
    EXPECT_NEAR(rs.forward.mean, s * r.forward.mean, 1e-6 * s * r.forward.mean);
    EXPECT_NEAR(rs.backward.rms, s * r.backward.rms, 1e-6 * s * r.backward.rms);
    EXPECT_NEAR(rs.relative_hausdorff(), r.relative_hausdorff(), 1e-9 * r.relative_hausdorff());
    EXPECT_NEAR(relative_to(rs.forward, rs.diagonal).rms, relative_to(r.forward, r.diagonal).rms,
                1e-6 * relative_to(r.forward, r.diagonal).rms);
    EXPECT_NEAR(rs.metro_diagonal, s * r.metro_diagonal, 1e-12 * rs.metro_diagonal);
}

TEST(SurfaceDistance, RigidMotionChangesNothing)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3 shift(0.3, -1.2, 2.0);
    const Mesh ma = transformed(a, 1.0, rot, shift);
    const Mesh mb = transformed(b, 1.0, rot, shift);
    // Vertex samples move with the meshes: equal up to rounding.
    SamplingOptions vertices_only;
    vertices_only.edges = vertices_only.faces = false;
    const SurfaceDistance v = surface_distance(a, b, distance_options(vertices_only));
    const SurfaceDistance mv = surface_distance(ma, mb, distance_options(vertices_only));
    EXPECT_NEAR(mv.forward.max, v.forward.max, 1e-9 * v.forward.max);
    EXPECT_NEAR(mv.forward.mean, v.forward.mean, 1e-9 * v.forward.mean);
    EXPECT_NEAR(mv.backward.rms, v.backward.rms, 1e-9 * v.backward.rms);
    // With edge and face samples, rounding of the areas can move a few samples
    // between faces (carry-over), so the statistics agree to sampling noise.
    const SurfaceDistance r = surface_distance(a, b);
    const SurfaceDistance m = surface_distance(ma, mb);
    EXPECT_NEAR(m.hausdorff, r.hausdorff, 1e-3 * r.hausdorff);
    EXPECT_NEAR(m.forward.mean, r.forward.mean, 1e-3 * r.forward.mean);
    EXPECT_NEAR(m.backward.rms, r.backward.rms, 1e-3 * r.backward.rms);
}

TEST(SurfaceDistance, DegenerateOpenAndNonManifoldMeshesGiveFiniteNumbers)
{
    const Mesh teapot = read_mesh(kData + "/teapot.obj").mesh;
    Mesh bunny = read_mesh(kData + "/bunny_res3.ply").mesh;
    // Add degenerate faces: a collinear one and a point-like one.
    const auto n = std::int32_t(bunny.points.size());
    bunny.points.push_back(bunny.points[0]);
    bunny.points.push_back(0.5 * (bunny.points[0] + bunny.points[1]));
    bunny.faces.push_back({0, n + 1, 1});
    bunny.faces.push_back({n, n, 0});
    const Mesh bunny4 = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    for (const auto& [a, b] : {std::pair<const Mesh*, const Mesh*>{&bunny, &bunny4}, {&teapot, &bunny4}}) {
        const SurfaceDistance r = surface_distance(*a, *b);
        for (const DistanceStats* s : {&r.forward, &r.backward})
            for (double x : {s->min, s->max, s->mean, s->rms, s->stddev, s->p50, s->p95, s->p99})
                EXPECT_TRUE(std::isfinite(x));
        EXPECT_GT(r.hausdorff, 0.0);
    }
}

TEST(SurfaceDistance, MonteCarloIsReproducibleForASeed)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    SamplingOptions o;
    o.face_scheme = FaceSampling::MonteCarlo;
    o.seed = 9;
    const SurfaceDistance x = surface_distance(a, b, distance_options(o));
    const SurfaceDistance y = surface_distance(a, b, distance_options(o));
    o.seed = 10;
    const SurfaceDistance z = surface_distance(a, b, distance_options(o));
    expect_identical(x.forward, y.forward);
    EXPECT_NE(x.forward.mean, z.forward.mean);
    EXPECT_NEAR(x.forward.mean, z.forward.mean, 0.05 * x.forward.mean);
}

TEST(SurfaceDistance, PercentilesUseNearestRank)
{
    SurfaceSamples s;
    std::vector<double> d;
    for (int i = 100; i >= 1; --i) {  // 100 .. 1, unsorted order
        s.points.emplace_back(0, 0, 0);
        d.push_back(double(i));
    }
    s.n_face = 100;
    const DistanceStats st = distance_stats(s, d);
    EXPECT_EQ(st.p50, 50.0);
    EXPECT_EQ(st.p95, 95.0);
    EXPECT_EQ(st.p99, 99.0);
    EXPECT_EQ(st.min, 1.0);
    EXPECT_EQ(st.max, 100.0);
    EXPECT_DOUBLE_EQ(st.mean, 50.5);
    EXPECT_DOUBLE_EQ(st.rms, std::sqrt(338350.0 / 100.0));
    EXPECT_DOUBLE_EQ(st.stddev, std::sqrt((100.0 * 100.0 - 1.0) / 12.0));
    // Ten samples: the 95th and 99th percentiles are the largest.
    s.points.resize(10);
    d = {3, 1, 4, 1, 5, 9, 2, 6, 5, 3};
    const DistanceStats t = distance_stats(s, d);
    EXPECT_EQ(t.p50, 3.0);
    EXPECT_EQ(t.p95, 9.0);
    EXPECT_EQ(t.p99, 9.0);
}

TEST(SurfaceDistance, VertexDistancesMatchBruteForce)
{
    const Mesh a = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res3.ply").mesh;
    const ClosestPointIndex index(b);
    const std::vector<double> d = vertex_distances(a, index);
    ASSERT_EQ(d.size(), a.n_vertices());
    for (std::size_t i = 0; i < a.n_vertices(); i += 7)
        EXPECT_NEAR(d[i], closest_point_brute_force(b, a.points[i]).distance, 1e-12 * d[i] + 1e-300);
}

TEST(SurfaceDistance, SamplesGiveTheSameStatisticsBitForBit)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    for (const FaceSampling scheme : {FaceSampling::SimilarTriangles, FaceSampling::MonteCarlo}) {
        SamplingOptions o;
        o.face_scheme = scheme;
        o.seed = 5;
        const SurfaceDistance plain = surface_distance(a, b, distance_options(o));
        const SampledSurfaceDistance kept = surface_distance_samples(a, b, o);
        expect_identical(plain.forward, kept.distance.forward);
        expect_identical(plain.backward, kept.distance.backward);
        EXPECT_TRUE(same_bits(plain.hausdorff, kept.distance.hausdorff));
        EXPECT_TRUE(same_bits(plain.diagonal, kept.distance.diagonal));
        EXPECT_TRUE(same_bits(plain.metro_diagonal, kept.distance.metro_diagonal));
        EXPECT_TRUE(kept.distance.processed_vertex_distance.empty());
        // The kept samples and distances are those the statistics came from.
        for (const auto* d : {&kept.forward, &kept.backward}) {
            ASSERT_EQ(d->distances.size(), d->samples.size());
            ASSERT_EQ(d->samples.kind.size(), d->samples.size());
        }
        EXPECT_EQ(kept.forward.samples.size(), plain.forward.n_samples());
        EXPECT_EQ(kept.backward.samples.n_face, plain.backward.n_face);
        expect_identical(distance_stats(kept.forward.samples, kept.forward.distances), plain.forward);
        expect_identical(distance_stats(kept.backward.samples, kept.backward.distances), plain.backward);
        EXPECT_TRUE(same_bits(*std::max_element(kept.forward.distances.begin(), kept.forward.distances.end()),
                              plain.forward.max));
    }
}

TEST(SurfaceDistance, KeptSampleDistancesMatchBruteForce)
{
    const Mesh a = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    const Mesh b = read_mesh(kData + "/hemisphere.ply").mesh;
    SamplingOptions o;
    o.samples = 3000;
    const SampledSurfaceDistance r = surface_distance_samples(a, b, o);
    // Forward: samples on a, distances to b; backward: samples on b, distances to a.
    for (std::size_t i = 0; i < r.forward.samples.size(); i += 37)
        EXPECT_NEAR(r.forward.distances[i], closest_point_brute_force(b, r.forward.samples.points[i]).distance,
                    1e-12 * r.forward.distances[i] + 1e-300);
    for (std::size_t i = 0; i < r.backward.samples.size(); i += 37)
        EXPECT_NEAR(r.backward.distances[i], closest_point_brute_force(a, r.backward.samples.points[i]).distance,
                    1e-12 * r.backward.distances[i] + 1e-300);
    SamplingOptions none;
    none.vertices = none.edges = none.faces = false;
    EXPECT_THROW(surface_distance_samples(a, b, none), InvalidArgumentError);
}

TEST(SurfaceDistance, MetroDiagonalWidensTheUnionBoxByTwoPercent)
{
    const Mesh a = plane_grid(3, 3, 0.5).mesh;  // [-0.5, 0.5]^2 at z = 0
    Mesh b = a;
    for (Vec3& p : b.points) p.z() = 1.0;
    // Union box 1 x 1 x 1, diagonal sqrt 3; widened by 0.02 sqrt 3 on every side.
    EXPECT_NEAR(metro_diagonal(a, b), std::sqrt(3.0) * (1.0 + 0.04 * std::sqrt(3.0)), 1e-12);
    const SurfaceDistance r = surface_distance(a, b);
    EXPECT_DOUBLE_EQ(r.diagonal, std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(r.metro_diagonal, metro_diagonal(a, b));
}

TEST(SurfaceDistance, InvalidOptionsAndMeshesThrow)
{
    const Mesh m = plane_grid(3, 3).mesh;
    SamplingOptions o;
    o.samples = 0;
    EXPECT_THROW(surface_distance(m, m, distance_options(o)), InvalidArgumentError);
    EXPECT_THROW(surface_distance(m, Mesh{}), InvalidMeshError);
    EXPECT_THROW(relative_to(DistanceStats{}, 0.0), InvalidArgumentError);
    // An original without extent (all vertices at one place, or a diagonal
    // that underflows) is an input error, as for a point cloud; the processed
    // mesh may be so (the relative distances divide by A's diagonal only).
    for (const double scale : {0.0, 1e-200, 5e-324}) {
        Mesh point = icosphere(1, 1.0).mesh;
        for (Vec3& p : point.points) p = scale == 0.0 ? Vec3(1, 2, 3) : Vec3(scale * p);
        EXPECT_THROW(surface_distance(point, point), InvalidMeshError) << scale;
        const SurfaceDistance r = surface_distance(icosphere(2, 1.0).mesh, point);
        EXPECT_TRUE(std::isfinite(r.hausdorff)) << scale;
    }
    // Faces only, on a mesh whose only face is degenerate: no sample at all.
    Mesh flat;
    flat.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
    flat.faces = {Face{0, 1, 2}};
    SamplingOptions faces_only;
    faces_only.vertices = faces_only.edges = false;
    EXPECT_THROW(surface_distance(flat, m, distance_options(faces_only)), InvalidArgumentError);
}

namespace {

// The square [-1, 1]^2 as four triangles around its centre, raised to height
// h there: a flat fan for h = 0, an open pyramid for h > 0.
Mesh pyramid(double h)
{
    Mesh m;
    m.points = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(0, 0, h)};
    m.faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    return m;
}

// 10 log10(3 peak^2 / e), by hand.
double psnr_of(double peak, double e)
{
    return 10.0 * std::log10(3.0 * peak * peak / e);
}

}  // namespace

TEST(SummaryMetrics, ParallelPlanesGiveTheOffsetExactly)
{
    const double d = 0.125;
    const Mesh a = plane_grid(11, 11, 0.1).mesh;  // the unit square, diagonal sqrt(2)
    Mesh b = plane_grid(8, 8, 1.0 / 7.0).mesh;
    for (Vec3& p : b.points) p.z() += d;
    SummaryOptions so;
    so.fscore_thresholds = {0.5 * d / std::sqrt(2.0), 2.0 * d / std::sqrt(2.0)};  // below and above the offset
    const SurfaceDistance r = surface_distance(a, b, distance_options({}, std::nullopt, so));
    for (const DistanceStats* s : {&r.forward, &r.backward}) {
        ASSERT_TRUE(s->area_weighted);
        EXPECT_NEAR(s->area_weighted->mean, d, 1e-14);
        EXPECT_NEAR(s->area_weighted->rms, d, 1e-14);
        EXPECT_NEAR(s->area_weighted->area, 1.0, 1e-12);
        EXPECT_EQ(s->area_weighted->n_face, s->n_face);
    }
    ASSERT_TRUE(r.summary);
    EXPECT_NEAR(r.summary->chamfer_l1, 2.0 * d, 1e-14);
    EXPECT_NEAR(r.summary->chamfer_l2, 2.0 * d * d, 1e-14);
    ASSERT_EQ(r.fscore.size(), 2u);
    EXPECT_EQ(r.fscore[0].fscore, 0.0);
    EXPECT_EQ(r.fscore[0].precision, 0.0);
    EXPECT_NEAR(r.fscore[1].fscore, 1.0, 1e-14);
    EXPECT_NEAR(r.fscore[1].threshold_absolute, 2.0 * d, 1e-15);
    // PSNR by hand: peak^2 = 2, e = 1/64: 10 log10(3 x 2 x 64) = 10 log10(384) = 25.8433 dB.
    EXPECT_NEAR(r.summary->psnr.peak, std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(r.summary->psnr.mse_db, 10.0 * std::log10(384.0), 1e-11);
    EXPECT_NEAR(r.summary->psnr.hausdorff_db, 10.0 * std::log10(384.0), 1e-11);
    EXPECT_NEAR(r.summary->psnr.mse_db, 25.843312243675, 1e-9);
}

TEST(SummaryMetrics, PlaneAgainstPyramidMatchesTheSurfaceIntegrals)
{
    // A: the flat fan; B: the pyramid of height h. Forward, a point of A at
    // m = max(|x|, |y|) lies h (1 - m) / s below its face of B, s = sqrt(1 + h^2);
    // backward, a point of B lies h (1 - m) above A. Over the square, the mean
    // of 1 - m is 1/3 and that of (1 - m)^2 is 1/6 (B's area element is s times
    // the projected one, the same on every face, so B's means are those of the
    // square). The distances are linear on every face: the lattice sampling
    // gets their means exactly (its points are symmetric about the centroid);
    // the mean squares converge as 1/k (the lattice order k, here about 440:
    // the lattice leaves out a band of width 1/(k+2) along the edges).
    const double h = 0.75, s = std::sqrt(1.0 + h * h);
    const Mesh a = pyramid(0.0), b = pyramid(h);
    SamplingOptions o;
    o.samples = 400000;
    const double diag = 2.0 * std::sqrt(2.0);
    const double t = 0.1;  // absolute F-score threshold
    SummaryOptions so;
    so.fscore_thresholds = {t / diag};
    const SurfaceDistance r = surface_distance(a, b, distance_options(o, std::nullopt, so));
    ASSERT_TRUE(r.forward.area_weighted && r.backward.area_weighted && r.summary);
    const AreaWeightedStats& f = *r.forward.area_weighted;
    const AreaWeightedStats& bw = *r.backward.area_weighted;
    EXPECT_NEAR(f.mean, h / (3.0 * s), 1e-13);
    EXPECT_NEAR(bw.mean, h / 3.0, 1e-13);
    EXPECT_NEAR(f.mean_square, h * h / (6.0 * s * s), 5e-3 * h * h / (6.0 * s * s));
    EXPECT_NEAR(bw.mean_square, h * h / 6.0, 5e-3 * h * h / 6.0);
    EXPECT_NEAR(f.area, 4.0, 1e-12);
    EXPECT_NEAR(bw.area, 4.0 * s, 1e-12);
    EXPECT_NEAR(r.summary->chamfer_l1, h / (3.0 * s) + h / 3.0, 1e-13);
    EXPECT_NEAR(r.summary->chamfer_l2, h * h / (6.0 * s * s) + h * h / 6.0, 5e-3 * h * h / 3.0);
    // Metro's pooled mean is not the surface mean (vertex and edge samples).
    EXPECT_GT(std::abs(r.backward.mean - h / 3.0), 1e-4);
    // F-score: share of the square with 1 - m < u is 1 - (1 - u)^2.
    const double recall = 1.0 - std::pow(1.0 - t * s / h, 2), precision = 1.0 - std::pow(1.0 - t / h, 2);
    ASSERT_EQ(r.fscore.size(), 1u);
    EXPECT_NEAR(r.fscore[0].recall, recall, 3e-3);
    EXPECT_NEAR(r.fscore[0].precision, precision, 3e-3);
    EXPECT_NEAR(r.fscore[0].fscore, 2.0 * precision * recall / (precision + recall), 3e-3);
    // PSNR: the larger mean square is the backward one, h^2 / 6.
    EXPECT_NEAR(r.summary->psnr.mse_db, psnr_of(diag, h * h / 6.0), 0.03);  // 10 log10(1.005) = 0.02 dB
    EXPECT_NEAR(r.summary->psnr.hausdorff_db, psnr_of(diag, r.hausdorff * r.hausdorff), 1e-12);
    EXPECT_NEAR(r.hausdorff, h, 1e-14);  // the apex, a vertex sample
}

TEST(SummaryMetrics, MeshAgainstItselfHasFScoreOne)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    SummaryOptions so;
    so.fscore_thresholds = {1e-6, 0.001, 0.005};
    const SurfaceDistance r = surface_distance(a, a, distance_options({}, std::nullopt, so));
    ASSERT_TRUE(r.summary);
    for (const FScore& f : r.fscore) {
        EXPECT_EQ(f.precision, 1.0);
        EXPECT_EQ(f.recall, 1.0);
        EXPECT_EQ(f.fscore, 1.0);
    }
    EXPECT_LT(r.summary->chamfer_l1, 1e-15 * r.diagonal);
    EXPECT_GT(r.summary->psnr.mse_db, 250.0);  // rounding-level distances
}

TEST(SummaryMetrics, WeightsAreTheAreaEachFaceSampleStandsFor)
{
    // Brute force from the kept samples: w = area(f) / (face samples on f).
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    for (const FaceSampling scheme : {FaceSampling::SimilarTriangles, FaceSampling::MonteCarlo}) {
        SamplingOptions o;
        o.face_scheme = scheme;
        const SampledSurfaceDistance r = surface_distance_samples(a, b, o);
        const auto& s = r.forward.samples;
        std::vector<int> n(a.n_faces(), 0);
        for (std::size_t i = 0; i < s.size(); ++i)
            if (s.kind[i] == SampleKind::OnFace) ++n[s.element[i]];
        long double sw = 0, swd = 0, swd2 = 0;
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (s.kind[i] != SampleKind::OnFace) continue;
            const long double w = 0.5L * (long double)face_cross(a, s.element[i]).norm() / n[s.element[i]];
            const long double d = r.forward.distances[i];
            sw += w;
            swd += w * d;
            swd2 += w * d * d;
        }
        ASSERT_TRUE(r.distance.forward.area_weighted);
        EXPECT_NEAR(r.distance.forward.area_weighted->mean, double(swd / sw), 1e-12 * double(swd / sw));
        EXPECT_NEAR(r.distance.forward.area_weighted->mean_square, double(swd2 / sw), 1e-12 * double(swd2 / sw));
    }
}

TEST(SummaryMetrics, NoFaceSamplesGiveNoSummaryAndAReason)
{
    const Mesh a = plane_grid(5, 5).mesh;
    SamplingOptions o;
    o.faces = false;
    const SurfaceDistance r = surface_distance(a, a, distance_options(o));
    EXPECT_FALSE(r.forward.area_weighted);
    EXPECT_FALSE(r.summary);
    EXPECT_NE(r.summary_unavailable.find("no face sample"), std::string::npos);
    SummaryOptions bad;
    bad.fscore_thresholds = {0.0};
    EXPECT_THROW(surface_distance(a, a, distance_options({}, std::nullopt, bad)), InvalidArgumentError);
    bad.fscore_thresholds = {NAN};
    EXPECT_THROW(surface_distance(a, a, distance_options({}, std::nullopt, bad)), InvalidArgumentError);
    bad.fscore_thresholds.clear();
    bad.histogram_bins = kMaxHistogramBins + 1;
    EXPECT_THROW(surface_distance(a, a, distance_options({}, std::nullopt, bad)), InvalidArgumentError);
}

TEST(SummaryMetrics, DefaultStatisticsAreBitwiseUnchangedByTheSummary)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    SummaryOptions so;
    so.fscore_thresholds = {0.001};
    so.histogram_bins = 16;
    const SurfaceDistance plain = surface_distance(a, b);
    const SurfaceDistance full = surface_distance(a, b, distance_options({}, std::nullopt, so));
    expect_identical(plain.forward, full.forward);
    expect_identical(plain.backward, full.backward);
    EXPECT_TRUE(plain.forward.histogram.counts.empty());
    EXPECT_EQ(full.forward.histogram.counts.size(), 16u);
}

TEST(Histogram, CountsEverySampleInEqualBinsUpToTheMaximum)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    const Mesh b = read_mesh(kData + "/bunny_res4_ascii.ply").mesh;
    SummaryOptions so;
    so.histogram_bins = 7;
    const SampledSurfaceDistance r = surface_distance_samples(a, b, {}, so);
    for (const auto& [stats, dir] : {std::pair{&r.distance.forward, &r.forward}, {&r.distance.backward, &r.backward}}) {
        const Histogram& h = stats->histogram;
        ASSERT_EQ(h.edges.size(), 8u);
        ASSERT_EQ(h.counts.size(), 7u);
        EXPECT_EQ(h.edges.front(), 0.0);
        EXPECT_EQ(h.edges.back(), stats->max);
        // Brute force: count the distances in [e_i, e_{i+1}) (the last bin closed).
        for (std::size_t i = 0; i < 7; ++i) {
            std::size_t n = 0;
            for (double d : dir->distances)
                if (d >= h.edges[i] && (d < h.edges[i + 1] || (i == 6 && d <= h.edges[7]))) ++n;
            EXPECT_NEAR(double(h.counts[i]), double(n), 2.0) << "bin " << i;  // ties at an edge may round either way
        }
        std::size_t total = 0;
        for (auto c : h.counts) total += c;
        EXPECT_EQ(total, stats->n_samples());
    }
    EXPECT_THROW(distance_histogram({}, 3), InvalidArgumentError);
    EXPECT_THROW(distance_histogram({1.0}, 0), InvalidArgumentError);
    const Histogram zero = distance_histogram({0.0, 0.0}, 4);
    EXPECT_EQ(zero.counts[0], 2u);
}

// The histogram's maximum and counts are made in parallel: the same as the
// loop over the distances, at any thread count (a NaN or a -0: the loop).
TEST(Histogram, IsTheLoopOverTheDistancesAtAnyThreadCount)
{
    const auto reference = [](const std::vector<double>& d, std::size_t bins) {
        const double max = *std::max_element(d.begin(), d.end());
        Histogram h;
        for (std::size_t i = 0; i <= bins; ++i) h.edges.push_back(max * double(i) / double(bins));
        h.counts.assign(bins, 0);
        const double width = max / double(bins);
        for (double x : d) ++h.counts[width > 0.0 ? std::min(bins - 1, std::size_t(x / width)) : 0];
        return h;
    };
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 2.0);
    std::vector<double> d(300001);
    for (double& x : d) x = u(rng);
    for (std::size_t i = 0; i < d.size(); i += 97) d[i] = 0.125 * double(i % 17);  // ties at bin edges
    std::vector<double> zeros = {0.0, -0.0, 0.0};
    const int threads = omp_get_max_threads();
    for (const int t : {1, 3}) {
        omp_set_num_threads(t);
        for (const std::size_t bins : {1u, 16u, 1000u}) {
            const Histogram h = distance_histogram(d, bins), r = reference(d, bins);
            EXPECT_EQ(h.edges, r.edges) << t << " threads, " << bins << " bins";
            EXPECT_EQ(h.counts, r.counts) << t << " threads, " << bins << " bins";
        }
        const Histogram hz = distance_histogram(zeros, 4);
        EXPECT_EQ(hz.counts, reference(zeros, 4).counts);
        EXPECT_FALSE(std::signbit(hz.edges[0]));  // the first of the equal maxima, +0
    }
    omp_set_num_threads(threads);
}

TEST(SummaryMetrics, MeanSquaresConvergeToTheSurfaceIntegral)
{
    // The pyramid's backward mean square h^2 / 6 (see above): the lattice's
    // error falls as the sample count grows (about 1/k, k ~ sqrt(samples)).
    const double h = 0.75;
    double previous = INFINITY;
    for (std::size_t n : {4000u, 40000u, 400000u}) {
        SamplingOptions o;
        o.samples = n;
        const SurfaceDistance r = surface_distance(pyramid(0.0), pyramid(h), distance_options(o));
        const double error = std::abs(r.backward.area_weighted->mean_square - h * h / 6.0);
        EXPECT_LT(error, 0.5 * previous) << n << " samples";
        previous = error;
    }
    // Monte Carlo face samples: no lattice bias; within a few standard errors.
    SamplingOptions mc;
    mc.samples = 400000;
    mc.face_scheme = FaceSampling::MonteCarlo;
    const SurfaceDistance r = surface_distance(pyramid(0.0), pyramid(h), distance_options(mc));
    EXPECT_NEAR(r.backward.area_weighted->mean_square, h * h / 6.0, 1e-2 * h * h / 6.0);  // 5 standard errors
    EXPECT_NEAR(r.backward.area_weighted->mean, h / 3.0, 1e-2 * h / 3.0);
}

namespace {

void expect_same_vector(const std::vector<double>& x, const std::vector<double>& y)
{
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_TRUE(same_bits(x[i], y[i])) << i;
}

// Every statistic of one direction, bit for bit.
void expect_every_bit(const DistanceStats& x, const DistanceStats& y)
{
    expect_identical(x, y);
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(same_bits(x.max_point[c], y.max_point[c]));
    EXPECT_EQ(x.max_kind, y.max_kind);
    EXPECT_EQ(x.max_element, y.max_element);
    ASSERT_EQ(x.area_weighted.has_value(), y.area_weighted.has_value());
    if (x.area_weighted) {
        const AreaWeightedStats &p = *x.area_weighted, &q = *y.area_weighted;
        for (auto m : {&AreaWeightedStats::mean, &AreaWeightedStats::mean_square, &AreaWeightedStats::rms,
                       &AreaWeightedStats::area, &AreaWeightedStats::area_fraction})
            EXPECT_TRUE(same_bits(p.*m, q.*m));
        EXPECT_EQ(p.n_face, q.n_face);
    }
    expect_same_vector(x.histogram.edges, y.histogram.edges);
    EXPECT_EQ(x.histogram.counts, y.histogram.counts);
    ASSERT_EQ(x.signed_distance.has_value(), y.signed_distance.has_value());
    if (x.signed_distance) {
        const SignedDistanceStats &p = *x.signed_distance, &q = *y.signed_distance;
        for (auto m : {&SignedDistanceStats::min, &SignedDistanceStats::max, &SignedDistanceStats::mean,
                       &SignedDistanceStats::rms})
            EXPECT_TRUE(same_bits(p.*m, q.*m));
        EXPECT_EQ(p.flipped, q.flipped);
    }
    EXPECT_EQ(x.signed_unavailable, y.signed_unavailable);
}

void expect_every_bit(const SurfaceDistance& x, const SurfaceDistance& y)
{
    expect_every_bit(x.forward, y.forward);
    expect_every_bit(x.backward, y.backward);
    EXPECT_TRUE(same_bits(x.hausdorff, y.hausdorff));
    ASSERT_EQ(x.summary.has_value(), y.summary.has_value());
    if (x.summary) {
        EXPECT_TRUE(same_bits(x.summary->chamfer_l1, y.summary->chamfer_l1));
        EXPECT_TRUE(same_bits(x.summary->chamfer_l2, y.summary->chamfer_l2));
        EXPECT_TRUE(same_bits(x.summary->psnr.mse_db, y.summary->psnr.mse_db));
    }
    EXPECT_EQ(x.summary_unavailable, y.summary_unavailable);
    ASSERT_EQ(x.fscore.size(), y.fscore.size());
    for (std::size_t k = 0; k < x.fscore.size(); ++k) {
        EXPECT_TRUE(same_bits(x.fscore[k].precision, y.fscore[k].precision));
        EXPECT_TRUE(same_bits(x.fscore[k].recall, y.fscore[k].recall));
    }
    ASSERT_EQ(x.forward_hausdorff.has_value(), y.forward_hausdorff.has_value());
    if (x.forward_hausdorff) {
        EXPECT_TRUE(same_bits(x.forward_hausdorff->lower, y.forward_hausdorff->lower));
        EXPECT_TRUE(same_bits(x.forward_hausdorff->upper, y.forward_hausdorff->upper));
        EXPECT_TRUE(same_bits(x.backward_hausdorff->lower, y.backward_hausdorff->lower));
        EXPECT_TRUE(same_bits(x.backward_hausdorff->upper, y.backward_hausdorff->upper));
    }
}

}  // namespace

// The order in which a chunk's samples are queried: its runs (one element's
// consecutive samples) whole and in their own order, sorted by the top 30
// bits of the Morton code of their first point (ties by position), every
// sample once; none (the samples' own order) where that order is already as
// coherent.
TEST(SurfaceDistance, ChunkQueryOrderSortsWholeRunsAlongTheMortonCurve)
{
    const Mesh sphere = icosphere(2).mesh;  // 320 faces
    SamplingOptions o;
    o.samples = 20000;
    const SurfaceSamples s = sample_surface(sphere, o);
    const BoundingBox box = bounding_box(sphere);
    const Vec3 ext = detail::morton_extent(box);
    // The samples' runs in a random order: an incoherent numbering.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;  // [first, end)
    for (std::uint32_t i = 0; i < s.size(); ++i)
        if (i == 0 || s.kind[i] != s.kind[i - 1] || s.element[i] != s.element[i - 1]) runs.push_back({i, i});
    for (std::size_t r = 0; r < runs.size(); ++r)
        runs[r].second = r + 1 < runs.size() ? runs[r + 1].first : std::uint32_t(s.size());
    std::mt19937_64 rng(3);
    std::shuffle(runs.begin(), runs.end(), rng);
    std::vector<Vec3> p;
    std::vector<SampleKind> kind;
    std::vector<std::uint32_t> element;
    for (const auto& [first, end] : runs)
        for (std::uint32_t i = first; i < end; ++i) {
            p.push_back(s.points[i]);
            kind.push_back(s.kind[i]);
            element.push_back(s.element[i]);
        }
    const std::size_t k = p.size();
    std::vector<std::uint32_t> order;
    detail::chunk_query_order(p.data(), kind.data(), element.data(), k, box, order);
    ASSERT_EQ(order.size(), k);
    std::vector<char> taken(k, 0);
    for (const std::uint32_t i : order) {
        ASSERT_LT(i, k);
        ASSERT_FALSE(taken[i]) << i;
        taken[i] = 1;
    }
    auto starts_run = [&](std::size_t i) { return i == 0 || kind[i] != kind[i - 1] || element[i] != element[i - 1]; };
    // The runs as they come in the order: each begins a run of the chunk and
    // holds all of it, in position order; their keys do not decrease.
    std::size_t n_runs = 0;
    std::pair<std::uint64_t, std::uint32_t> last{0, 0};
    for (std::size_t j = 0; j < k;) {
        const std::uint32_t first = order[j];
        ASSERT_TRUE(starts_run(first)) << j;
        std::size_t len = 1;
        while (j + len < k && order[j + len] == first + len && !starts_run(first + len)) ++len;
        ASSERT_TRUE(first + len == k || starts_run(first + len)) << "run at " << first << " cut after " << len;
        const std::pair<std::uint64_t, std::uint32_t> key{detail::morton_code(p[first], box.min, ext) >> 33, first};
        EXPECT_TRUE(n_runs == 0 || last < key) << j;
        last = key;
        ++n_runs;
        j += len;
    }
    EXPECT_EQ(n_runs, runs.size());
    // The chunk in that order is coherent: no order again.
    std::vector<Vec3> p2;
    std::vector<SampleKind> kind2;
    std::vector<std::uint32_t> element2;
    for (const std::uint32_t i : order) {
        p2.push_back(p[i]);
        kind2.push_back(kind[i]);
        element2.push_back(element[i]);
    }
    std::vector<std::uint32_t> again;
    detail::chunk_query_order(p2.data(), kind2.data(), element2.data(), k, box, again);
    EXPECT_TRUE(again.empty());
    // Nothing to order: no sample, one run.
    detail::chunk_query_order(p.data(), kind.data(), element.data(), 0, box, order);
    EXPECT_TRUE(order.empty());
    const std::size_t one = runs.front().second - runs.front().first;
    detail::chunk_query_order(p.data(), kind.data(), element.data(), one, box, order);
    EXPECT_TRUE(order.empty());
    // A point in the box keeps its cell; one outside it takes the nearest.
    EXPECT_EQ(detail::morton_code(box.min, box.min, ext), 0u);
    EXPECT_EQ(detail::morton_code(box.max, box.min, ext), (std::uint64_t(1) << 63) - 1);
    EXPECT_EQ(detail::morton_code(box.max + ext, box.min, ext), (std::uint64_t(1) << 63) - 1);
    EXPECT_EQ(detail::morton_code(box.min - ext, box.min, ext), 0u);
}

// A mesh numbered at random (its vertices and faces shuffled), whose chunks
// are queried in Morton order, gives the statistics of its kept samples,
// which are queried in their own order, bit for bit.
TEST(SurfaceDistance, ChunksQueriedInMortonOrderGiveTheKeptSamplesStatisticsBitForBit)
{
    Mesh a = icosphere(4).mesh;  // 5,120 faces
    const Mesh b = icosphere(2, 1.02).mesh;
    std::mt19937_64 rng(11);
    std::vector<std::uint32_t> to(a.n_vertices());
    std::iota(to.begin(), to.end(), 0u);
    std::shuffle(to.begin(), to.end(), rng);
    std::vector<Vec3> points(a.n_vertices());
    for (std::size_t v = 0; v < to.size(); ++v) points[to[v]] = a.points[v];
    a.points = points;
    for (Face& f : a.faces)
        for (auto& v : f) v = decltype(f[0])(to[std::size_t(v)]);
    std::shuffle(a.faces.begin(), a.faces.end(), rng);
    SamplingOptions o;
    o.samples = 60000;
    // The first chunk of A's samples is ordered.
    const SurfaceSamples s = sample_surface(a, o);
    std::vector<std::uint32_t> order;
    const std::size_t k = std::min(s.size(), 4 * detail::kQueryBlock);
    detail::chunk_query_order(s.points.data(), s.kind.data(), s.element.data(), k, bounding_box(a), order);
    EXPECT_EQ(order.size(), k);
    SummaryOptions so;
    so.fscore_thresholds = {0.001, 0.02};
    so.histogram_bins = 5;
    DistanceOptions options = distance_options(o, std::nullopt, so);
    options.keep_samples = true;
    const SurfaceDistance kept = detail::surface_distance(a, b, options, detail::kQueryBlock);
    options.keep_samples = false;
    const int threads = omp_get_max_threads();
    for (const std::size_t chunk : {4 * detail::kQueryBlock, detail::kSampleChunk})
        for (const int t : {1, 2}) {
            omp_set_num_threads(t);
            expect_every_bit(kept, detail::surface_distance(a, b, options, chunk));
        }
    omp_set_num_threads(threads);
}

TEST(SurfaceDistance, ChunkedSamplesGiveTheKeptSamplesStatisticsBitForBit)
{
    // The kept path makes and queries all samples at once; without kept
    // samples they are made, queried and summed a chunk at a time. With one
    // query block a chunk, the chunks end inside vertex, edge and face runs
    // (20 coarse faces of 2500 samples each span several chunks).
    const Mesh coarse = icosphere(0).mesh;
    const Mesh fine = icosphere(2, 1.05).mesh;
    const Mesh flat = plane_grid(12, 9, 0.1).mesh;  // open: no sign
    const Mesh bumpy = heightfield(16, 0.05).mesh;
    SummaryOptions so;
    so.fscore_thresholds = {0.001, 0.02, 0.05};
    so.histogram_bins = 7;
    HausdorffOptions certify;
    certify.relative_tolerance = 1e-3;
    struct Case
    {
        const Mesh *a, *b;
        std::optional<std::size_t> samples;
        bool edges;
        bool certified;
    };
    for (const Case& c : {Case{&coarse, &fine, 50000, true, false}, Case{&fine, &coarse, 40000, true, true},
                          Case{&coarse, &fine, 30000, false, true}, Case{&flat, &bumpy, 20000, true, false}})
        for (const FaceSampling scheme : {FaceSampling::SimilarTriangles, FaceSampling::MonteCarlo}) {
            SCOPED_TRACE(testing::Message() << "faces " << c.a->n_faces() << " vs " << c.b->n_faces() << ", scheme "
                                            << int(scheme) << ", certified " << c.certified);
            SamplingOptions o;
            o.face_scheme = scheme;
            o.seed = 9;
            o.samples = c.samples;
            o.edges = c.edges;
            const auto cert = c.certified ? std::optional<HausdorffOptions>(certify) : std::nullopt;
            DistanceOptions options = distance_options(o, cert, so);
            options.vertex_distances = true;
            options.keep_samples = true;
            const SurfaceDistance kept = detail::surface_distance(*c.a, *c.b, options, detail::kQueryBlock);
            ASSERT_GT(kept.forward_samples.samples.size(), 4 * detail::kQueryBlock);
            options.keep_samples = false;
            for (const std::size_t chunk : {detail::kQueryBlock, 3 * detail::kQueryBlock, detail::kSampleChunk}) {
                const SurfaceDistance chunked = detail::surface_distance(*c.a, *c.b, options, chunk);
                expect_every_bit(kept, chunked);
                EXPECT_TRUE(chunked.forward_samples.samples.points.empty());
                expect_same_vector(kept.original_vertex_distance, chunked.original_vertex_distance);
                expect_same_vector(kept.processed_vertex_signed_distance, chunked.processed_vertex_signed_distance);
            }
            // A chunk is folded by one thread of the team that queries the
            // next: the same at 1 and 3 threads.
            const int threads = omp_get_max_threads();
            for (const int t : {1, 3}) {
                omp_set_num_threads(t);
                expect_every_bit(kept, detail::surface_distance(*c.a, *c.b, options, detail::kQueryBlock));
            }
            omp_set_num_threads(threads);
            // The public call (default chunks) too.
            expect_every_bit(kept, surface_distance(*c.a, *c.b, distance_options(o, cert, so)));
            // And the deprecated positional overload (0.2), its kept samples
            // in the pointers given.
            SampledDirection fk;
            const SurfaceDistance old = surface_distance(*c.a, *c.b, o, true, cert, so, &fk);
            expect_every_bit(kept, old);
            expect_same_vector(kept.forward_samples.distances, fk.distances);
            expect_same_vector(kept.processed_vertex_distance, old.b_vertex_distance);  // the 0.2 names
            expect_same_vector(kept.original_vertex_signed_distance, old.a_vertex_signed_distance);
            EXPECT_TRUE(old.processed_vertex_distance.empty());
        }
    EXPECT_THROW(detail::surface_distance(coarse, fine, distance_options({}, std::nullopt, so), 1000),
                 InvalidArgumentError);
}

namespace {

// Every part of a surface distance a caller can ask for: F-scores, a
// histogram, certified Hausdorff bounds, per-vertex distances, and the
// samples kept (\p keep) or folded chunk by chunk.
DistanceOptions everything_options(bool keep)
{
    SummaryOptions so;
    so.fscore_thresholds = {0.01, 0.05};
    so.histogram_bins = 5;
    HausdorffOptions certify;
    certify.relative_tolerance = 1e-3;
    DistanceOptions o = distance_options({}, certify, so);
    o.vertex_distances = true;
    o.keep_samples = keep;
    return o;
}

}  // namespace

TEST(SurfaceDistance, CallerBuiltIndexesGiveTheSameResultsBitForBit)
{
    const Mesh coarse = icosphere(0).mesh;
    const Mesh fine = icosphere(2, 1.05).mesh;
    for (const bool keep : {false, true}) {
        DistanceOptions o = everything_options(keep);
        const SurfaceDistance own = surface_distance(coarse, fine, o);
        const ClosestPointIndex ia(coarse), ib(fine);
        o.index_a = &ia;
        o.index_b = &ib;
        const SurfaceDistance given = surface_distance(coarse, fine, o);
        expect_every_bit(own, given);
        expect_same_vector(own.original_vertex_distance, given.original_vertex_distance);
        expect_same_vector(own.processed_vertex_signed_distance, given.processed_vertex_signed_distance);
        expect_same_vector(own.forward_samples.distances, given.forward_samples.distances);
        o.index_a = &ib;  // an index of the other mesh
        EXPECT_THROW(surface_distance(coarse, fine, o), InvalidArgumentError);
    }
}

TEST(SurfaceDistance, WhatIsHandedOverGivesTheSameResultsBitForBitAndIsFreed)
{
    // compare_meshes() hands the local difference's index of the original,
    // and the closest points of the processed mesh's vertices on it, to the
    // surface distance: the backward direction runs first on them and frees
    // them; the results are those of a surface distance that makes its own,
    // to the last bit.
    const Mesh coarse = icosphere(0).mesh;
    const Mesh fine = icosphere(2, 1.05).mesh;
    for (const bool keep : {false, true}) {
        DistanceOptions o = everything_options(keep);
        const SurfaceDistance own = surface_distance(coarse, fine, o);
        auto check = [&](const SurfaceDistance& given) {
            expect_every_bit(own, given);
            ASSERT_TRUE(own.backward_hausdorff && given.backward_hausdorff);
            EXPECT_TRUE(same_bits(own.backward_hausdorff->lower, given.backward_hausdorff->lower));
            EXPECT_TRUE(same_bits(own.backward_hausdorff->upper, given.backward_hausdorff->upper));
            expect_same_vector(own.original_vertex_distance, given.original_vertex_distance);
            expect_same_vector(own.processed_vertex_distance, given.processed_vertex_distance);
            expect_same_vector(own.processed_vertex_signed_distance, given.processed_vertex_signed_distance);
            expect_same_vector(own.backward_samples.distances, given.backward_samples.distances);
        };
        detail::HandedToDistance handed;
        handed.index_a.emplace(coarse);
        handed.b_vertices_on_a = handed.index_a->closest_points(fine.points);
        check(detail::two_directions(coarse, fine, o, keep, keep, false, detail::kSampleChunk, &handed));
        EXPECT_FALSE(handed.index_a.has_value());  // freed once the backward direction is done
        EXPECT_TRUE(handed.b_vertices_on_a.empty());
        // Each alone, and nothing (an empty hand): as without.
        handed.index_a.emplace(coarse);
        check(detail::two_directions(coarse, fine, o, keep, keep, false, detail::kSampleChunk, &handed));
        handed.b_vertices_on_a = ClosestPointIndex(coarse).closest_points(fine.points);
        check(detail::two_directions(coarse, fine, o, keep, keep, false, detail::kSampleChunk, &handed));
        EXPECT_TRUE(handed.b_vertices_on_a.empty());
        check(detail::two_directions(coarse, fine, o, keep, keep, false, detail::kSampleChunk, &handed));
        // An index beside DistanceOptions::index_a is a caller's mistake.
        const ClosestPointIndex ia(coarse);
        o.index_a = &ia;
        handed.index_a.emplace(coarse);
        EXPECT_THROW(detail::two_directions(coarse, fine, o, keep, keep, false, detail::kSampleChunk, &handed),
                     InvalidArgumentError);
    }
}
