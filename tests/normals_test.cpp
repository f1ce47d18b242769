#include "meshdiff/geometry/normals.h"

#include <gtest/gtest.h>
#include <omp.h>

#include "support/data.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace meshdiff;
using meshdiff::test::data;

namespace {

double angle(const Vec3& a, const Vec3& b)
{
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

// A fan around vertex 0 at the origin: rim points at the given polar angles
// (radians, ascending) and radii in the plane spanned by \p u and \p v,
// triangles (0, rim k, rim k+1) counter-clockwise seen from u x v.
void add_fan(Mesh& mesh, const Vec3& u, const Vec3& v, const std::vector<double>& angles,
             const std::vector<double>& radii, bool closed)
{
    const auto first = std::int32_t(mesh.n_vertices());
    for (std::size_t k = 0; k < angles.size(); ++k)
        mesh.points.push_back(radii[k] * (std::cos(angles[k]) * u + std::sin(angles[k]) * v));
    const auto n = std::int32_t(angles.size());
    for (std::int32_t k = 0; k + 1 < n + (closed ? 1 : 0); ++k)
        mesh.faces.push_back({0, first + k, first + (k + 1) % n});
}

// The definition as a loop over the faces (the sums at each vertex in face
// order), for a bit-for-bit check of the per-vertex loop.
std::vector<Vec3> normals_by_faces(const Mesh& mesh)
{
    const MeshData data(mesh);
    std::vector<Vec3> sum(mesh.n_vertices(), Vec3::Zero());
    std::vector<double> weight(mesh.n_vertices(), 0.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        if (data.degenerate_faces()[f]) continue;
        const Face& t = mesh.faces[f];
        const Vec3 n = face_cross(mesh, f).normalized();
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = mesh.points[std::size_t(t[k])];
            const Vec3 e1 = mesh.points[std::size_t(t[(k + 1) % 3])] - p;
            const Vec3 e2 = mesh.points[std::size_t(t[(k + 2) % 3])] - p;
            const double a = angle(e1, e2);
            sum[std::size_t(t[k])] += a * n;
            weight[std::size_t(t[k])] += a;
        }
    }
    for (std::size_t v = 0; v < sum.size(); ++v) {
        const double len = sum[v].norm();
        sum[v] = len > kMinNormalRatio * weight[v] && len > 0.0 ? Vec3(sum[v] / len) : Vec3(Vec3::Zero());
    }
    return sum;
}

}  // namespace

TEST(VertexNormals, EqualTheLoopOverTheFacesBitForBitAtAnyThreadCount)
{
    // bunny_res4 has duplicate faces, bunny_res3 is a scan's mesh; the
    // icosphere gets the degenerate faces of the test below.
    Mesh sliver = icosphere(2).mesh;
    const Face t = sliver.faces[0];
    sliver.points.push_back(sliver.points[std::size_t(t[0])] + 1e-7 * Vec3(1, 0, 0));
    sliver.faces.push_back({t[0], t[1], std::int32_t(sliver.n_vertices()) - 1});
    sliver.faces.push_back({t[0], t[0], t[1]});
    const int saved = omp_get_max_threads();
    for (const Mesh& m :
         {read_mesh(data("bunny_res4_ascii.ply")).mesh, read_mesh(data("bunny_res3.ply")).mesh, sliver}) {
        const std::vector<Vec3> want = normals_by_faces(m);
        for (int threads : {1, 3}) {
            omp_set_num_threads(threads);
            const MeshData d(m);
            const std::vector<Vec3> given = vertex_normals(d, vertex_faces(m)), derived = vertex_normals(d);
            for (std::size_t v = 0; v < want.size(); ++v) {
                ASSERT_EQ(given[v], want[v]) << "vertex " << v << ", " << threads << " threads";
                ASSERT_EQ(derived[v], want[v]) << "vertex " << v << ", " << threads << " threads";
            }
        }
    }
    omp_set_num_threads(saved);
    Mesh fewer = sliver;
    fewer.points.pop_back();
    fewer.faces.resize(fewer.faces.size() - 2);
    EXPECT_THROW(vertex_normals(MeshData(fewer), vertex_faces(sliver)), InvalidArgumentError);
}

