#include "meshdiff/distance/signed_distance.h"

#include "meshdiff/compare.h"
#include "meshdiff/core/topology.h"
#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"
#include "meshdiff/studies/shapes.h"

#include "distance/hausdorff_bounds.h"
#include "distance/signed_query.h"

#include <fmt/format.h>

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace meshdiff;

namespace {

const std::string kData = MESHDIFF_TEST_DATA_DIR;

// The axis-aligned cube [lo, hi]^3, 12 triangles, counter-clockwise seen from outside.
Mesh cube(double lo, double hi)
{
    Mesh m;
    for (int i = 0; i < 8; ++i) m.points.emplace_back(i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo);
    m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
               {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

Mesh flipped(Mesh m)
{
    for (Face& f : m.faces) std::swap(f[1], f[2]);
    return m;
}

// Distance of p to the solid box [lo, hi]^3 from outside (0 inside).
double outside_box(const Vec3& p, double lo, double hi)
{
    Vec3 d;
    for (int k = 0; k < 3; ++k) d[k] = std::max({0.0, lo - p[k], p[k] - hi});
    return d.norm();
}

// Distance of p inside [lo, hi]^3 to the box's surface.
double inside_box(const Vec3& p, double lo, double hi)
{
    double d = INFINITY;
    for (int k = 0; k < 3; ++k) d = std::min({d, p[k] - lo, hi - p[k]});
    return d;
}

// The sign of a face normal of face f: the naive method.
int face_normal_sign(const Mesh& m, const Vec3& p, std::uint32_t f)
{
    const Face& t = m.faces[f];
    const Vec3 c = closest_point_on_triangle(p, m.points[std::size_t(t[0])], m.points[std::size_t(t[1])],
                                             m.points[std::size_t(t[2])])
                       .point;
    const double s = (p - c).dot(face_cross(m, f));
    return s > 0 ? 1 : (s < 0 ? -1 : 0);
}

}  // namespace

TEST(SignedDistance, ClosestFeatureMatchesClosestPointBitForBit)
{
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.3, 0.8, 0.1);
    const Vec3 thin_c(2, 1e-12, 0);  // a thin triangle: the union of its edges
    int kinds[3] = {0, 0, 0};
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p(u(rng), u(rng), u(rng));
        for (const Vec3* cc : {&c, &thin_c}) {
            const ClosestFeature f = closest_feature(p, a, b, *cc);
            const Vec3 q = closest_point_on_triangle(p, a, b, *cc).point;
            EXPECT_EQ(f.point, q);
            ++kinds[int(f.kind)];
            if (f.kind == FeatureKind::Vertex) {
                EXPECT_EQ(f.point, (std::array<Vec3, 3>{a, b, *cc}[f.index]));
            }
        }
    }
    EXPECT_GT(kinds[0], 100);
    EXPECT_GT(kinds[1], 100);
    EXPECT_GT(kinds[2], 20);
    // Regions of the regular triangle: the projection inside, beyond an edge, beyond a corner.
    EXPECT_EQ(closest_feature(Vec3(0.3, 0.3, 1), a, b, c).kind, FeatureKind::Interior);
    const ClosestFeature e = closest_feature(Vec3(0.5, -1, 0), a, b, c);
    EXPECT_EQ(e.kind, FeatureKind::Edge);
    EXPECT_EQ(e.index, 0);
    const ClosestFeature v = closest_feature(Vec3(2, -1, 0), a, b, c);
    EXPECT_EQ(v.kind, FeatureKind::Vertex);
    EXPECT_EQ(v.index, 1);
}

