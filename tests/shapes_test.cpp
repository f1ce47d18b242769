#include "meshdiff/studies/shapes.h"
#include "meshdiff/core/topology.h"

#include "meshdiff/error.h"
#include "support/analytic.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>

namespace meshdiff {
namespace {

double signed_volume(const Mesh& m)
{
    double v = 0;
    for (const Face& f : m.faces)
        v += m.points[std::size_t(f[0])].dot(m.points[std::size_t(f[1])].cross(m.points[std::size_t(f[2])])) / 6.0;
    return v;
}

long euler_characteristic(const Mesh& m)
{
    const TopologyReport t = topology_report(m);
    return long(t.vertices) - long(t.edges) + long(t.faces);
}

std::map<std::size_t, std::size_t> valence_histogram(const Mesh& m, const std::vector<char>* skip = nullptr)
{
    const Adjacency adj = vertex_adjacency(m);
    std::map<std::size_t, std::size_t> h;
    for (std::size_t i = 0; i < adj.size(); ++i)
        if (!skip || !(*skip)[i]) ++h[adj.degree(i)];
    return h;
}

void expect_clean_closed(const Mesh& m, long euler)
{
    const TopologyReport t = topology_report(m);
    EXPECT_EQ(t.boundary_edges, 0u);
    EXPECT_EQ(t.non_manifold_edges, 0u);
    EXPECT_EQ(t.non_manifold_vertices, 0u);
    EXPECT_EQ(t.orientation_conflicts, 0u);
    EXPECT_EQ(t.degenerate_faces, 0u);
    EXPECT_EQ(t.duplicate_faces, 0u);
    EXPECT_EQ(t.components, 1u);
    EXPECT_EQ(euler_characteristic(m), euler);
    EXPECT_GT(signed_volume(m), 0.0);
}

// Every face's normal points away from the given centre-of-curvature direction.
template <class Inward>
void expect_faces_outward(const Mesh& m, Inward inward_point)
{
    std::size_t bad = 0;
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
        const Face& t = m.faces[f];
        const Vec3 c = (m.points[std::size_t(t[0])] + m.points[std::size_t(t[1])] + m.points[std::size_t(t[2])]) / 3;
        if (face_cross(m, f).dot(c - inward_point(c)) <= 0) ++bad;
    }
    EXPECT_EQ(bad, 0u);
}

// Torus: distance of p from the tube's centre circle, and cos v.
double torus_tube_distance(const Vec3& p, double R)
{
    const double rho = std::hypot(p.x(), p.y());
    return std::hypot(rho - R, p.z());
}

Vec3 torus_tube_centre(const Vec3& p, double R)
{
    const double rho = std::hypot(p.x(), p.y());
    return {R * p.x() / rho, R * p.y() / rho, 0.0};
}

double torus_cos_v(const Vec3& p, double R, double r)
{
    return (std::hypot(p.x(), p.y()) - R) / r;
}

TEST(Shapes, IcosphereVertexCountsFollowTenFourToTheKPlusTwo)
{
    const std::size_t expected[] = {12, 42, 162, 642, 2562, 10242};
    for (int k = 0; k <= 5; ++k) {
        const Shape s = icosphere(k);
        EXPECT_EQ(s.mesh.n_vertices(), expected[k]) << k;
        EXPECT_EQ(s.mesh.n_faces(), 20u << (2 * k)) << k;
        EXPECT_EQ(s.exact_H.size(), s.mesh.n_vertices());
    }
}

TEST(Shapes, IcosphereIsAClosedOutwardSphereWithValenceFiveAndSix)
{
    const double r = 2.5;
    const Shape s = icosphere(4, r);
    expect_clean_closed(s.mesh, 2);
    expect_faces_outward(s.mesh, [](const Vec3&) { return Vec3(0, 0, 0); });
    for (std::size_t i = 0; i < s.mesh.n_vertices(); ++i) {
        EXPECT_NEAR(s.mesh.points[i].norm(), r, 1e-14 * r);
        EXPECT_DOUBLE_EQ(s.exact_H[i], test::sphere_H(r));
    }
    const auto h = valence_histogram(s.mesh);
    ASSERT_EQ(h.size(), 2u);
    EXPECT_EQ(h.at(5), 12u);
    EXPECT_EQ(h.at(6), s.mesh.n_vertices() - 12);
    // Volume approaches 4/3 pi r^3 from below.
    const double ball = 4.0 / 3.0 * M_PI * r * r * r;
    EXPECT_LT(signed_volume(s.mesh), ball);
    EXPECT_GT(signed_volume(s.mesh), 0.98 * ball);
}

TEST(Shapes, GeodesicSphereHasTwentyFSquaredFacesValenceFiveAndSixAndMatchesTheIcosphere)
{
    for (int f : {1, 2, 3, 7, 20}) {
        const double r = 1.5;
        const Shape s = geodesic_sphere(f, r);
        SCOPED_TRACE(f);
        EXPECT_EQ(s.mesh.n_faces(), 20u * std::size_t(f * f));
        EXPECT_EQ(s.mesh.n_vertices(), 10u * std::size_t(f * f) + 2);
        expect_clean_closed(s.mesh, 2);
        expect_faces_outward(s.mesh, [](const Vec3&) { return Vec3(0, 0, 0); });
        double worst = 0;
        for (const auto& p : s.mesh.points) worst = std::max(worst, std::abs(p.norm() - r));
        EXPECT_LT(worst, 1e-14 * r);
        EXPECT_EQ(s.exact_H, std::vector<double>(s.mesh.n_vertices(), 1 / r));
        const auto h = valence_histogram(s.mesh);
        EXPECT_EQ(h.at(5), 12u);
        if (f > 1) {
            EXPECT_EQ(h.at(6), s.mesh.n_vertices() - 12);
        }
        // Central projection of the flat grid stretches the middle of each face: the
        // longest edge is at most 1.5 times the shortest (1.44 at f = 20).
        const Adjacency adj = vertex_adjacency(s.mesh);
        double lo = 1e300, hi = 0;
        for (std::size_t i = 0; i < adj.size(); ++i)
            for (auto j = adj.begin(i); j != adj.end(i); ++j) {
                const double e = (s.mesh.points[i] - s.mesh.points[*j]).norm();
                lo = std::min(lo, e);
                hi = std::max(hi, e);
            }
        EXPECT_LT(hi / lo, 1.5);
    }
    // Frequency 2 is one midpoint subdivision: the same point set as icosphere(1).
    auto sorted = [](std::vector<Vec3> p) {
        std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) {
            return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
        });
        return p;
    };
    const auto g = sorted(geodesic_sphere(2).mesh.points), ico = sorted(icosphere(1).mesh.points);
    ASSERT_EQ(g.size(), ico.size());
    for (std::size_t i = 0; i < g.size(); ++i) EXPECT_LT((g[i] - ico[i]).norm(), 1e-15) << i;
    // Stretching and noise work on it as on the icosphere.
    const Shape e = ellipsoid(geodesic_sphere(20).mesh, 1.5, 1, 1);
    EXPECT_EQ(e.mesh.n_faces(), 8000u);
    for (std::size_t i = 0; i < e.mesh.n_vertices(); ++i) {
        const Vec3& p = e.mesh.points[i];
        EXPECT_NEAR(p.x() * p.x() / 2.25 + p.y() * p.y() + p.z() * p.z(), 1.0, 1e-13);
    }
    const Shape n1 = noisy_sphere(geodesic_sphere(20), 0.02, 3), n2 = noisy_sphere(geodesic_sphere(20), 0.02, 3);
    EXPECT_EQ(n1.mesh.points, n2.mesh.points);
    EXPECT_NE(n1.mesh.points, geodesic_sphere(20).mesh.points);
    for (const auto& p : n1.mesh.points) EXPECT_NEAR(p.norm(), 1.0, 0.02 + 1e-15);
    EXPECT_THROW(geodesic_sphere(0), InvalidArgumentError);
    EXPECT_THROW(geodesic_sphere(2, -1), InvalidArgumentError);
}

