#include "meshdiff/distance/same_connectivity.h"

#include "meshdiff/core/tolerances.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <string>

using namespace meshdiff;

namespace {

const std::string kData = MESHDIFF_TEST_DATA_DIR;

}  // namespace

TEST(SameConnectivity, TranslatedCopyMovesEveryVertexByTheVectorAndKeepsNormals)
{
    const Mesh a = read_mesh(kData + "/bunny_res3.ply").mesh;
    Mesh b = a;
    const Vec3 t(0.03, -0.04, 0.12);  // |t| = 0.13
    for (Vec3& p : b.points) p += t;
    std::string why;
    const auto r = same_connectivity(a, b, &why);
    ASSERT_TRUE(r) << why;
    EXPECT_EQ(r->vertices, a.n_vertices());
    EXPECT_NEAR(r->displacement_rms, 0.13, 1e-15);
    EXPECT_NEAR(r->displacement_max, 0.13, 1e-15);
    EXPECT_NEAR(r->normal_max_deg, 0.0, 1e-5);  // rounding of the translated coordinates only
    EXPECT_NEAR(r->normal_rms_deg, 0.0, 1e-6);
    EXPECT_EQ(r->faces + r->degenerate_faces, a.n_faces());
}

TEST(SameConnectivity, RotatedPlaneTurnsEveryNormalByTheAngle)
{
    // A flat grid rotated about an axis in its plane: every face normal turns
    // by the rotation angle exactly.
    const Mesh a = plane_grid(9, 7, 0.2).mesh;
    const double angle = 0.3;  // radians
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(angle, Vec3(1, 1, 0).normalized()).toRotationMatrix();
    Mesh b = a;
    for (Vec3& p : b.points) p = rot * p;
    const auto r = same_connectivity(a, b);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->normal_rms_deg, angle * 180.0 / kPi, 1e-12);
    EXPECT_NEAR(r->normal_max_deg, angle * 180.0 / kPi, 1e-12);
    EXPECT_EQ(r->faces, a.n_faces());
    // Displacement of p under a rotation by angle about an axis through the
    // origin: 2 sin(angle / 2) x (distance of p to the axis).
    double max = 0.0;
    for (const Vec3& p : a.points) {
        const Vec3 axis = Vec3(1, 1, 0).normalized();
        max = std::max(max, 2.0 * std::sin(angle / 2.0) * (p - axis * axis.dot(p)).norm());
    }
    EXPECT_NEAR(r->displacement_max, max, 1e-14);
}

TEST(SameConnectivity, RotatedSphereTurnsNoNormalByMoreThanTheAngle)
{
    const Mesh a = icosphere(2).mesh;
    const double angle = 0.2;
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(angle, Vec3(0.2, -0.5, 1).normalized()).toRotationMatrix();
    Mesh b = a;
    for (Vec3& p : b.points) p = rot * p;
    const auto r = same_connectivity(a, b);
    ASSERT_TRUE(r);
    EXPECT_LE(r->normal_max_deg, angle * 180.0 / kPi + 1e-10);
    EXPECT_GT(r->normal_max_deg, 0.95 * angle * 180.0 / kPi);  // faces near the equator of the axis
    // Unit sphere: no vertex moves more than 2 sin(angle / 2), those near the equator nearly so.
    EXPECT_LE(r->displacement_max, 2.0 * std::sin(angle / 2.0) + 1e-12);
    EXPECT_GT(r->displacement_max, 0.95 * 2.0 * std::sin(angle / 2.0));
}

TEST(SameConnectivity, OneMovedVertexGivesItsDisplacement)
{
    const Mesh a = plane_grid(5, 5).mesh;  // 25 vertices
    Mesh b = a;
    b.points[12] += Vec3(0, 0, 0.5);  // the centre vertex
    const auto r = same_connectivity(a, b);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->max_vertex, 12u);
    EXPECT_DOUBLE_EQ(r->displacement_max, 0.5);
    EXPECT_NEAR(r->displacement_rms, 0.5 / 5.0, 1e-15);  // sqrt(0.25 / 25)
    EXPECT_GT(r->normal_max_deg, 0.0);
}

TEST(SameConnectivity, DifferentConnectivityGivesTheReason)
{
    const Mesh a = plane_grid(5, 5).mesh;
    std::string why;
    EXPECT_FALSE(same_connectivity(a, plane_grid(5, 6).mesh, &why));
    EXPECT_EQ(why, "vertex counts differ (25 vs 30)");
    Mesh b = a;
    b.faces.pop_back();
    EXPECT_FALSE(same_connectivity(a, b, &why));
    EXPECT_NE(why.find("face counts differ"), std::string::npos);
    b = a;
    std::swap(b.faces[3][1], b.faces[3][2]);
    EXPECT_FALSE(same_connectivity(a, b, &why));
    EXPECT_NE(why.find("face 3 differs"), std::string::npos);
}