// The unit cube against the cube scaled by 1.1 about its centre: every sample
// has a closed-form signed distance.
TEST(SignedDistance, CubeAgainstScaledCubeClosedForm)
{
    const Mesh small = cube(0.0, 1.0);
    const Mesh big = cube(-0.05, 1.05);
    SamplingOptions o;
    o.samples = 3000;
    const SampledSurfaceDistance r = surface_distance_samples(big, small, o);
    ASSERT_EQ(r.forward.signed_distances.size(), r.forward.samples.size());
    ASSERT_EQ(r.backward.signed_distances.size(), r.backward.samples.size());
    // Forward: samples on the big cube, all outside the small one.
    for (std::size_t i = 0; i < r.forward.samples.size(); ++i) {
        const Vec3& p = r.forward.samples.points[i];
        EXPECT_NEAR(r.forward.signed_distances[i], outside_box(p, 0.0, 1.0), 1e-14);
        EXPECT_GT(r.forward.signed_distances[i], 0.0);
        if (r.forward.samples.kind[i] == SampleKind::OnVertex) {  // a corner: to the small cube's corner
            EXPECT_NEAR(r.forward.signed_distances[i], std::sqrt(3.0) * 0.05, 1e-15);
        }
    }
    // Backward: samples on the small cube, all inside the big one.
    for (std::size_t i = 0; i < r.backward.samples.size(); ++i) {
        const Vec3& p = r.backward.samples.points[i];
        EXPECT_NEAR(r.backward.signed_distances[i], -inside_box(p, -0.05, 1.05), 1e-14);
        EXPECT_LT(r.backward.signed_distances[i], 0.0);
        if (r.backward.samples.kind[i] == SampleKind::OnVertex) {
            EXPECT_NEAR(r.backward.signed_distances[i], -0.05, 1e-15);
        }
    }
    const DistanceStats& f = r.distance.forward;
    const DistanceStats& b = r.distance.backward;
    ASSERT_TRUE(f.signed_distance && b.signed_distance);
    EXPECT_TRUE(f.signed_unavailable.empty());
    EXPECT_FALSE(f.signed_distance->flipped);
    // All positive forward, all negative backward: the signed statistics are
    // the unsigned ones, negated backward (same sums in the same order).
    EXPECT_EQ(f.signed_distance->min, f.min);
    EXPECT_EQ(f.signed_distance->max, f.max);
    EXPECT_EQ(f.signed_distance->mean, f.mean);
    EXPECT_EQ(f.signed_distance->rms, f.rms);
    EXPECT_EQ(b.signed_distance->min, -b.max);
    EXPECT_EQ(b.signed_distance->max, -b.min);
    EXPECT_EQ(b.signed_distance->mean, -b.mean);
    EXPECT_EQ(b.signed_distance->rms, b.rms);
    EXPECT_NEAR(f.signed_distance->max, std::sqrt(3.0) * 0.05, 1e-15);
    EXPECT_NEAR(f.signed_distance->min, 0.05, 1e-15);
    EXPECT_NEAR(b.signed_distance->min, -0.05, 1e-15);  // vertices and edges of the small cube
    EXPECT_NEAR(b.signed_distance->max, -b.min, 0.0);
}

TEST(SignedDistance, InwardOrientedCubeIsFlipped)
{
    const Mesh small = flipped(cube(0.0, 1.0));
    const Mesh big = cube(-0.05, 1.05);
    std::string why;
    const auto n = pseudo_normals(small, "the small cube", &why);
    ASSERT_TRUE(n) << why;
    EXPECT_TRUE(n->flipped);
    EXPECT_NEAR(n->volume, -1.0, 1e-15);
    SamplingOptions o;
    o.samples = 2000;
    const SampledSurfaceDistance r = surface_distance_samples(big, small, o);
    ASSERT_TRUE(r.distance.forward.signed_distance);
    EXPECT_TRUE(r.distance.forward.signed_distance->flipped);
    EXPECT_FALSE(r.distance.backward.signed_distance->flipped);
    for (std::size_t i = 0; i < r.forward.samples.size(); ++i)
        EXPECT_NEAR(r.forward.signed_distances[i], outside_box(r.forward.samples.points[i], 0.0, 1.0), 1e-14);
    const std::string j = surface_distance_json(r.distance, o).dump();
    EXPECT_NE(j.find("\"orientation\":\"flipped to outward\""), std::string::npos);
}

TEST(SignedDistance, SphereInsideAndOutside)
{
    const Mesh unit = icosphere(3).mesh;
    for (const double radius : {0.5, 2.0}) {
        const Mesh other = icosphere(2, radius).mesh;
        SamplingOptions o;
        o.samples = 5000;
        const SampledSurfaceDistance r = surface_distance_samples(other, unit, o);
        const double sign = radius < 1.0 ? -1.0 : 1.0;
        for (std::size_t i = 0; i < r.forward.samples.size(); ++i)
            EXPECT_EQ(r.forward.signed_distances[i], sign * r.forward.distances[i]);
        // Backward: the unit sphere is outside the small one, inside the big one.
        for (std::size_t i = 0; i < r.backward.samples.size(); ++i)
            EXPECT_EQ(r.backward.signed_distances[i], -sign * r.backward.distances[i]);
        ASSERT_TRUE(r.distance.forward.signed_distance);
        EXPECT_EQ(r.distance.forward.signed_distance->mean, sign * r.distance.forward.mean);
        // Closed form at the vertices of the other sphere: |radius - 1| up to the chord sag of the unit mesh.
        for (std::size_t i = 0; i < r.forward.samples.n_vertex; ++i)
            EXPECT_NEAR(r.forward.signed_distances[i], radius - 1.0, 0.01);
    }
}