TEST(Shapes, UvSphereHasSinglePolesAndIsClosed)
{
    const double r = 0.7;
    const Shape s = uv_sphere(24, 12, r);
    EXPECT_EQ(s.mesh.n_vertices(), 24u * 11u + 2u);
    EXPECT_EQ(s.mesh.n_faces(), 2u * 24u * 11u);
    expect_clean_closed(s.mesh, 2);
    expect_faces_outward(s.mesh, [](const Vec3&) { return Vec3(0, 0, 0); });
    for (std::size_t i = 0; i < s.mesh.n_vertices(); ++i) {
        EXPECT_NEAR(s.mesh.points[i].norm(), r, 1e-14);
        EXPECT_DOUBLE_EQ(s.exact_H[i], test::sphere_H(r));
    }
    const auto h = valence_histogram(s.mesh);
    EXPECT_EQ(h.at(24), 2u);  // the poles
}

TEST(Shapes, TorusIsClosedWithValenceSixAndExactH)
{
    const double R = 1.0, r = 0.25;
    const Shape s = torus(48, 16, R, r);
    EXPECT_EQ(s.mesh.n_vertices(), 48u * 16u);
    EXPECT_EQ(s.mesh.n_faces(), 2u * 48u * 16u);
    expect_clean_closed(s.mesh, 0);
    expect_faces_outward(s.mesh, [R](const Vec3& c) { return torus_tube_centre(c, R); });
    const auto h = valence_histogram(s.mesh);
    ASSERT_EQ(h.size(), 1u);
    EXPECT_EQ(h.begin()->first, 6u);
    double hmin = 1e9, hmax = -1e9;
    for (std::size_t i = 0; i < s.mesh.n_vertices(); ++i) {
        const Vec3& p = s.mesh.points[i];
        EXPECT_NEAR(torus_tube_distance(p, R), r, 1e-14);
        EXPECT_NEAR(s.exact_H[i], test::torus_H(R, r, torus_cos_v(p, R, r)), 1e-12);
        hmin = std::min(hmin, s.exact_H[i]);
        hmax = std::max(hmax, s.exact_H[i]);
    }
    EXPECT_NEAR(hmax, (R + 2 * r) / (2 * r * (R + r)), 1e-12);  // outer equator, v = 0
    EXPECT_NEAR(hmin, (R - 2 * r) / (2 * r * (R - r)), 1e-12);  // inner equator, v = pi (16 is even)
}

