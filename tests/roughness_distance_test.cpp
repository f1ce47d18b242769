#include "meshdiff/roughness/roughness_distance.h"

#include <gtest/gtest.h>

#include "meshdiff/error.h"
#include "meshdiff/studies/shapes.h"

#include <cmath>

using namespace meshdiff;

TEST(RoughnessDistance, ZeroForIdenticalProfiles)
{
    const auto p = roughness_profile(noisy_sphere(3, 0.02, 4).mesh);
    const auto d = roughness_distance(p, p);
    ASSERT_EQ(d.levels.size(), 20u);
    for (const auto& l : d.levels) {
        EXPECT_EQ(l.distance, 0.0);
        EXPECT_EQ(l.relative_change, 0.0);
    }
    EXPECT_TRUE(d.has_global);
    EXPECT_EQ(d.global.distance, 0.0);
}

TEST(RoughnessDistance, CorsiniFormulaBothDirections)
{
    const double k = 1e-4;
    const auto up = level_distance(1, 2.0, 3.0, k);
    EXPECT_NEAR(up.distance, std::log(0.5 + k) - std::log(k), 1e-12);
    EXPECT_NEAR(up.relative_change, 0.5, 1e-15);
    const auto down = level_distance(1, 2.0, 1.0, k);  // the paper's printed form is undefined here
    EXPECT_NEAR(down.distance, std::log(0.5 + k) - std::log(k), 1e-12);
    EXPECT_NEAR(down.relative_change, -0.5, 1e-15);
    // Monotone in |change|, and k only rescales.
    EXPECT_LT(level_distance(1, 2.0, 2.2, k).distance, level_distance(1, 2.0, 2.6, k).distance);
    EXPECT_GT(level_distance(1, 2.0, 3.0, 1e-6).distance, up.distance);
}

TEST(RoughnessDistance, ZeroReferenceRoughnessIsFiniteAndFlagged)
{
    const auto both = level_distance(3, 0.0, 0.0);
    EXPECT_EQ(both.distance, 0.0);
    EXPECT_TRUE(both.reference_zero);
    EXPECT_TRUE(both.relative_change_defined);
    const auto one = level_distance(3, 0.0, 1.0, 1e-4);
    EXPECT_TRUE(std::isfinite(one.distance));
    EXPECT_NEAR(one.distance, std::log(1 + 1e-4) - std::log(1e-4), 1e-12);
    EXPECT_FALSE(one.relative_change_defined);
    EXPECT_THROW(level_distance(1, 1.0, 1.0, 0.0), InvalidArgumentError);
    EXPECT_THROW(level_distance(1, -1.0, 1.0), InvalidArgumentError);
    EXPECT_THROW(level_distance(1, std::nan(""), 1.0), InvalidArgumentError);
}

TEST(RoughnessDistance, MatchesLevelsByNumber)
{
    ProfileOptions a, b;
    a.levels = {1, 2, 5};
    b.levels = {5, 1};
    b.global = false;
    const Shape s = torus(32, 16);
    const auto d = roughness_distance(roughness_profile(s.mesh, a), roughness_profile(s.mesh, b));
    ASSERT_EQ(d.levels.size(), 2u);
    EXPECT_EQ(d.levels[0].level, 1);
    EXPECT_EQ(d.levels[1].level, 5);
    EXPECT_FALSE(d.has_global);
    for (const auto& l : d.levels) EXPECT_EQ(l.distance, 0.0);
}

TEST(RoughnessDistance, NoisierSphereIsFartherAtEveryLevel)
{
    const auto ref = roughness_profile(icosphere(4).mesh);
    const auto lo = roughness_profile(noisy_sphere(4, 0.005, 1).mesh);
    const auto hi = roughness_profile(noisy_sphere(4, 0.02, 1).mesh);
    const auto dlo = roughness_distance(ref, lo), dhi = roughness_distance(ref, hi);
    for (std::size_t k = 0; k < dlo.levels.size(); ++k) {
        EXPECT_GT(dlo.levels[k].relative_change, 0.0);
        EXPECT_GT(dhi.levels[k].distance, dlo.levels[k].distance);
    }
}