TEST(SignedDistance, OpenMeshGivesNullWithReason)
{
    const LoadedMesh hemi = read_mesh(kData + "/hemisphere.ply");
    const Mesh sphere = icosphere(2).mesh;
    const SurfaceDistance d = surface_distance(sphere, hemi.mesh);
    EXPECT_FALSE(d.forward.signed_distance);
    EXPECT_NE(d.forward.signed_unavailable.find("the processed mesh has "), std::string::npos)
        << d.forward.signed_unavailable;
    EXPECT_NE(d.forward.signed_unavailable.find(" boundary edges"), std::string::npos) << d.forward.signed_unavailable;
    ASSERT_TRUE(d.backward.signed_distance);  // the sphere is closed
    EXPECT_TRUE(d.backward.signed_unavailable.empty());
    const nlohmann::json j = surface_distance_json(d, {});
    EXPECT_EQ(j["sign"], "positive outside");
    EXPECT_TRUE(j["forward"]["signed"].is_null());
    EXPECT_EQ(j["forward"]["signed_unavailable"], d.forward.signed_unavailable);
    EXPECT_TRUE(j["backward"]["signed_unavailable"].is_null());
    EXPECT_EQ(j["backward"]["signed"]["min"], d.backward.signed_distance->min);
    EXPECT_EQ(j["backward"]["signed"]["orientation"], "outward as given");
    // The reason counts what topology_report() counts.
    const std::size_t boundary = topology_report(hemi.mesh).boundary_edges;
    ASSERT_GT(boundary, 0u);
    EXPECT_NE(d.forward.signed_unavailable.find(fmt::format("has {} boundary edges", boundary)), std::string::npos);
}

TEST(SignedDistance, ReasonsNameTheCondition)
{
    Mesh open = cube(0, 1);
    open.faces.pop_back();
    EXPECT_EQ(sign_unavailable_reason(open, "the original mesh").rfind("the original mesh has 3 boundary edges", 0),
              0u);
    Mesh twisted = cube(0, 1);
    std::swap(twisted.faces[0][1], twisted.faces[0][2]);
    EXPECT_NE(sign_unavailable_reason(twisted, "M").find("3 edges with inconsistent orientation"), std::string::npos);
    Mesh degenerate = cube(0, 1);
    degenerate.points.emplace_back(0.5, 0.0, 0.0);  // on edge 0-1: split face {0, 1, 4}... as a zero-area sliver
    degenerate.faces[4] = {0, 8, 4};
    degenerate.faces.push_back({8, 1, 4});
    degenerate.faces.push_back({0, 1, 8});  // zero area, closes the hole in face {0, 2, 1}'s edge 0-1
    const std::string why = sign_unavailable_reason(degenerate, "M");
    EXPECT_NE(why.find("degenerate face"), std::string::npos) << why;
    EXPECT_TRUE(sign_unavailable_reason(cube(0, 1), "M").empty());
    std::string reason;
    EXPECT_FALSE(pseudo_normals(open, "the original mesh", &reason));
    EXPECT_EQ(reason, sign_unavailable_reason(open, "the original mesh"));
}

// Baerentzen and Aanaes's failure case: at a sharp edge the two faces tie, and
// the normal of one of them gives the wrong sign; the pseudo-normal of the
// edge is right whichever face the index returns.
TEST(SignedDistance, SharpEdgeWherePseudoNormalIsRightAndFaceNormalWrong)
{
    // A tetrahedron with a knife edge A-B (dihedral angle about 5.7 degrees).
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0.05, 0.5), Vec3(1, -0.05, 0.5)};
    m.faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    std::string why;
    const auto n = pseudo_normals(m, "M", &why);
    ASSERT_TRUE(n) << why;
    ASSERT_FALSE(n->flipped);
    ASSERT_GT(winding_number(m, Vec3(0.5, 0, 0.5)), 0.99);  // outward as built
    // p beyond the edge, closer to face 1's normal than to face 0's.
    const Vec3 p = Vec3(0, 0, 0.5) + 0.01 * Vec3(-0.2, -1.0, 0.0);
    EXPECT_LT(std::abs(winding_number(m, p)), 1e-9);  // outside
    const ClosestPoint c = closest_point_brute_force(m, p);
    for (std::uint32_t f : {0u, 1u}) {
        const Face& t = m.faces[f];
        const ClosestFeature cf =
            closest_feature(p, m.points[std::size_t(t[0])], m.points[std::size_t(t[1])], m.points[std::size_t(t[2])]);
        EXPECT_EQ(cf.kind, FeatureKind::Edge);
        EXPECT_NEAR((p - cf.point).norm(), c.distance, 1e-15);  // both faces tie
        EXPECT_EQ(distance_sign(m, *n, p, f), 1);
    }
    EXPECT_EQ(face_normal_sign(m, p, 0), -1);  // the naive sign with face 0: wrong
    EXPECT_EQ(face_normal_sign(m, p, 1), 1);
    // And inside, near the edge: the face region, right with either.
    const Vec3 q(0.02, 0, 0.5);
    const ClosestPoint cq = closest_point_brute_force(m, q);
    EXPECT_EQ(distance_sign(m, *n, q, cq.face), -1);
}

