#include "meshdiff/report/csv.h"

#include <gtest/gtest.h>

#include "meshdiff/compare.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/json.h"
#include "meshdiff/studies/shapes.h"

#include <sstream>

using namespace meshdiff;

namespace {

std::vector<std::string> lines(const std::string& s)
{
    std::vector<std::string> out;
    std::istringstream in(s);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// The cells of one CSV line without quoted commas.
std::vector<std::string> cells(const std::string& line)
{
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string c; std::getline(in, c, ',');) out.push_back(c);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

}  // namespace

TEST(CsvTable, ColumnsInFirstAppearanceOrderMissingCellsEmptyAndRfc4180Quotes)
{
    CsvTable t;
    t.set(0, "id", "a");
    t.set(1, "error", "said \"no\", twice");
    t.set(1, "id", "b");
    t.set(0, "x", "1");
    std::ostringstream out;
    t.write(out);
    EXPECT_EQ(out.str(), "id,error,x\na,,1\nb,\"said \"\"no\"\", twice\",\n");
}

TEST(CsvCell, NumbersRoundTripNullIsEmptyStringsAsTheyAre)
{
    EXPECT_EQ(csv_cell(nlohmann::json(nullptr)), "");
    EXPECT_EQ(csv_cell(nlohmann::json(0.1)), "0.1");
    EXPECT_EQ(csv_cell(nlohmann::json(true)), "true");
    EXPECT_EQ(csv_cell(nlohmann::json("certified")), "certified");
    const double x = 1.0 / 3.0;
    EXPECT_EQ(std::stod(csv_cell(nlohmann::json(x))), x);
}

TEST(ComparisonColumns, HeadlineColumnsFirstAndEveryValueFromTheJson)
{
    LoadedMesh a, b;
    a.mesh = icosphere(3).mesh;
    b.mesh = a.mesh;
    for (auto& p : b.mesh.points) p *= 1.01;
    CompareOptions o;
    o.profile.levels = {1, 2};
    o.sampling.samples = 2000;
    const nlohmann::json j = comparison_json(compare_meshes(a, b, o));
    CsvTable t;
    add_comparison_columns(t, 0, j);
    std::ostringstream out;
    t.write(out);
    const auto rows = lines(out.str());
    ASSERT_EQ(rows.size(), 2u);
    const auto head = cells(rows[0]), row = cells(rows[1]);
    ASSERT_EQ(head.size(), row.size());
    std::map<std::string, std::string> m;
    for (std::size_t i = 0; i < head.size(); ++i) m[head[i]] = row[i];
    EXPECT_EQ(head[0], "original_vertices");
    EXPECT_EQ(m["original_vertices"], csv_cell(j["original"]["mesh"]["vertices"]));
    EXPECT_EQ(m["hausdorff"], csv_cell(j["surface_distance"]["hausdorff"]["upper"]));
    EXPECT_EQ(m["forward_rms"], csv_cell(j["surface_distance"]["forward"]["rms"]));
    EXPECT_EQ(m["forward_p999"], csv_cell(j["surface_distance"]["forward"]["p999"]));
    EXPECT_EQ(m["d_L2"], csv_cell(j["roughness_distance"]["distance"][1]));
    EXPECT_EQ(m["d_global"], csv_cell(j["roughness_distance"]["global"]["distance"]));
    EXPECT_EQ(m.count("sampling_samples"), 0u);  // the sampling settings are left out
}
