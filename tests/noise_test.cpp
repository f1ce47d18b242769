#include "meshdiff/studies/noise.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/normals.h"
#include "meshdiff/studies/shapes.h"

#include <gtest/gtest.h>
#include <omp.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace meshdiff {
namespace {

const NoiseDirection kDirections[] = {NoiseDirection::Normal, NoiseDirection::Random};
const NoiseDistribution kDistributions[] = {NoiseDistribution::Uniform, NoiseDistribution::Gaussian};

NoiseOptions options(double amplitude, NoiseDirection direction = NoiseDirection::Normal,
                     NoiseDistribution distribution = NoiseDistribution::Uniform, std::uint64_t seed = 1)
{
    NoiseOptions o;
    o.amplitude = amplitude;
    o.direction = direction;
    o.distribution = distribution;
    o.seed = seed;
    return o;
}

std::string label(const NoiseOptions& o)
{
    return to_string(o.direction) + "/" + to_string(o.distribution);
}

// Bitwise equality of the positions (== would call -0.0 and +0.0 equal).
bool bitwise_equal(const Mesh& a, const Mesh& b)
{
    return a.points.size() == b.points.size() &&
           std::memcmp(a.points.data(), b.points.data(), a.points.size() * sizeof(Vec3)) == 0;
}

// Mean edge length computed independently of the library: the set of
// undirected face edges.
double reference_mean_edge(const Mesh& m)
{
    std::set<std::pair<int, int>> edges;
    for (const Face& f : m.faces)
        for (int k = 0; k < 3; ++k) {
            const int a = f[std::size_t(k)], b = f[std::size_t((k + 1) % 3)];
            edges.emplace(std::min(a, b), std::max(a, b));
        }
    double sum = 0;
    for (const auto& [a, b] : edges) sum += (m.points[std::size_t(a)] - m.points[std::size_t(b)]).norm();
    return sum / double(edges.size());
}

TEST(Noise, ZeroAmplitudeChangesNothing)
{
    const Mesh original = noisy_sphere(3, 0.05, 3).mesh;
    for (auto dir : kDirections)
        for (auto dist : kDistributions) {
            Mesh m = original;
            m.points[5] = Vec3(-0.0, 0.0, -0.0);  // signed zeros must survive too
            const Mesh before = m;
            const NoiseReport r = add_noise(m, options(0.0, dir, dist));
            const std::string what = label(options(0.0, dir, dist));
            EXPECT_TRUE(bitwise_equal(m, before)) << what;
            EXPECT_EQ(m.faces, before.faces) << what;
            EXPECT_EQ(r.amplitude, 0.0) << what;
            EXPECT_EQ(r.max_displacement, 0.0) << what;
        }
}

TEST(Noise, SameSeedSameBitsDifferentSeedDifferentNoise)
{
    const Mesh original = noisy_sphere(3, 0.05, 3).mesh;
    for (auto dir : kDirections)
        for (auto dist : kDistributions) {
            Mesh a = original, b = original, c = original;
            add_noise(a, options(0.3, dir, dist, 42));
            add_noise(b, options(0.3, dir, dist, 42));
            add_noise(c, options(0.3, dir, dist, 43));
            const std::string what = label(options(0.3, dir, dist));
            EXPECT_FALSE(bitwise_equal(a, original)) << what;
            EXPECT_TRUE(bitwise_equal(a, b)) << what;
            EXPECT_FALSE(bitwise_equal(a, c)) << what;
            std::size_t same = 0;  // a different seed changes (almost) every vertex, not a few
            for (std::size_t i = 0; i < a.n_vertices(); ++i) same += a.points[i] == c.points[i];
            EXPECT_EQ(same, 0u) << what;
            EXPECT_EQ(a.faces, original.faces) << what;
        }
}

// Signed displacements t_i = (p'_i - p_i) . n_i along the normals of an
// icosphere, checking on the way that every displacement is parallel to n_i.
std::vector<double> normal_displacements(const Mesh& before, const Mesh& after)
{
    const std::vector<Vec3> n = vertex_normals(before);
    std::vector<double> t;
    for (std::size_t i = 0; i < before.n_vertices(); ++i) {
        const Vec3 d = after.points[i] - before.points[i];
        EXPECT_LE(d.cross(n[i]).norm(), 1e-15 + 1e-12 * d.norm()) << "vertex " << i << " left its normal line";
        t.push_back(d.dot(n[i]));
    }
    return t;
}

// Statistical tolerances. With n independent draws, the sample mean of t has
// standard deviation sd(t) / sqrt(n) and the sample mean of t^2 has
// sd(t^2) / sqrt(n). Uniform t on [-A, A): E t^2 = A^2/3, Var t^2 = A^4/5 -
// A^4/9 = 4 A^4/45. Gaussian t: E t^2 = A^2, Var t^2 = 2 A^4. The checks allow
// 5 standard deviations, which a correct implementation exceeds with
// probability below 1e-6 (whatever the seed); the seed is fixed anyway, so the
// test is deterministic. With n = 10242 the mean-square bands are about +-4.4%
// (uniform) and +-7% (gaussian) of the expected value, so an amplitude off by
// 10%, a uniform law on [0, A) or [-A/2, A/2), or a Gaussian in place of a
// uniform (RMS off by sqrt(3)) all fail.
TEST(Noise, UniformAlongNormalsOnAnIcosphere)
{
    const Mesh sphere = icosphere(5).mesh;
    Mesh m = sphere;
    const double a = 0.4;
    const NoiseReport r = add_noise(m, options(a));
    const double A = a * reference_mean_edge(sphere);
    EXPECT_NEAR(r.amplitude, A, 1e-12 * A);
    EXPECT_EQ(r.moved, sphere.n_vertices());
    EXPECT_EQ(r.skipped(), 0u);
    const std::vector<double> t = normal_displacements(sphere, m);
    const double n = double(t.size());
    double sum = 0, sum2 = 0, largest = 0;
    for (double x : t) {
        EXPECT_LE(std::abs(x), A * (1 + 1e-12));
        sum += x;
        sum2 += x * x;
        largest = std::max(largest, std::abs(x));
    }
    EXPECT_NEAR(largest, r.max_displacement, 1e-12 * A);
    EXPECT_GT(largest, 0.99 * A);  // the whole range [-A, A) is used
    EXPECT_NEAR(sum / n, 0.0, 5 * (A / std::sqrt(3.0)) / std::sqrt(n));
    EXPECT_NEAR(sum2 / n, A * A / 3, 5 * A * A * std::sqrt(4.0 / 45.0) / std::sqrt(n));
    EXPECT_NEAR(std::sqrt(sum2 / n), A / std::sqrt(3.0), 0.025 * A / std::sqrt(3.0));
}

TEST(Noise, GaussianAlongNormalsOnAnIcosphere)
{
    const Mesh sphere = icosphere(5).mesh;
    Mesh m = sphere;
    const double a = 0.4;
    const NoiseReport r = add_noise(m, options(a, NoiseDirection::Normal, NoiseDistribution::Gaussian, 9));
    const double A = r.amplitude;
    const std::vector<double> t = normal_displacements(sphere, m);
    const double n = double(t.size());
    double sum = 0, sum2 = 0;
    std::size_t beyond = 0;
    for (double x : t) {
        sum += x;
        sum2 += x * x;
        beyond += std::abs(x) > A;
    }
    EXPECT_NEAR(sum / n, 0.0, 5 * A / std::sqrt(n));
    EXPECT_NEAR(sum2 / n, A * A, 5 * A * A * std::sqrt(2.0) / std::sqrt(n));
    // P(|g| > 1) = 0.3173 for a standard normal: binomial sd sqrt(p (1 - p) / n) = 0.0046, 5 sd = 0.023.
    EXPECT_NEAR(double(beyond) / n, 0.3173, 0.023);
}

TEST(Noise, RandomDirectionsAreIsotropicAndBounded)
{
    const Mesh sphere = icosphere(5).mesh;
    Mesh m = sphere;
    const NoiseReport r = add_noise(m, options(0.3, NoiseDirection::Random));
    const double A = r.amplitude;
    EXPECT_EQ(r.moved, sphere.n_vertices());
    const std::vector<Vec3> normals = vertex_normals(sphere);
    const double n = double(sphere.n_vertices());
    Vec3 sq = Vec3::Zero();
    double cos_sum = 0;
    for (std::size_t i = 0; i < sphere.n_vertices(); ++i) {
        const Vec3 d = m.points[i] - sphere.points[i];
        EXPECT_LE(d.norm(), A * (1 + 1e-12));
        ASSERT_GT(d.norm(), 0.0);
        const Vec3 u = d.normalized();
        sq += u.cwiseProduct(u);
        cos_sum += std::abs(u.dot(normals[i]));
    }
    // A uniform unit vector: each squared component has mean 1/3 and variance
    // 4/45; |cos| to any fixed axis is uniform on [0, 1] (mean 1/2, variance
    // 1/12). 5 standard deviations of the sample means. Normals would give
    // |cos| = 1, a bias towards an axis a squared component far from 1/3.
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(sq[k] / n, 1.0 / 3, 5 * std::sqrt(4.0 / 45.0 / n)) << "axis " << k;
    EXPECT_NEAR(cos_sum / n, 0.5, 5 * std::sqrt(1.0 / 12.0 / n));
}

TEST(Noise, UnitsScaleAsDocumented)
{
    const Mesh base = torus(48, 16).mesh;
    const double e = reference_mean_edge(base);
    const double diag = bounding_box(base).diagonal();
    for (auto dir : kDirections)
        for (auto dist : kDistributions) {
            const std::string what = label(options(0, dir, dist));
            Mesh edge = base, diagonal = base, absolute_e = base, absolute_d = base;
            NoiseOptions o = options(0.25, dir, dist, 5);
            o.unit = NoiseUnit::MeanEdge;
            const NoiseReport re = add_noise(edge, o);
            EXPECT_NEAR(re.unit_length, e, 1e-12 * e) << what;
            EXPECT_NEAR(re.mean_edge, e, 1e-12 * e) << what;
            EXPECT_EQ(re.amplitude, 0.25 * re.unit_length) << what;
            o.unit = NoiseUnit::BBoxDiagonal;
            const NoiseReport rd = add_noise(diagonal, o);
            EXPECT_EQ(rd.unit_length, diag) << what;
            EXPECT_EQ(rd.amplitude, 0.25 * diag) << what;
            // The same seed with the amplitude given in absolute units moves every vertex identically.
            o.unit = NoiseUnit::Absolute;
            o.amplitude = re.amplitude;
            const NoiseReport ra = add_noise(absolute_e, o);
            EXPECT_EQ(ra.unit_length, 1.0) << what;
            EXPECT_TRUE(bitwise_equal(edge, absolute_e)) << what;
            o.amplitude = rd.amplitude;
            add_noise(absolute_d, o);
            EXPECT_TRUE(bitwise_equal(diagonal, absolute_d)) << what;
            EXPECT_FALSE(bitwise_equal(edge, diagonal)) << what;
        }
}

TEST(Noise, RelativeUnitsFollowTheMeshScaleAbsoluteDoesNot)
{
    // Scaling by 4 (a power of two) is exact in floating point, so the noise
    // of the scaled mesh is exactly 4 times the noise of the original when the
    // unit scales with the mesh. With an absolute unit it is the same length,
    // up to the rounding of the positions (ulp(4) = 8.9e-16).
    const Mesh base = icosphere(3).mesh;
    Mesh big = base;
    for (auto& p : big.points) p *= 4.0;
    for (NoiseUnit unit : {NoiseUnit::MeanEdge, NoiseUnit::BBoxDiagonal, NoiseUnit::Absolute}) {
        Mesh a = base, b = big;
        NoiseOptions o = options(0.05, NoiseDirection::Random, NoiseDistribution::Gaussian, 11);
        o.unit = unit;
        const NoiseReport ra = add_noise(a, o);
        const NoiseReport rb = add_noise(b, o);
        const double factor = unit == NoiseUnit::Absolute ? 1.0 : 4.0;
        EXPECT_EQ(rb.amplitude, factor * ra.amplitude) << to_string(unit);
        for (std::size_t i = 0; i < base.n_vertices(); ++i) {
            const Vec3 db = b.points[i] - big.points[i], da = a.points[i] - base.points[i];
            if (unit == NoiseUnit::Absolute)
                ASSERT_LE((db - da).norm(), 1e-14) << "vertex " << i;
            else
                ASSERT_EQ(db, 4.0 * da) << to_string(unit) << " vertex " << i;
        }
    }
}

TEST(Noise, BoundaryVerticesStayUnlessMoveBoundary)
{
    for (const Mesh& open : {plane_grid(9, 9, 0.5).mesh, heightfield(17).mesh}) {
        const std::vector<char> boundary = boundary_vertex_mask(open);
        std::size_t n_boundary = 0;
        for (char b : boundary) n_boundary += b != 0;
        ASSERT_GT(n_boundary, 0u);
        for (auto dir : kDirections) {
            Mesh fixed = open, moving = open;
            NoiseOptions o = options(0.3, dir, NoiseDistribution::Uniform, 17);
            const NoiseReport rf = add_noise(fixed, o);
            o.move_boundary = true;
            const NoiseReport rm = add_noise(moving, o);
            EXPECT_EQ(rf.skipped_boundary, n_boundary);
            EXPECT_EQ(rf.moved, open.n_vertices() - n_boundary);
            EXPECT_EQ(rm.skipped(), 0u);
            EXPECT_EQ(rm.moved, open.n_vertices());
            for (std::size_t i = 0; i < open.n_vertices(); ++i) {
                if (boundary[i]) {
                    EXPECT_EQ(fixed.points[i], open.points[i]) << "boundary vertex " << i << " moved";
                    EXPECT_NE(moving.points[i], open.points[i]) << "boundary vertex " << i << " fixed";
                } else {
                    EXPECT_NE(fixed.points[i], open.points[i]) << "interior vertex " << i << " fixed";
                    // Skipping the boundary does not shift the other vertices' noise.
                    EXPECT_EQ(fixed.points[i], moving.points[i]) << "interior vertex " << i;
                }
            }
        }
    }
    // On the flat grid the normal is +z: interior vertices move along z only.
    Mesh plane = plane_grid(9, 9, 0.5).mesh;
    const Mesh flat = plane;
    const NoiseReport r = add_noise(plane, options(0.3));
    EXPECT_NEAR(r.mean_edge, reference_mean_edge(flat), 1e-12);
    for (std::size_t i = 0; i < plane.n_vertices(); ++i) {
        EXPECT_EQ(plane.points[i].x(), flat.points[i].x());
        EXPECT_EQ(plane.points[i].y(), flat.points[i].y());
        EXPECT_LE(std::abs(plane.points[i].z()), r.amplitude);
    }
}

TEST(Noise, VerticesWithoutNormalOrFaceStayAndAreCounted)
{
    // Two back-to-back triangles: their angle-weighted normals cancel, so none
    // of the three vertices has a normal; vertex 3 is in no face. No edge is a
    // boundary edge (each has exactly two faces).
    Mesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
    m.faces = {{0, 1, 2}, {0, 2, 1}};
    Mesh along_normal = m;
    const NoiseReport rn = add_noise(along_normal, options(0.5));
    EXPECT_EQ(rn.skipped_no_direction, 3u);
    EXPECT_EQ(rn.skipped_isolated, 1u);
    EXPECT_EQ(rn.skipped_boundary, 0u);
    EXPECT_EQ(rn.moved, 0u);
    EXPECT_TRUE(bitwise_equal(along_normal, m));

    Mesh random = m;
    const NoiseReport rr = add_noise(random, options(0.5, NoiseDirection::Random));
    EXPECT_EQ(rr.moved, 3u);
    EXPECT_EQ(rr.skipped_isolated, 1u);
    EXPECT_EQ(random.points[3], m.points[3]);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NE(random.points[i], m.points[i]);
}

TEST(Noise, IndependentOfTheThreadCount)
{
    const Mesh base = torus_irregular(2000, 1.0, 0.3, 4).mesh;
    const int saved = omp_get_max_threads();
    for (auto dir : kDirections)
        for (auto dist : kDistributions) {
            Mesh one = base, many = base;
            omp_set_num_threads(1);
            add_noise(one, options(0.5, dir, dist, 21));
            omp_set_num_threads(4);
            add_noise(many, options(0.5, dir, dist, 21));
            EXPECT_TRUE(bitwise_equal(one, many)) << label(options(0, dir, dist));
        }
    omp_set_num_threads(saved);
}

void expect_invalid(const NoiseOptions& o, const std::string& field)
{
    Mesh m = icosphere(1).mesh;
    const Mesh before = m;
    try {
        add_noise(m, o);
        ADD_FAILURE() << "no exception for " << field;
    } catch (const InvalidArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("noise"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(bitwise_equal(m, before)) << "a rejected call changed the mesh (" << field << ")";
}

TEST(Noise, InvalidOptionsThrowNamingTheField)
{
    expect_invalid(options(-0.1), "amplitude");
    expect_invalid(options(std::numeric_limits<double>::quiet_NaN()), "amplitude");
    expect_invalid(options(std::numeric_limits<double>::infinity()), "amplitude");
    NoiseOptions huge = options(1e308);
    huge.unit = NoiseUnit::BBoxDiagonal;  // diagonal 2 of the unit sphere: A overflows
    expect_invalid(huge, "amplitude");
    NoiseOptions o = options(0.1);
    o.unit = static_cast<NoiseUnit>(7);
    expect_invalid(o, "unit");
    o = options(0.1);
    o.direction = static_cast<NoiseDirection>(7);
    expect_invalid(o, "direction");
    o = options(0.1);
    o.distribution = static_cast<NoiseDistribution>(7);
    expect_invalid(o, "distribution");

    Mesh no_faces;
    no_faces.points = {{0, 0, 0}};
    EXPECT_THROW(add_noise(no_faces, options(0.1)), InvalidMeshError);
    Mesh bad_index = icosphere(0).mesh;
    bad_index.faces[0][1] = 99;
    EXPECT_THROW(add_noise(bad_index, options(0.1)), InvalidMeshError);
}

TEST(Noise, NamesRoundTrip)
{
    for (NoiseUnit u : {NoiseUnit::MeanEdge, NoiseUnit::BBoxDiagonal, NoiseUnit::Absolute})
        EXPECT_EQ(parse_enum<NoiseUnit>(to_string(u)), u);
    for (auto d : kDirections) EXPECT_EQ(parse_enum<NoiseDirection>(to_string(d)), d);
    for (auto d : kDistributions) EXPECT_EQ(parse_enum<NoiseDistribution>(to_string(d)), d);
    EXPECT_EQ(to_string(NoiseUnit::MeanEdge), "edge");
    EXPECT_EQ(to_string(NoiseUnit::BBoxDiagonal), "diagonal");
    EXPECT_THROW(parse_enum<NoiseUnit>("meters"), InvalidArgumentError);
    EXPECT_THROW(parse_enum<NoiseDirection>("up"), InvalidArgumentError);
    EXPECT_THROW(parse_enum<NoiseDistribution>("poisson"), InvalidArgumentError);
}

}  // namespace
}  // namespace meshdiff
