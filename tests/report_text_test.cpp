#include "meshdiff/report/text.h"

#include <gtest/gtest.h>

#include "meshdiff/compare.h"
#include "meshdiff/io.h"
#include "meshdiff/shapes.h"

#include <string>

using namespace meshdiff;

namespace {

std::string data(const std::string& name)
{
    return std::string(MESHDIFF_TEST_DATA_DIR) + "/" + name;
}

}  // namespace

TEST(ComparisonText, HasMetroSectionNames)
{
    const LoadedMesh a = read_mesh(data("sphere_ico_2562.ply"));
    const LoadedMesh b = read_mesh(data("ellipsoid_150_100_100.ply"));
    CompareOptions o;
    o.profile.levels = {1, 10};
    o.sampling.samples = 20000;
    const std::string text = comparison_text(compare_meshes(a, b, o));
    EXPECT_NE(text.find("Forward distance (M1 -> M2)"), std::string::npos);
    EXPECT_NE(text.find("Hausdorff distance"), std::string::npos);
}