TEST(VertexNormals, OutwardOnTheSphereAndZeroWhereFacesCancel)
{
    const Shape s = icosphere(3);
    const auto n = vertex_normals(s.mesh);
    for (std::size_t i = 0; i < n.size(); ++i) EXPECT_GT(n[i].dot(s.mesh.points[i].normalized()), 0.999);
    // Two copies of a triangle with opposite orientation: normals cancel.
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    m.faces = {{0, 1, 2}, {0, 2, 1}};
    for (const auto& v : vertex_normals(m)) EXPECT_EQ(v.squaredNorm(), 0.0);
}

TEST(VertexNormals, UnitOutwardAndRadialToFirstOrderOnIcospheres)
{
    // The icosahedron and its first split are symmetric enough that the
    // normals are radial up to rounding; beyond that the largest angle to the
    // radial direction is about 0.035 h (h the mean edge length, radius 1): we
    // allow 0.05 h, and require it to shrink with every refinement.
    double previous = kPi;
    for (int k = 0; k <= 5; ++k) {
        const Mesh mesh = icosphere(k).mesh;
        const auto n = vertex_normals(mesh);
        const double h = mean_edge_length(mesh, vertex_adjacency(mesh));
        const double tol = k <= 1 ? 1e-14 : 0.05 * h;
        double worst = 0;
        for (std::size_t i = 0; i < n.size(); ++i) {
            ASSERT_NEAR(n[i].norm(), 1.0, 1e-15) << "k = " << k << ", vertex " << i;
            ASSERT_GT(n[i].dot(mesh.points[i]), 0.0) << "k = " << k << ", vertex " << i;
            worst = std::max(worst, angle(n[i], mesh.points[i]));
        }
        EXPECT_LT(worst, tol) << "k = " << k;
        if (k >= 3) {
            EXPECT_LT(worst, 0.6 * previous) << "k = " << k;
        }
        previous = worst;
    }
}

TEST(VertexNormals, CoplanarFanGivesThePlaneNormalWhateverItsTriangulation)
{
    // A closed fan in z = 0: the plane normal exactly, for any rim.
    for (const auto& angles :
         {std::vector<double>{0, 2.0, 4.0}, std::vector<double>{0, 0.1, 0.3, 1.9, 2.0, 3.5, 5.9, 6.2}}) {
        Mesh mesh;
        mesh.points = {Vec3::Zero()};
        const std::vector<double> radii = {1, 3, 0.2, 7, 1, 1, 2, 0.5};
        add_fan(mesh, Vec3::UnitX(), Vec3::UnitY(), angles, radii, true);
        EXPECT_EQ(vertex_normals(mesh)[0], Vec3::UnitZ()) << angles.size() << " triangles";
    }
    // A tilted plane: the plane normal up to rounding.
    const Vec3 u = Vec3(1, -1, 0).normalized(), v = Vec3(1, 1, -1).normalized().cross(u);
    Mesh mesh;
    mesh.points = {Vec3::Zero()};
    add_fan(mesh, u, v, {0, 0.7, 0.8, 2.5, 4.4, 5.0}, {2, 1, 0.1, 3, 1, 4}, true);
    EXPECT_LT(angle(vertex_normals(mesh)[0], u.cross(v)), 1e-15);
}

TEST(VertexNormals, CubeCornerIsTheDiagonalHoweverItsFacesAreSplit)
{
    // The corner of the cube [0, 1]^3 at the origin. Each of its three faces
    // is cut into a different number of wedges of different sizes: every face
    // still subtends pi/2 there, so angle weighting gives -(1, 1, 1)/sqrt(3);
    // weighting by area or by face count would not.
    Mesh mesh;
    mesh.points = {Vec3::Zero()};
    const double q = kPi / 2;
    // Seen from outside (from -x, -y, -z), counter-clockwise means from y to x
    // in z = 0 (y x x = -z), from x to z in y = 0, from z to y in x = 0.
    add_fan(mesh, Vec3::UnitY(), Vec3::UnitX(), {0, q}, {1, 1}, false);
    add_fan(mesh, Vec3::UnitX(), Vec3::UnitZ(), {0, 0.2, 0.3, q}, {1, 5, 0.3, 2}, false);
    add_fan(mesh, Vec3::UnitZ(), Vec3::UnitY(), {0, 1.2, q}, {0.5, 9, 1}, false);
    const Vec3 n = vertex_normals(mesh)[0];
    EXPECT_LT((n + Vec3(1, 1, 1).normalized()).norm(), 1e-15) << n.transpose();
}