// The same at a sharp vertex: the apex of a needle-like cone, a point in the
// apex's region on the side of one face.
TEST(SignedDistance, SharpVertexWherePseudoNormalIsRightAndFaceNormalWrong)
{
    // A square pyramid with apex (0, 0, 10) over the base [-1, 1]^2 at z = 0, and a point
    // above and beside the apex. Outward faces.
    Mesh m;
    m.points = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(0, 0, 10)};
    m.faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 2, 1}, {0, 3, 2}};
    std::string why;
    const auto n = pseudo_normals(m, "M", &why);
    ASSERT_TRUE(n) << why;
    ASSERT_FALSE(n->flipped);
    int naive_wrong = 0, vertex_cases = 0;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 4000; ++i) {
        const Vec3 p = Vec3(0, 0, 10) + 0.5 * Vec3(u(rng), u(rng), u(rng));
        const ClosestPoint c = closest_point_brute_force(m, p);
        if (c.distance < 1e-3) continue;
        const bool inside = winding_number(m, p) > 0.5;
        // Every face at the minimum distance (ties at the apex): the pseudo-normal sign is right for each.
        for (std::uint32_t f = 0; f < 4; ++f) {
            const Face& t = m.faces[f];
            const ClosestFeature cf = closest_feature(p, m.points[std::size_t(t[0])], m.points[std::size_t(t[1])],
                                                      m.points[std::size_t(t[2])]);
            if ((p - cf.point).norm() > c.distance * (1 + 1e-12)) continue;
            EXPECT_EQ(distance_sign(m, *n, p, f), inside ? -1 : 1) << p.transpose();
            if (cf.kind == FeatureKind::Vertex) {
                ++vertex_cases;
                if (face_normal_sign(m, p, f) != (inside ? -1 : 1)) ++naive_wrong;
            }
        }
    }
    EXPECT_GT(vertex_cases, 100);
    EXPECT_GT(naive_wrong, 10);  // the failure case occurs, and the pseudo-normal handles it
}

// Brute force: the sign against the winding number on random points not too
// near the surface, on closed meshes of the test data and a flipped copy.
TEST(SignedDistance, SignAgreesWithWindingNumber)
{
    std::vector<Mesh> meshes = {read_mesh(kData + "/fandisk.ply").mesh, read_mesh(kData + "/torus_R1_r025.ply").mesh,
                                read_mesh(kData + "/sphere_irregular_3072.ply").mesh};
    meshes.push_back(flipped(meshes[1]));
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const Mesh& m = meshes[k];
        std::string why;
        const auto n = pseudo_normals(m, "M", &why);
        ASSERT_TRUE(n) << k << ": " << why;
        EXPECT_EQ(n->flipped, k == 3);
        const ClosestPointIndex index(m);
        const BoundingBox box = bounding_box(m);
        const double diag = box.diagonal();
        std::mt19937_64 rng(k + 1);
        std::uniform_real_distribution<double> u(-0.1, 1.1);
        std::vector<Vec3> q;
        while (q.size() < 400) {
            const Vec3 t(u(rng), u(rng), u(rng));
            const Vec3 p = box.min + t.cwiseProduct(box.max - box.min);
            if (index.closest_point(p).distance > 1e-3 * diag) q.push_back(p);
        }
        std::vector<double> d(q.size());
        std::vector<std::int8_t> signs(q.size());
        signed_query(m, index, *n, q.data(), q.size(), d.data(), signs.data());
        EXPECT_EQ(d, index.distances(q));  // bit for bit the unsigned query
        // The same signs from the closest faces of closest_points().
        std::vector<std::uint32_t> faces;
        for (const ClosestPoint& c : index.closest_points(q)) faces.push_back(c.face);
        const std::vector<double> s = signed_distances(m, *n, q.data(), d.data(), faces.data(), q.size());
        for (std::size_t i = 0; i < q.size(); ++i) EXPECT_EQ(s[i], signs[i] * d[i]);
        int inside = 0;
        for (std::size_t i = 0; i < q.size(); ++i) {
            double w = winding_number(m, q[i]);
            if (k == 3) w = -w;
            ASSERT_LT(std::min(std::abs(w), std::abs(w - 1.0)), 1e-6) << "winding number " << w;
            const bool in = w > 0.5;
            inside += in;
            EXPECT_EQ(s[i], in ? -d[i] : d[i]) << k << " " << q[i].transpose();
        }
        EXPECT_GT(inside, 20) << k;
        EXPECT_GT(int(q.size()) - inside, 20) << k;
    }
}

