#include "meshdiff/core/mesh.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"
#include "meshdiff/studies/shapes.h"

#include <cmath>
#include <limits>
#include <string>

using namespace meshdiff;

namespace {

// The unit cube [0, 1]^3 as 12 outward triangles.
Mesh unit_cube()
{
    Mesh m;
    for (int i = 0; i < 8; ++i) m.points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    m.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
               {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

Mesh right_triangle()
{
    Mesh m;
    m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    m.faces = {{0, 1, 2}};
    return m;
}

template <class F>
std::string invalid_mesh_message(F&& f)
{
    try {
        f();
    } catch (const InvalidMeshError& e) {
        return e.what();
    }
    return "no InvalidMeshError";
}

}  // namespace

TEST(Validate, AcceptsAValidMesh)
{
    EXPECT_NO_THROW(validate(unit_cube()));
    EXPECT_NO_THROW(validate(icosphere(2).mesh, "sphere"));
}

TEST(Validate, ThrowsForAnOutOfRangeOrNegativeIndexNamingTheMesh)
{
    Mesh m = right_triangle();
    m.faces[0][2] = 3;
    const std::string message = invalid_mesh_message([&] { validate(m, "mesh A"); });
    EXPECT_NE(message.find("mesh A"), std::string::npos) << message;
    EXPECT_NE(message.find("vertex 3"), std::string::npos) << message;
    m.faces[0][2] = -1;
    EXPECT_THROW(validate(m), InvalidMeshError);
}

TEST(Validate, ThrowsForANonFiniteCoordinate)
{
    for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        Mesh m = right_triangle();
        m.points[1].y() = bad;
        const std::string message = invalid_mesh_message([&] { validate(m, "mesh B"); });
        EXPECT_NE(message.find("mesh B"), std::string::npos) << message;
        EXPECT_NE(message.find("vertex 1"), std::string::npos) << message;
    }
}

TEST(Validate, ThrowsWithoutFacesOrVertices)
{
    Mesh m = right_triangle();
    m.faces.clear();
    EXPECT_THROW(validate(m), InvalidMeshError);
    EXPECT_THROW(validate(Mesh()), InvalidMeshError);
}

TEST(BoundingBox, UnitCubeHasDiagonalSqrt3)
{
    const BoundingBox box = bounding_box(unit_cube());
    EXPECT_EQ(box.min, Vec3(0, 0, 0));
    EXPECT_EQ(box.max, Vec3(1, 1, 1));
    EXPECT_EQ(box.diagonal(), std::sqrt(3.0));
}

TEST(BoundingBox, IsTheCoordinatewiseExtremesOfTheVertices)
{
    Mesh m;
    m.points = {Vec3(1, -2, 3), Vec3(-4, 5, -6), Vec3(7, 8, 0.5)};
    m.faces = {{0, 1, 2}};
    const BoundingBox box = bounding_box(m);
    EXPECT_EQ(box.min, Vec3(-4, -2, -6));
    EXPECT_EQ(box.max, Vec3(7, 8, 3));
    EXPECT_EQ(box.diagonal(), std::sqrt(11.0 * 11 + 10 * 10 + 9 * 9));
    EXPECT_EQ(bounding_box(Mesh()).diagonal(), 0.0);  // no vertices: the zero box
}

TEST(FaceCross, IsTwiceTheAreaVectorCounterClockwise)
{
    Mesh m = right_triangle();
    EXPECT_EQ(face_cross(m, 0), Vec3(0, 0, 1));
    m.faces[0] = {0, 2, 1};  // clockwise seen from +z
    EXPECT_EQ(face_cross(m, 0), Vec3(0, 0, -1));
    m.points = {Vec3(1, 1, 1), Vec3(3, 1, 1), Vec3(1, 1, 4)};  // legs 2 (x) and 3 (z)
    m.faces[0] = {0, 1, 2};
    EXPECT_EQ(face_cross(m, 0), Vec3(0, -6, 0));
}

TEST(SurfaceArea, UnitRightTriangleIsOneHalf)
{
    EXPECT_EQ(surface_area(right_triangle()), 0.5);
}

TEST(SurfaceArea, UnitCubeIsSixAndAGridIsItsRectangle)
{
    EXPECT_EQ(surface_area(unit_cube()), 6.0);
    // plane_grid(nx, ny, s) covers (nx - 1) s by (ny - 1) s.
    EXPECT_NEAR(surface_area(plane_grid(5, 4, 0.5).mesh), 4 * 0.5 * 3 * 0.5, 1e-14);
}

TEST(SurfaceArea, InscribedIcospheresApproachFourPiFromBelow)
{
    double previous = 0.0;
    for (int k = 1; k <= 4; ++k) {
        const double a = surface_area(icosphere(k).mesh);
        EXPECT_LT(a, 4 * M_PI);
        EXPECT_GT(a, previous);
        previous = a;
    }
    EXPECT_NEAR(previous, 4 * M_PI, 0.01 * 4 * M_PI);
}
