// The umbrella header alone is enough for the whole computing library.
#include "meshdiff/meshdiff.h"

#include <gtest/gtest.h>

#include <string>

using namespace meshdiff;

TEST(Umbrella, OneIncludeComparesTwoSpheres)
{
    // A sphere against the same sphere scaled by 1.1: every vertex of the
    // larger one is about 0.1 r from the smaller surface.
    const Shape a = icosphere(3, 1.0);
    const Shape b = icosphere(3, 1.1);
    const SurfaceDistance d = surface_distance(a.mesh, b.mesh);
    EXPECT_NEAR(d.hausdorff, 0.1, 0.005);
    const RoughnessDistance rd = roughness_distance(roughness_profile(a.mesh), roughness_profile(b.mesh));
    // Roughness is scale-invariant: the two profiles agree.
    for (const LevelDistance& l : rd.levels) EXPECT_NEAR(l.relative_change, 0.0, 1e-9) << l.level;
    EXPECT_EQ(std::string(MESHDIFF_VERSION).substr(0, 2), std::to_string(MESHDIFF_VERSION_MAJOR) + ".");
}