TEST(SignedDistance, OnTheSurfaceIsZero)
{
    const Mesh m = cube(0, 1);
    const auto n = pseudo_normals(m);
    ASSERT_TRUE(n);
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(0.3, 0.4, 1.0)}) {
        const ClosestPoint c = closest_point_brute_force(m, p);
        EXPECT_EQ(c.distance, 0.0);
        EXPECT_EQ(distance_sign(m, *n, p, c.face), 0);
    }
    // A mesh against itself: every signed distance is 0 at the vertices.
    const SampledSurfaceDistance r = surface_distance_samples(m, m);
    for (std::size_t i = 0; i < r.forward.samples.n_vertex; ++i) EXPECT_EQ(r.forward.signed_distances[i], 0.0);
}

TEST(SignedDistance, UnsignedNumbersUnchangedAndVertexDistances)
{
    // With and without a signable target the unsigned numbers are those of the
    // distances alone: compare with one_sided_distance() (no sign computed).
    const Mesh a = icosphere(2, 1.1).mesh;
    const Mesh b = icosphere(3).mesh;
    SamplingOptions o;
    o.samples = 4000;
    const SurfaceDistance d = surface_distance(a, b, o, true, HausdorffOptions{});
    ASSERT_TRUE(d.forward_hausdorff);
    const DistanceStats f = one_sided_distance(a, ClosestPointIndex(b), o);
    EXPECT_EQ(d.forward.mean, f.mean);
    EXPECT_EQ(d.forward.max, f.max);
    EXPECT_EQ(d.forward.p95, f.p95);
    ASSERT_EQ(d.a_vertex_signed_distance.size(), a.n_vertices());
    ASSERT_EQ(d.b_vertex_signed_distance.size(), b.n_vertices());
    for (std::size_t v = 0; v < a.n_vertices(); ++v) EXPECT_EQ(d.a_vertex_signed_distance[v], d.a_vertex_distance[v]);
    for (std::size_t v = 0; v < b.n_vertices(); ++v) EXPECT_EQ(d.b_vertex_signed_distance[v], -d.b_vertex_distance[v]);
    // The same from the sampled-only path (no certification) and the standalone function.
    const SurfaceDistance s = surface_distance(a, b, o, true, std::nullopt);
    EXPECT_EQ(s.a_vertex_signed_distance, d.a_vertex_signed_distance);
    std::vector<double> sd;
    const std::vector<double> vd = vertex_distances(a, b, ClosestPointIndex(b), sd, "B");
    EXPECT_EQ(vd, d.a_vertex_distance);
    EXPECT_EQ(sd, d.a_vertex_signed_distance);
    // Not signable: no signed vertex distances.
    const LoadedMesh hemi = read_mesh(kData + "/hemisphere.ply");
    const std::vector<double> open = vertex_distances(a, hemi.mesh, ClosestPointIndex(hemi.mesh), sd, "H");
    EXPECT_EQ(open.size(), a.n_vertices());
    EXPECT_TRUE(sd.empty());
}

TEST(SignedDistance, TextReportLine)
{
    const LoadedMesh hemi = read_mesh(kData + "/hemisphere.ply");
    LoadedMesh sphere;
    sphere.mesh = icosphere(2).mesh;
    sphere.input.path = "sphere";
    CompareOptions o;
    o.roughness = false;
    o.hausdorff = std::nullopt;
    const Comparison c = compare_meshes(sphere, hemi, o);
    const std::string t = comparison_text(c);
    EXPECT_NE(t.find("  signed: unavailable, the processed mesh has "), std::string::npos) << t;
    EXPECT_NE(
        t.find(fmt::format("  signed (positive outside M1): min {:.6g}, max {:.6g}, mean {:.6g}, RMS {:.6g}\n",
                           c.distance->backward.signed_distance->min, c.distance->backward.signed_distance->max,
                           c.distance->backward.signed_distance->mean, c.distance->backward.signed_distance->rms)),
        std::string::npos)
        << t;
}