TEST(VertexNormals, DegenerateFacesContributeNothing)
{
    const Shape s = icosphere(2);
    const auto reference = vertex_normals(s.mesh);
    Mesh mesh = s.mesh;
    const Face t = mesh.faces[0];
    const std::int32_t v0 = t[0], extra = std::int32_t(mesh.n_vertices());
    const Vec3 a = mesh.points[std::size_t(t[0])], b = mesh.points[std::size_t(t[1])],
               c = mesh.points[std::size_t(t[2])];
    // Faces at v0 below the zero-area threshold (|cross| <= 1e-14 diag^2): a
    // tiny sliver turned against face t (well-defined direction, wide angle,
    // area ~1e-14 that of t), a collinear one and a repeated corner; the new
    // vertices touch nothing but degenerate faces.
    mesh.points.push_back(a + 1e-7 * (c - a));
    mesh.points.push_back(a + 1e-7 * (b - a));
    mesh.points.push_back(0.5 * (a + b));
    mesh.points.push_back(0.25 * a + 0.75 * b);
    mesh.faces.push_back({v0, extra, extra + 1});
    mesh.faces.push_back({v0, extra + 2, extra + 3});
    mesh.faces.push_back({v0, v0, t[1]});
    const auto n = vertex_normals(mesh);
    for (std::size_t i = 0; i < reference.size(); ++i) ASSERT_EQ(n[i], reference[i]) << "vertex " << i;
    for (std::int32_t k = 0; k < 4; ++k) EXPECT_EQ(n[std::size_t(extra + k)], Vec3::Zero()) << "new vertex " << k;

    // Only degenerate faces (a point and a segment): every normal is zero.
    Mesh flat;
    flat.points = {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(5, 0, 0)};
    flat.faces = {{0, 1, 2}, {2, 1, 0}, {3, 3, 3}};
    for (const auto& v : vertex_normals(flat)) EXPECT_EQ(v, Vec3::Zero());
}

TEST(VertexNormals, ReversingEveryFaceNegatesEveryNormal)
{
    for (const char* name : {"bunny_res3.ply", "fandisk.ply"}) {
        const Mesh mesh = read_mesh(data(name)).mesh;
        Mesh flipped = mesh;
        for (auto& f : flipped.faces) std::swap(f[1], f[2]);
        const auto n = vertex_normals(mesh), m = vertex_normals(flipped);
        for (std::size_t i = 0; i < n.size(); ++i) ASSERT_EQ(m[i], Vec3(-n[i])) << name << ", vertex " << i;
    }
}

TEST(VertexNormals, InvariantToTranslationAndUniformScale)
{
    for (const char* name : {"bunny_res3.ply", "fandisk.ply"}) {
        const Mesh mesh = read_mesh(data(name)).mesh;
        const auto n = vertex_normals(mesh);
        // A power of two scales every intermediate exactly.
        Mesh doubled = mesh;
        for (auto& p : doubled.points) p *= 8.0;
        EXPECT_EQ(vertex_normals(doubled), n) << name;
        Mesh moved = mesh;
        for (auto& p : moved.points) p = 37.5 * p + Vec3(100, -20, 5);
        const auto m = vertex_normals(moved);
        for (std::size_t i = 0; i < n.size(); ++i) {
            ASSERT_EQ(m[i].isZero(0.0), n[i].isZero(0.0)) << name << ", vertex " << i;
            ASSERT_LT((m[i] - n[i]).norm(), 1e-12) << name << ", vertex " << i;
        }
    }
}
