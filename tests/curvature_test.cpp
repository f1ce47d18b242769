#include "meshdiff/curvature.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/shapes.h"

#include <cmath>
#include <vector>

using namespace meshdiff;

namespace {

// The error of the estimate against the exact H over the interior vertices.
CurvatureError error(const Shape& s, const CurvatureOptions& o = {})
{
    return curvature_error(mean_curvature(s.mesh, o).H, s.exact_H, boundary_vertex_mask(s.mesh));
}

CurvatureOptions method(CurvatureMethod m)
{
    CurvatureOptions o;
    o.method = m;
    return o;
}

}  // namespace

TEST(MeanCurvature, SphereEqualsInverseRadiusWithPositiveSign)
{
    for (double r : {0.5, 1.0, 3.0}) {
        const Shape s = icosphere(4, r);
        const auto field = mean_curvature(s.mesh);
        for (double h : field.H) EXPECT_NEAR(h, 1.0 / r, 0.015 / r);
        EXPECT_EQ(field.undefined, 0u);
    }
}

TEST(MeanCurvature, FlippedOrientationFlipsTheSign)
{
    Shape s = icosphere(3);
    for (auto& f : s.mesh.faces) std::swap(f[1], f[2]);
    for (double h : mean_curvature(s.mesh).H) EXPECT_NEAR(h, -1.0, 0.03);
}

TEST(MeanCurvature, CubicFitConvergesOnIcospheres)
{
    double previous = 1e9;
    for (int k = 2; k <= 5; ++k) {
        const double e = error(icosphere(k)).rms;
        EXPECT_LT(e, 0.8 * previous) << "k = " << k;
        previous = e;
    }
    EXPECT_LT(previous, 5e-3);
}

TEST(MeanCurvature, CubicFitConvergesQuadraticallyOnTheTorus)
{
    // Regular torus grids: halving the spacing divides the error by about 4.
    const double e1 = error(torus(32, 16)).rms;
    const double e2 = error(torus(64, 32)).rms;
    const double e3 = error(torus(128, 64)).rms;
    EXPECT_GT(e1 / e2, 3.0);
    EXPECT_GT(e2 / e3, 3.0);
    EXPECT_LT(e3, 0.02);
}

TEST(MeanCurvature, CubicFitConvergesOnTheEllipsoid)
{
    double previous = 1e9;
    for (int k = 2; k <= 5; ++k) {
        const double e = error(ellipsoid(k, 1.5, 1.0, 1.0)).rms;
        EXPECT_LT(e, 0.8 * previous) << "k = " << k;
        previous = e;
    }
    EXPECT_LT(previous, 5e-3);
}

TEST(MeanCurvature, EstimatorsAgreeWithTheTorusFormula)
{
    // All three estimators on a fine regular torus: H within a few percent of
    // the range of H, which runs from -2 to 2.4 for R = 1, r = 0.25... here
    // R = 1, r = 0.25: inner H = (1 - 0.5) / (0.5 * 0.75) = 1.33, outer 1.2 / 0.625 = 2.4.
    for (auto m : {CurvatureMethod::GoldfeatherCubic, CurvatureMethod::Quadric, CurvatureMethod::MeyerCotangent}) {
        const CurvatureError e = error(torus(128, 64), method(m));
        EXPECT_LT(e.rms, 0.02) << to_string(m);
        EXPECT_LT(e.max, 0.03) << to_string(m);
        EXPECT_EQ(e.undefined, 0u);
    }
}

TEST(MeanCurvature, MeyerConvergesOnIcospheres)
{
    const double e3 = error(icosphere(3), method(CurvatureMethod::MeyerCotangent)).rms;
    const double e5 = error(icosphere(5), method(CurvatureMethod::MeyerCotangent)).rms;
    EXPECT_LT(e5, e3 / 4);
    EXPECT_LT(e5, 1e-5);
}

TEST(MeanCurvature, HeightFieldInteriorIsAccurateForEveryEstimator)
{
    const Shape s = heightfield(129);
    for (auto m : {CurvatureMethod::GoldfeatherCubic, CurvatureMethod::Quadric, CurvatureMethod::MeyerCotangent}) {
        const CurvatureError e = error(s, method(m));
        EXPECT_LT(e.rms, 0.02) << to_string(m);
    }
}

TEST(MeanCurvature, IndependentOfRotationAndScalesAsInverseLength)
{
    const Shape s = torus_irregular(3000, 1.0, 0.3, 5);
    const auto ref = mean_curvature(s.mesh).H;
    Mesh moved = s.mesh;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(1.1, Vec3(0.3, -1, 2).normalized()).toRotationMatrix();
    for (auto& p : moved.points) p = 4.0 * (R * p) + Vec3(3, 2, 1);
    const auto h = mean_curvature(moved).H;
    for (std::size_t i = 0; i < ref.size(); ++i) ASSERT_NEAR(h[i] * 4.0, ref[i], 1e-9 * (1 + std::abs(ref[i])));
}

TEST(MeanCurvature, FallbacksAndUndefinedVerticesAreCounted)
{
    // A single triangle: every vertex has two neighbours, too few for any fit.
    Mesh tri;
    tri.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    tri.faces = {{0, 1, 2}};
    const auto f = mean_curvature(tri);
    EXPECT_EQ(f.undefined, 3u);
    for (double h : f.H) EXPECT_TRUE(std::isnan(h));
    // Meyer is undefined on boundary vertices, the fits are not.
    const Shape grid = heightfield(17);
    const auto meyer = mean_curvature(grid.mesh, method(CurvatureMethod::MeyerCotangent));
    EXPECT_EQ(meyer.undefined, std::size_t(4 * 16));
    EXPECT_EQ(mean_curvature(grid.mesh).undefined, 0u);
    // Valence-5 icosphere vertices widen to the 2-ring (min_neighbors 6).
    EXPECT_EQ(mean_curvature(icosphere(3).mesh).widened, 12u);
}

TEST(MeanCurvature, InverseSquareWeightingIsMeasuredNotDefault)
{
    // Both weightings converge on the sphere; the default stays unweighted
    // because the weighted fit is far less stable on real meshes (README).
    CurvatureOptions w;
    w.weighting = RowWeighting::InverseSquare;
    EXPECT_LT(error(icosphere(5), w).rms, 5e-3);
    EXPECT_EQ(CurvatureOptions{}.weighting, RowWeighting::None);
}

TEST(MeanCurvature, RejectsBadOptions)
{
    const Shape s = icosphere(1);
    CurvatureOptions o;
    o.min_neighbors = 2;
    EXPECT_THROW(mean_curvature(s.mesh, o), InvalidArgumentError);
    o = {};
    o.max_normal_angle_deg = 0;
    EXPECT_THROW(mean_curvature(s.mesh, o), InvalidArgumentError);
    EXPECT_THROW(parse_enum<CurvatureMethod>("rusinkiewicz"), InvalidArgumentError);
    EXPECT_EQ(parse_enum<CurvatureMethod>("meyer"), CurvatureMethod::MeyerCotangent);
}