// A closed double cone whose two apexes have valence 200,000: the checks and
// the pseudo-normals cost O(valence) there, not O(valence^2) (this test would
// not finish otherwise), and the signs are right.
TEST(SignedDistance, HubVerticesOfAClosedDoubleCone)
{
    constexpr int n = 200000;
    Mesh m;
    m.points.emplace_back(0, 0, 1);
    m.points.emplace_back(0, 0, -1);
    for (int i = 0; i < n; ++i) {
        const double a = 2 * 3.14159265358979323846 * i / n;
        m.points.emplace_back(std::cos(a), std::sin(a), 0.0);
    }
    for (int i = 0; i < n; ++i) {
        const int p = 2 + i, q = 2 + (i + 1) % n;
        m.faces.push_back({0, p, q});
        m.faces.push_back({1, q, p});
    }
    std::string why;
    const auto normals = pseudo_normals(m, "the cone", &why);
    ASSERT_TRUE(normals) << why;
    EXPECT_FALSE(normals->flipped);
    const ClosestPointIndex index(m);
    for (const auto& [p, sign] : {std::pair{Vec3(0, 0, 1.5), 1},
                                  {Vec3(0, 0, -1.2), 1},
                                  {Vec3(0.1, 0.2, 0.3), -1},
                                  {Vec3(2, 0, 0), 1},
                                  {Vec3(0, 0, 0.9), -1}}) {
        const ClosestPoint c = index.closest_point(p);
        EXPECT_EQ(distance_sign(m, *normals, p, c.face), sign) << p.transpose();
    }
    // Glue a third cone sheet on the apex: a non-manifold vertex, named.
    Mesh pinched = m;
    const auto base = std::int32_t(pinched.points.size());
    pinched.points.emplace_back(0, 0, 2);
    pinched.points.emplace_back(1, 0, 2);
    pinched.points.emplace_back(0, 1, 2);
    pinched.points.emplace_back(0, 0, 3);
    pinched.faces.push_back({0, base + 1, base + 2});
    pinched.faces.push_back({0, base + 2, base + 3});
    pinched.faces.push_back({0, base + 3, base + 1});
    pinched.faces.push_back({base + 1, base + 3, base + 2});
    EXPECT_NE(sign_unavailable_reason(pinched, "M").find("has 1 non-manifold vertex"), std::string::npos)
        << sign_unavailable_reason(pinched, "M");
}

// Regression (issue 27's shared edge table): a face with a repeated corner, passed as arrays (the readers drop
// it), made the sign check count a non-manifold edge twice when the corner's vertex had the lower degree; the
// reason now gives topology_report()'s counts.
TEST(SignAvailability, CollapsedCornerFacesCountTheirEdgesAsTheTopologyReportDoes)
{
    const Mesh sphere = icosphere(1).mesh;
    const Face f = sphere.faces[0];  // each extra face lies on an edge of face 0: that edge gets 4 half-edges
    for (const Face extra : {Face{f[0], f[0], f[1]}, Face{f[1], f[0], f[0]}, Face{f[2], f[2], f[0]}}) {
        Mesh m = sphere;
        m.faces.push_back(extra);
        const TopologyReport t = topology_report(m);
        EXPECT_GT(t.non_manifold_edges, 0u);
        const std::string reason = sign_unavailable_reason(m, "M");
        ASSERT_FALSE(reason.empty());
        if (t.non_manifold_edges) {
            EXPECT_NE(reason.find(fmt::format("{} non-manifold edge", t.non_manifold_edges)), std::string::npos)
                << reason;
        } else {
            EXPECT_EQ(reason.find("non-manifold edge"), std::string::npos) << reason;
        }
        if (t.boundary_edges) {
            EXPECT_NE(reason.find(fmt::format("{} boundary edge", t.boundary_edges)), std::string::npos) << reason;
        }
    }
}

// The pseudo-normals are made one face, then one vertex, at a time in
// parallel; each vertex's sum is the loop over the faces' (in face order).
TEST(PseudoNormals, EqualTheLoopOverTheFacesBitForBitAtAnyThreadCount)
{
    for (const char* name : {"fandisk.ply", "torus_R1_r025.ply", "sphere_irregular_3072.ply"}) {
        const Mesh m = read_mesh(kData + "/" + name).mesh;
        // The reference: the loop over the faces and their corners.
        std::vector<Vec3> face(m.n_faces()), vertex(m.n_vertices(), Vec3::Zero());
        const auto reference = pseudo_normals(m, "M");
        ASSERT_TRUE(reference) << name;
        const double s = reference->flipped ? -1.0 : 1.0;
        for (std::size_t f = 0; f < m.n_faces(); ++f) face[f] = s * face_cross(m, f).normalized();
        for (std::size_t f = 0; f < m.n_faces(); ++f)
            for (std::size_t k = 0; k < 3; ++k) {
                const Vec3& p = m.points[std::size_t(m.faces[f][k])];
                const Vec3 u = m.points[std::size_t(m.faces[f][(k + 1) % 3])] - p;
                const Vec3 v = m.points[std::size_t(m.faces[f][(k + 2) % 3])] - p;
                vertex[std::size_t(m.faces[f][k])] += std::atan2(u.cross(v).norm(), u.dot(v)) * face[f];
            }
        const int threads = omp_get_max_threads();
        for (const int t : {1, 3}) {
            omp_set_num_threads(t);
            const auto n = pseudo_normals(m, "M");
            ASSERT_TRUE(n);
            EXPECT_EQ(n->face, face) << name << " at " << t << " threads";
            EXPECT_EQ(n->vertex, vertex) << name << " at " << t << " threads";
        }
        omp_set_num_threads(threads);
    }
}