TEST(Shapes, TorusInnerEquatorIsNegativeWhenTubeIsFat)
{
    const Shape s = torus(32, 16, 1.0, 0.6);
    EXPECT_LT(*std::min_element(s.exact_H.begin(), s.exact_H.end()), 0.0);
}

TEST(Shapes, EllipsoidLiesOnItsSurfaceWithExactH)
{
    const double a = 1.5, b = 1.0, c = 0.8;
    const Shape s = ellipsoid(4, a, b, c);
    EXPECT_EQ(s.mesh.n_vertices(), 2562u);
    expect_clean_closed(s.mesh, 2);
    for (std::size_t i = 0; i < s.mesh.n_vertices(); ++i) {
        const Vec3& p = s.mesh.points[i];
        EXPECT_NEAR(p.x() * p.x() / (a * a) + p.y() * p.y() / (b * b) + p.z() * p.z() / (c * c), 1.0, 1e-14);
        EXPECT_NEAR(s.exact_H[i], test::ellipsoid_H(a, b, c, p), 1e-12 * s.exact_H[i]);
        EXPECT_GT(s.exact_H[i], 0.0);
    }
    // Axis tips of the icosphere (vertices 0..11 are not on the axes, so check
    // the range): H lies between the extreme values a/2 (1/b^2 + 1/c^2) and
    // c/2 (1/a^2 + 1/b^2).
    const auto [lo, hi] = std::minmax_element(s.exact_H.begin(), s.exact_H.end());
    EXPECT_LE(*hi, a / 2 * (1 / (b * b) + 1 / (c * c)) + 1e-12);
    EXPECT_GE(*lo, c / 2 * (1 / (a * a) + 1 / (b * b)) - 1e-12);
    // A sphere as the special case.
    const Shape sphere = ellipsoid(2, 2.0, 2.0, 2.0);
    for (double H : sphere.exact_H) EXPECT_NEAR(H, 0.5, 1e-13);
}

