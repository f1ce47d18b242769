#include "meshdiff/geometry/cotangent.h"

#include "meshdiff/geometry/normals.h"
#include "meshdiff/io/io.h"
#include "meshdiff/roughness/curvature.h"
#include "meshdiff/studies/shapes.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include <cmath>

using namespace meshdiff;
using meshdiff::test::data;

TEST(Cotangent, OfKnownAnglesAndZeroForAFlatCorner)
{
    const Vec3 x(1, 0, 0);
    EXPECT_NEAR(cot(x, Vec3(0, 2, 0)), 0.0, 1e-16);
    EXPECT_NEAR(cot(x, Vec3(1, 1, 0)), 1.0, 1e-15);
    EXPECT_NEAR(cot(x, Vec3(0.5, std::sqrt(3.0) / 2, 0)), 1.0 / std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(cot(x, Vec3(-1, 1, 0)), -1.0, 1e-15);
    // sin just above and below kFlatCornerSine.
    EXPECT_GT(cot(x, Vec3(1, 10 * kFlatCornerSine, 0)), 1e10);
    EXPECT_EQ(cot(x, Vec3(1, 0.1 * kFlatCornerSine, 0)), 0.0);
    EXPECT_EQ(cot(x, Vec3(-3, 0, 0)), 0.0);
    EXPECT_EQ(cot(x, Vec3(0, 0, 0)), 0.0);
}

TEST(Cotangent, MeyerCurvatureEqualsTheFlowsCurvatureNormalOnAnIcosphere)
{
    // The Meyer estimator (face by face) and the curvature flows (vertex by
    // vertex) use the same operator: H = -Hn . n, both close to 1 / r.
    for (double r : {0.5, 2.0}) {
        const Mesh m = icosphere(3, r).mesh;
        CurvatureOptions o;
        o.method = CurvatureMethod::MeyerCotangent;
        const CurvatureField meyer = mean_curvature(m, o);
        const std::vector<Vec3> normals = vertex_normals(m);
        const Adjacency vf = vertex_faces(m);
        ASSERT_EQ(meyer.undefined, 0u);
        for (std::size_t v = 0; v < m.n_vertices(); ++v) {
            const double flow = -curvature_normal(m, vf, m.points, v).dot(normals[v]);
            EXPECT_NEAR(meyer.H[v], flow, 1e-13 / r) << v;
            EXPECT_NEAR(flow, 1.0 / r, 0.01 / r) << v;
        }
    }
}

TEST(Cotangent, FaceAndVertexAssembliesAgreeOnARealMesh)
{
    const Mesh m = read_mesh(data("bunny_res4_ascii.ply")).mesh;
    const Adjacency vf = vertex_faces(m);
    const std::vector<CotangentSums> by_face = cotangent_sums_by_face(m);
    ASSERT_EQ(by_face.size(), m.n_vertices());
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
        const CotangentSums c = cotangent_sums(m, vf, m.points, v);
        const double scale = c.abs_weights * 1.0 + 1.0;
        EXPECT_NEAR((c.sum - by_face[v].sum).norm(), 0.0, 1e-12 * scale) << v;
        EXPECT_NEAR(c.area4, by_face[v].area4, 1e-12 * c.area4) << v;
        EXPECT_NEAR(c.abs_weights, by_face[v].abs_weights, 1e-12 * scale) << v;
    }
}

TEST(Cotangent, MixedAreasTileAClosedSurface)
{
    // The mixed areas of all vertices sum to the surface area (Meyer et al.).
    for (const Mesh& m : {icosphere(2).mesh, torus_irregular(1500, 1.0, 0.3, 4).mesh}) {
        const Adjacency vf = vertex_faces(m);
        double sum = 0.0;
        for (std::size_t v = 0; v < m.n_vertices(); ++v) sum += cotangent_sums(m, vf, m.points, v).area4 / 4;
        EXPECT_NEAR(sum, surface_area(m), 1e-12 * surface_area(m));
    }
}

TEST(Cotangent, CurvatureNormalVanishesInsideAPlane)
{
    const Mesh m = plane_grid(7, 7, 0.3).mesh;
    const Adjacency vf = vertex_faces(m);
    const auto boundary = boundary_vertex_mask(m);
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
        if (boundary[v]) continue;
        EXPECT_LT(curvature_normal(m, vf, m.points, v).norm(), 1e-14) << v;
    }
}

TEST(Cotangent, BackwardEulerSystemIsSymmetricAndItsResidualIsTheCurvatureTerm)
{
    const Mesh m = torus_irregular(800, 1.0, 0.35, 2).mesh;
    const Adjacency vf = vertex_faces(m);
    std::vector<char> fixed(m.n_vertices(), 0);
    fixed[0] = fixed[5] = 1;
    const double dt = 0.01;
    const CotangentSystem s = backward_euler_system(m, vf, fixed, dt, m.points);
    EXPECT_EQ(s.index[0], -1);
    EXPECT_EQ(s.index[5], -1);
    EXPECT_EQ(s.free(), Eigen::Index(m.n_vertices() - 2));
    const Eigen::SparseMatrix<double> at = s.matrix.transpose();
    EXPECT_LT((s.matrix - at).norm(), 1e-15 * s.matrix.norm());
    // (D - dt L) X - (D X + held terms) = -dt sum_j w_ij (x_j - x_i) for every free vertex.
    const Eigen::MatrixXd residual = s.matrix * s.positions - s.rhs;
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
        if (s.index[v] < 0) continue;
        const CotangentSums c = cotangent_sums(m, vf, m.points, v);
        const Vec3 r = residual.row(s.index[v]).transpose();
        EXPECT_NEAR((r + dt * c.sum).norm(), 0.0, 1e-12 * (1.0 + c.area4 * m.points[v].norm())) << v;
    }
}