TEST(PseudoNormals, SignsWithTheFaceNormalsLeftOutAreTheSame)
{
    // The surface distance drops PseudoNormals::face once the vertex normals
    // are made; the signs then make each face normal from the corners (the
    // index's copy in signed_query(), the mesh's in distance_sign()). Points
    // near the corners and edge midpoints (closest to a corner or an edge,
    // where the neighbour's normal across the edge is read too) and in the
    // box, on sharp (fandisk), smooth and inward-oriented (flipped) meshes:
    // the same signs as from the stored normals, every one.
    std::vector<Mesh> meshes = {read_mesh(kData + "/fandisk.ply").mesh, read_mesh(kData + "/torus_R1_r025.ply").mesh};
    meshes.push_back(flipped(meshes[1]));
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const Mesh& m = meshes[k];
        const auto kept = pseudo_normals(m, "M");
        ASSERT_TRUE(kept) << k;
        PseudoNormals left_out = *kept;
        left_out.face = {};
        left_out.face.shrink_to_fit();
        const ClosestPointIndex index(m);
        const BoundingBox box = bounding_box(m);
        const double h = 1e-3 * box.diagonal();
        std::mt19937_64 rng(k + 7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::vector<Vec3> q;
        for (std::size_t f = 0; f < m.n_faces(); f += 3) {
            const Vec3& a = m.points[std::size_t(m.faces[f][0])];
            const Vec3& b = m.points[std::size_t(m.faces[f][1])];
            q.push_back(a + h * Vec3(u(rng), u(rng), u(rng)));
            q.push_back(0.5 * (a + b) + h * Vec3(u(rng), u(rng), u(rng)));
        }
        for (int i = 0; i < 500; ++i)
            q.push_back(box.min + 0.5 * (Vec3(u(rng), u(rng), u(rng)) + Vec3::Ones()).cwiseProduct(box.max - box.min));
        std::vector<double> d(q.size()), d2(q.size());
        std::vector<std::int8_t> s_kept(q.size()), s_left(q.size());
        signed_query(m, index, *kept, q.data(), q.size(), d.data(), s_kept.data());
        signed_query(m, index, left_out, q.data(), q.size(), d2.data(), s_left.data());
        EXPECT_EQ(d, d2);
        EXPECT_EQ(s_kept, s_left) << k;
        const std::vector<ClosestPoint> c = index.closest_points(q);
        int positive = 0, negative = 0;
        for (std::size_t i = 0; i < q.size(); ++i) {
            const int s = distance_sign(m, *kept, q[i], c[i].face);
            EXPECT_EQ(distance_sign(m, left_out, q[i], c[i].face), s) << k << " " << i;
            positive += s > 0;
            negative += s < 0;
        }
        EXPECT_GT(positive, 100) << k;
        EXPECT_GT(negative, 100) << k;
    }
}

// Four spheres in a chain, each pair sharing one vertex: three vertices whose
// faces form two fans. The fans are walked one vertex at a time in parallel:
// the same count as the topology report at any thread count.
TEST(SignAvailability, PinchedVerticesAreCountedAtAnyThreadCount)
{
    const Mesh sphere = icosphere(2).mesh;
    Mesh chain;
    std::int32_t previous_top = -1;
    for (int k = 0; k < 4; ++k) {
        const auto base = std::int32_t(chain.points.size());
        // Sphere k's lowest vertex goes onto sphere k-1's highest one.
        std::size_t low = 0, high = 0;
        for (std::size_t v = 0; v < sphere.n_vertices(); ++v) {
            if (sphere.points[v].z() < sphere.points[low].z()) low = v;
            if (sphere.points[v].z() > sphere.points[high].z()) high = v;
        }
        const Vec3 shift = k == 0 ? Vec3::Zero() : Vec3(chain.points[std::size_t(previous_top)] - sphere.points[low]);
        for (const Vec3& p : sphere.points) chain.points.push_back(p + shift);
        for (Face t : sphere.faces) {
            for (auto& v : t) v = (k > 0 && std::size_t(v) == low) ? previous_top : base + v;
            chain.faces.push_back(t);
        }
        previous_top = base + std::int32_t(high);
    }
    const TopologyReport t = topology_report(chain);
    EXPECT_EQ(t.non_manifold_vertices, 3u);
    EXPECT_EQ(t.boundary_edges + t.non_manifold_edges + t.orientation_conflicts, 0u);
    const int threads = omp_get_max_threads();
    for (const int n : {1, 3}) {
        omp_set_num_threads(n);
        const std::string reason = sign_unavailable_reason(chain, "M");
        EXPECT_NE(reason.find("has 3 non-manifold vertices"), std::string::npos) << reason;
        EXPECT_FALSE(pseudo_normals(chain, "M"));
        EXPECT_TRUE(pseudo_normals(sphere, "M"));
    }
    omp_set_num_threads(threads);
}