TEST(Shapes, PlaneGridHasInteriorValenceSixAndZeroH)
{
    const Shape s = plane_grid(7, 5, 0.5);
    EXPECT_EQ(s.mesh.n_vertices(), 35u);
    EXPECT_EQ(s.mesh.n_faces(), 2u * 6u * 4u);
    const TopologyReport t = topology_report(s.mesh);
    EXPECT_EQ(t.boundary_loops, 1u);
    EXPECT_EQ(t.orientation_conflicts, 0u);
    EXPECT_EQ(euler_characteristic(s.mesh), 1);
    for (std::size_t f = 0; f < s.mesh.n_faces(); ++f) EXPECT_GT(face_cross(s.mesh, f).z(), 0.0);
    const std::vector<char> boundary = boundary_vertex_mask(s.mesh);
    EXPECT_EQ(std::count(boundary.begin(), boundary.end(), 1), 2 * 7 + 2 * 5 - 4);
    const auto h = valence_histogram(s.mesh, &boundary);
    ASSERT_EQ(h.size(), 1u);
    EXPECT_EQ(h.begin()->first, 6u);
    for (double H : s.exact_H) EXPECT_EQ(H, 0.0);
    // Centred; index j * nx + i.
    const BoundingBox box = bounding_box(s.mesh);
    EXPECT_DOUBLE_EQ(box.min.x(), -1.5);
    EXPECT_DOUBLE_EQ(box.max.y(), 1.0);
    EXPECT_DOUBLE_EQ(s.mesh.points[7 * 2 + 3].x(), 0.0);
    EXPECT_DOUBLE_EQ(s.mesh.points[7 * 2 + 3].y(), 0.0);
    EXPECT_NEAR(surface_area(s.mesh), 3.0 * 2.0, 1e-12);
}

TEST(Shapes, NoisySphereStaysWithinTheNoiseBandAndIsSeeded)
{
    const double f = 0.05, r = 2.0;
    const Shape s = noisy_sphere(3, f, 7, r);
    const Shape clean = icosphere(3, r);
    ASSERT_EQ(s.mesh.n_vertices(), clean.mesh.n_vertices());
    EXPECT_EQ(s.mesh.faces, clean.mesh.faces);
    double lo = 1e9, hi = -1e9, mean = 0;
    for (std::size_t i = 0; i < s.mesh.n_vertices(); ++i) {
        const double e = s.mesh.points[i].norm() / r - 1;
        lo = std::min(lo, e);
        hi = std::max(hi, e);
        mean += e / double(s.mesh.n_vertices());
        // Radial only: same direction as the clean vertex.
        EXPECT_NEAR(s.mesh.points[i].normalized().dot(clean.mesh.points[i].normalized()), 1.0, 1e-14);
        EXPECT_DOUBLE_EQ(s.exact_H[i], 1.0 / r);
    }
    EXPECT_GE(lo, -f - 1e-14);
    EXPECT_LT(hi, f + 1e-14);
    EXPECT_LT(lo, -0.9 * f);  // the band is used (642 draws)
    EXPECT_GT(hi, 0.9 * f);
    EXPECT_NEAR(mean, 0.0, 0.01);
    expect_clean_closed(s.mesh, 2);

    const Shape again = noisy_sphere(3, f, 7, r);
    EXPECT_EQ(again.mesh.points, s.mesh.points);
    const Shape other = noisy_sphere(3, f, 8, r);
    EXPECT_NE(other.mesh.points, s.mesh.points);
    const Shape none = noisy_sphere(3, 0.0, 7, r);
    EXPECT_EQ(none.mesh.points, clean.mesh.points);
}

