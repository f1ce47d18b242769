#include "meshdiff/report/json.h"

#include <gtest/gtest.h>

#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/shapes.h"

#include <cmath>
#include <functional>

using namespace meshdiff;

namespace {

std::string data(const std::string& name)
{
    return std::string(MESHDIFF_TEST_DATA_DIR) + "/" + name;
}

// No NaN or Inf can reach a JSON report: nlohmann would write null for them,
// so check that every number is finite (nulls are allowed only where documented).
bool all_finite(const nlohmann::json& j)
{
    if (j.is_number_float()) return std::isfinite(j.get<double>());
    if (j.is_object() || j.is_array())
        for (const auto& v : j)
            if (!all_finite(v)) return false;
    return true;
}

}  // namespace

TEST(ProfileJson, HasTheSchemaKeysAndOnlyFiniteNumbers)
{
    const LoadedMesh m = read_mesh(data("teapot.obj"));
    ProfileOptions o;
    o.levels = {1, 2, 5};
    const auto j = profile_json(mesh_facts(m), roughness_profile(m.mesh, o));
    EXPECT_EQ(j["schema"], "meshdiff.profile/1");
    for (const char* key : {"mesh", "curvature", "levels", "sigma", "sigma_global", "level_details", "warnings"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["levels"], nlohmann::json({1, 2, 5}));
    EXPECT_EQ(j["mesh"]["components"], 4);
    EXPECT_TRUE(j["curvature"].contains("undefined_vertices"));
    EXPECT_GT(j["mesh"]["scale_factor"].get<double>(), 0.0);
    EXPECT_TRUE(all_finite(j));
    EXPECT_FALSE(j["warnings"].empty());
}

TEST(CompareJson, HasTheSchemaKeysAndHausdorffIsTheLargerMaximum)
{
    const LoadedMesh a = read_mesh(data("sphere_ico_2562.ply"));
    const LoadedMesh b = read_mesh(data("ellipsoid_150_100_100.ply"));
    CompareOptions o;
    o.profile.levels = {1, 10};
    o.sampling.samples = 20000;
    const auto j = comparison_json(compare_meshes(a, b, o));
    EXPECT_EQ(j["schema"], "meshdiff.compare/1");
    EXPECT_EQ(j["original"]["schema"], "meshdiff.profile/1");
    const auto& rd = j["roughness_distance"];
    for (const char* key : {"k", "levels", "distance", "relative_change", "global"}) EXPECT_TRUE(rd.contains(key));
    EXPECT_TRUE(rd["global"].contains("distance") && rd["global"].contains("relative_change"));
    const auto& sd = j["surface_distance"];
    for (const char* key : {"min", "max", "mean", "rms", "samples"}) {
        EXPECT_TRUE(sd["forward"].contains(key));
        EXPECT_TRUE(sd["backward"].contains(key));
    }
    EXPECT_EQ(sd["hausdorff"].get<double>(),
              std::max(sd["forward"]["max"].get<double>(), sd["backward"]["max"].get<double>()));
    // The stretched sphere reaches 0.5 beyond the unit sphere along x.
    EXPECT_NEAR(sd["hausdorff"].get<double>(), 0.5, 0.01);
    EXPECT_TRUE(all_finite(j));
}

TEST(CompareJson, EachHalfCanBeSwitchedOff)
{
    const LoadedMesh a = read_mesh(data("hemisphere.ply"));
    CompareOptions o;
    o.roughness = false;
    auto j = comparison_json(compare_meshes(a, a, o));
    EXPECT_TRUE(j["roughness_distance"].is_null());
    EXPECT_LT(j["surface_distance"]["hausdorff"].get<double>(), 1e-12);
    o.roughness = true;
    o.distance = false;
    j = comparison_json(compare_meshes(a, a, o));
    EXPECT_TRUE(j["surface_distance"].is_null());
    o.roughness = false;
    EXPECT_THROW(compare_meshes(a, a, o), InvalidArgumentError);
}