TEST(PseudoNormals, OppositeHalfEdgesGiveTheCertificationsNeighbours)
{
    // The certification reads the neighbours across the target's edges from
    // its pseudo-normals' opposite half-edges when it can be signed against:
    // the table of the edge map, on sharp, smooth and flipped closed meshes.
    std::vector<Mesh> meshes = {read_mesh(kData + "/fandisk.ply").mesh, read_mesh(kData + "/torus_R1_r025.ply").mesh,
                                read_mesh(kData + "/sphere_irregular_3072.ply").mesh};
    meshes.push_back(flipped(meshes[1]));
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const MeshData data(meshes[k]);
        const auto normals = pseudo_normals(data, "M");
        ASSERT_TRUE(normals) << k;
        const detail::Neighbours from_edges = detail::edge_neighbours(data);
        ASSERT_EQ(from_edges.size(), meshes[k].n_faces());
        EXPECT_TRUE(detail::neighbours_across(normals->opposite) == from_edges) << k;
    }
}

TEST(PseudoNormals, MadeWithoutFaceNormalsTheyAreTheSame)
{
    // The surface distance makes the pseudo-normals without their face
    // normals (made as the vertex normals read them): the same vertex
    // normals, opposite half-edges, orientation and volume, bit for bit.
    std::vector<Mesh> meshes = {read_mesh(kData + "/fandisk.ply").mesh, read_mesh(kData + "/torus_R1_r025.ply").mesh};
    meshes.push_back(flipped(meshes[1]));
    for (std::size_t k = 0; k < meshes.size(); ++k) {
        const MeshData data(meshes[k]);
        const auto full = pseudo_normals(data, "M");
        std::string reason;
        const auto lean = detail::pseudo_normals_without_faces(data, "M", &reason);
        ASSERT_TRUE(full && lean) << k << ": " << reason;
        EXPECT_EQ(full->face.size(), meshes[k].n_faces());
        EXPECT_TRUE(lean->face.empty());
        EXPECT_TRUE(lean->vertex == full->vertex) << k;
        EXPECT_EQ(lean->opposite, full->opposite);
        EXPECT_EQ(lean->flipped, full->flipped);
        EXPECT_EQ(lean->volume, full->volume);
    }
    // And the same reason where there are none.
    Mesh open = meshes[1];
    open.faces.pop_back();
    std::string r1, r2;
    EXPECT_FALSE(pseudo_normals(MeshData(open), "M", &r1));
    EXPECT_FALSE(detail::pseudo_normals_without_faces(MeshData(open), "M", &r2));
    EXPECT_EQ(r1, r2);
    EXPECT_FALSE(r1.empty());
}

// The sign of a point over a face's interior without the normal's
// normalisation is that of the normalised product in every case: points far
// from the plane, points a few units in the last place from it (where the
// unnormalised product is not certain and the normalised one decides),
// points on it, and meshes at extreme scales. The reference is the
// normalised product itself (unit_face_normal()).
TEST(SignedDistance, InteriorSignIsTheNormalisedProductsSign)
{
    const auto reference = [](bool flipped, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
        const double s = d.dot(unit_face_normal(flipped, a, b, c));
        return s > 0.0 ? 1 : (s < 0.0 ? -1 : 0);
    };
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::size_t near = 0, zeros = 0, checked = 0;
    for (const double scale : {1e-160, 1e-80, 1e-3, 1.0, 1e3, 1e80, 1e160}) {
        for (int i = 0; i < 20000; ++i) {
            const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
            const Vec3 n = (b - a).cross(c - a);
            if (!(n.norm() > 1e-3)) continue;
            // In-plane part plus an offset along the normal from 1 down to a
            // few units in the last place of the in-plane part (and zero).
            const Vec3 inplane = u(rng) * (b - a) + u(rng) * (c - a);
            const int k = i % 20;
            const double off = k == 19 ? 0.0 : std::ldexp(u(rng), -3 * k);
            const Vec3 d = scale * (inplane + off * n.normalized());
            for (const bool flipped : {false, true}) {
                const int want = reference(flipped, d, scale * a, scale * b, scale * c);
                ASSERT_EQ(detail::interior_sign(flipped, d, scale * a, scale * b, scale * c), want)
                    << "scale " << scale << " offset " << off << " flipped " << flipped;
                ++checked;
                zeros += want == 0;
            }
            near += k >= 14;
        }
    }
    EXPECT_GT(checked, std::size_t(200000));
    EXPECT_GT(near, std::size_t(1000));  // the uncertain band was visited
    EXPECT_GT(zeros, std::size_t(0));
}
