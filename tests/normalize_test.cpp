#include "meshdiff/geometry/normalize.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/error.h"
#include "meshdiff/io/io.h"

using namespace meshdiff;
using meshdiff::test::data;

TEST(Normalization, UnitMeanRadiusAboutTheCentroid)
{
    Mesh m = read_mesh(data("fandisk.ply")).mesh;
    const auto n = unit_normalization(m);
    const Mesh u = apply_normalization(m, n);
    Vec3 c = Vec3::Zero();
    for (const auto& p : u.points) c += p;
    c /= double(u.n_vertices());
    double mean = 0;
    for (const auto& p : u.points) mean += p.norm();
    mean /= double(u.n_vertices());
    EXPECT_NEAR(c.norm(), 0.0, 1e-12);
    EXPECT_NEAR(mean, 1.0, 1e-12);
    Mesh point;
    point.points = {Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)};
    point.faces = {{0, 1, 2}};
    EXPECT_THROW(unit_normalization(point), Error);
}