TEST(Shapes, IrregularTorusLiesOnTheSameTorusWithVariedValence)
{
    const double R = 1.0, r = 0.25;
    const Shape s = torus_irregular(3000, R, r, 42);
    EXPECT_NEAR(double(s.mesh.n_vertices()), 3000.0, 100.0);
    expect_clean_closed(s.mesh, 0);
    expect_faces_outward(s.mesh, [R](const Vec3& c) { return torus_tube_centre(c, R); });
    for (std::size_t i = 0; i < s.mesh.n_vertices(); ++i) {
        const Vec3& p = s.mesh.points[i];
        EXPECT_NEAR(torus_tube_distance(p, R), r, 1e-14);
        EXPECT_NEAR(s.exact_H[i], test::torus_H(R, r, torus_cos_v(p, R, r)), 1e-10);
    }
    const auto h = valence_histogram(s.mesh);
    EXPECT_GE(h.size(), 4u);  // valences 4..8 occur
    EXPECT_GT(h.at(6), 0u);
    EXPECT_EQ(h.begin()->first, 4u);
    EXPECT_EQ(h.rbegin()->first, 8u);
    // Edge lengths vary much more than on the regular torus of the same size.
    auto edge_cv = [](const Mesh& m) {
        const Adjacency adj = vertex_adjacency(m);
        double sum = 0, sum2 = 0, n = 0;
        for (std::size_t i = 0; i < adj.size(); ++i)
            for (auto j = adj.begin(i); j != adj.end(i); ++j) {
                const double l = (m.points[i] - m.points[*j]).norm();
                sum += l;
                sum2 += l * l;
                ++n;
            }
        const double mean = sum / n;
        return std::sqrt(sum2 / n - mean * mean) / mean;
    };
    const Shape regular = torus(110, 27, R, r);
    EXPECT_GT(edge_cv(s.mesh), 1.2 * edge_cv(regular.mesh));

    EXPECT_EQ(torus_irregular(3000, R, r, 42).mesh.points, s.mesh.points);
    EXPECT_EQ(torus_irregular(3000, R, r, 42).mesh.faces, s.mesh.faces);
    EXPECT_NE(torus_irregular(3000, R, r, 43).mesh.points, s.mesh.points);
}

// Mean curvature of a graph from finite differences of heightfield_z, as an
// independent check of the analytic derivatives.
double graph_H_by_differences(double x, double y, double amp)
{
    const double h = 1e-4;
    auto f = [amp](double u, double v) { return heightfield_z(u, v, amp); };
    const double fx = (f(x + h, y) - f(x - h, y)) / (2 * h);
    const double fy = (f(x, y + h) - f(x, y - h)) / (2 * h);
    const double fxx = (f(x + h, y) - 2 * f(x, y) + f(x - h, y)) / (h * h);
    const double fyy = (f(x, y + h) - 2 * f(x, y) + f(x, y - h)) / (h * h);
    const double fxy = (f(x + h, y + h) - f(x + h, y - h) - f(x - h, y + h) + f(x - h, y - h)) / (4 * h * h);
    const double w2 = 1 + fx * fx + fy * fy;
    return -((1 + fy * fy) * fxx - 2 * fx * fy * fxy + (1 + fx * fx) * fyy) / (2 * std::pow(w2, 1.5));
}

TEST(Shapes, HeightfieldHMatchesFiniteDifferencesOfItsHeight)
{
    const Shape s = heightfield(33, 1.0);
    EXPECT_EQ(s.mesh.n_vertices(), 33u * 33u);
    double hmin = 1e9, hmax = -1e9;
    for (std::size_t i = 0; i < s.mesh.n_vertices(); ++i) {
        const Vec3& p = s.mesh.points[i];
        EXPECT_DOUBLE_EQ(p.z(), heightfield_z(p.x(), p.y()));
        EXPECT_NEAR(s.exact_H[i], graph_H_by_differences(p.x(), p.y(), 1.0), 1e-5);
        hmin = std::min(hmin, s.exact_H[i]);
        hmax = std::max(hmax, s.exact_H[i]);
    }
    EXPECT_GT(hmax, 1.0);   // the bump (H about 0.3 / 0.35^2 at its top)
    EXPECT_LT(hmin, -1.0);  // the pit
    const BoundingBox box = bounding_box(s.mesh);
    EXPECT_DOUBLE_EQ(box.min.x(), -1.0);
    EXPECT_NEAR(box.max.y(), 1.0, 1e-15);
    for (std::size_t f = 0; f < s.mesh.n_faces(); ++f) EXPECT_GT(face_cross(s.mesh, f).z(), 0.0);
    // Amplitude 0 is the flat grid, and H scales sign with the amplitude.
    for (double H : heightfield(5, 0.0).exact_H) EXPECT_EQ(H, 0.0);
    EXPECT_NEAR(heightfield_H(0.3, 0.2, -1.0), -heightfield_H(0.3, 0.2, 1.0), 1e-15);
    EXPECT_NEAR(heightfield_H(0.3, 0.2, 1.0), graph_H_by_differences(0.3, 0.2, 1.0), 1e-5);
}

TEST(Shapes, IrregularHeightfieldSamplesTheSameFunctionOnTheSameSquare)
{
    const Shape s = heightfield_irregular(1000, 5, 1.0);
    EXPECT_NEAR(double(s.mesh.n_vertices()), 1000.0, 70.0);
    const TopologyReport t = topology_report(s.mesh);
    EXPECT_EQ(t.boundary_loops, 1u);
    EXPECT_EQ(t.orientation_conflicts, 0u);
    EXPECT_EQ(t.degenerate_faces, 0u);
    EXPECT_EQ(euler_characteristic(s.mesh), 1);
    for (std::size_t f = 0; f < s.mesh.n_faces(); ++f) {
        const Face& tri = s.mesh.faces[f];
        const Vec3 a = s.mesh.points[std::size_t(tri[0])], b = s.mesh.points[std::size_t(tri[1])],
                   c = s.mesh.points[std::size_t(tri[2])];
        // Counter-clockwise in the xy plane.
        EXPECT_GT((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()), 0.0);
    }
    for (std::size_t i = 0; i < s.mesh.n_vertices(); ++i) {
        const Vec3& p = s.mesh.points[i];
        EXPECT_EQ(p.z(), heightfield_z(p.x(), p.y()));
        EXPECT_EQ(s.exact_H[i], heightfield_H(p.x(), p.y()));
        EXPECT_LE(std::abs(p.x()), 1.0);
        EXPECT_LE(std::abs(p.y()), 1.0);
    }
    const BoundingBox box = bounding_box(s.mesh);
    EXPECT_EQ(box.min.x(), -1.0);
    EXPECT_EQ(box.max.x(), 1.0);
    EXPECT_NEAR(surface_area(s.mesh), surface_area(heightfield(32).mesh), 0.01);
    EXPECT_EQ(heightfield_irregular(1000, 5).mesh.points, s.mesh.points);
    EXPECT_NE(heightfield_irregular(1000, 6).mesh.points, s.mesh.points);
}

TEST(Shapes, InvalidArgumentsThrowNamingTheField)
{
    auto message = [](auto&& f) {
        try {
            f();
        } catch (const InvalidArgumentError& e) {
            return std::string(e.what());
        }
        return std::string("no throw");
    };
    EXPECT_NE(message([] { icosphere(-1); }).find("subdivisions"), std::string::npos);
    EXPECT_NE(message([] { icosphere(9); }).find("subdivisions"), std::string::npos);
    EXPECT_NE(message([] { icosphere(1, 0.0); }).find("radius"), std::string::npos);
    EXPECT_NE(message([] { uv_sphere(2, 5); }).find("n_longitude"), std::string::npos);
    EXPECT_NE(message([] { torus(10, 10, 0.2, 0.3); }).find("r"), std::string::npos);
    EXPECT_NE(message([] { torus(2, 10); }).find("n_major"), std::string::npos);
    EXPECT_NE(message([] { ellipsoid(2, 1, -1, 1); }).find("b"), std::string::npos);
    EXPECT_NE(message([] { plane_grid(1, 4); }).find("nx"), std::string::npos);
    EXPECT_NE(message([] { noisy_sphere(2, 1.5, 1); }).find("noise_fraction"), std::string::npos);
    EXPECT_NE(message([] { noisy_sphere(2, std::nan(""), 1); }).find("noise_fraction"), std::string::npos);
    EXPECT_NE(message([] { torus_irregular(5, 1, 0.25, 1); }).find("approx_vertices"), std::string::npos);
    EXPECT_NE(message([] { heightfield(1); }).find("n"), std::string::npos);
    EXPECT_NE(message([] { heightfield(4, INFINITY); }).find("amplitude"), std::string::npos);
}

}  // namespace
}  // namespace meshdiff
