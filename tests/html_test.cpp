#include "meshdiff/report/html.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/error.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/report/colormap.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/outputs.h"
#include "meshdiff/studies/shapes.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

using namespace meshdiff;
using meshdiff::test::data;

namespace {

// The text of the element <script ... id="ID"> of a page.
std::string element(const std::string& page, const std::string& id)
{
    const std::string open = "id=\"" + id + "\">";
    const auto from = page.find(open);
    if (from == std::string::npos) return {};
    const auto begin = from + open.size();
    return page.substr(begin, page.find("</script>", begin) - begin);
}

// A comparison as --html asks for it (with_outputs()), of the two bundled bunnies.
struct BunnyReport
{
    LoadedMesh a = read_mesh(data("bunny_res3.ply"));
    LoadedMesh b = read_mesh(data("bunny_res4_ascii.ply"));
    Comparison c;
    BunnyReport()
    {
        CompareOutputs o;
        o.html = "unused.html";
        CompareOptions options = with_outputs(CompareOptions{}, o);
        options.profile.levels = {1, 2};
        c = compare_meshes(a, b, options);
    }
};

}  // namespace

TEST(ReduceForDisplay, KeepsAMeshWithinTheBudgetAsItIs)
{
    const Mesh m = icosphere(2).mesh;
    std::vector<double> v(m.n_vertices());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = double(i) * 0.5;
    const DisplayMesh d = reduce_for_display(m, {&v}, m.n_faces());
    EXPECT_FALSE(d.reduced);
    ASSERT_EQ(d.positions.size(), 3 * m.n_vertices());
    ASSERT_EQ(d.indices.size(), 3 * m.n_faces());
    EXPECT_EQ(d.positions[3 * 7 + 1], float(m.points[7].y()));
    EXPECT_EQ(d.indices[3 * 5 + 2], std::uint32_t(m.faces[5][2]));
    EXPECT_EQ(d.values[0], v);
}

TEST(ReduceForDisplay, MeetsTheBudgetAndKeepsTheLargestValueOfEveryCluster)
{
    const Mesh m = icosphere(5).mesh;  // 20480 faces
    std::vector<double> v(m.n_vertices(), 1.0), w(m.n_vertices(), -0.5);
    v[1234] = 40.0;                                    // one worst vertex
    w[77] = -9.0;                                      // a largest magnitude that is negative
    w[78] = std::numeric_limits<double>::quiet_NaN();  // undefined values are skipped
    const DisplayMesh d = reduce_for_display(m, {&v, &w}, 2000);
    EXPECT_TRUE(d.reduced);
    EXPECT_EQ(d.full_faces, m.n_faces());
    EXPECT_LE(d.indices.size() / 3, 2000u);
    EXPECT_GE(d.indices.size() / 3, 500u);  // not coarser than needed
    const std::size_t n = d.positions.size() / 3;
    ASSERT_EQ(d.values[0].size(), n);
    for (std::uint32_t i : d.indices) ASSERT_LT(i, n);
    EXPECT_EQ(*std::max_element(d.values[0].begin(), d.values[0].end()), 40.0);
    EXPECT_EQ(*std::min_element(d.values[1].begin(), d.values[1].end()), -9.0);
    for (double x : d.values[1]) EXPECT_FALSE(std::isnan(x));
    // Cluster positions stay on the unit sphere's neighbourhood (means of nearby vertices).
    for (std::size_t i = 0; i < n; ++i) {
        const double r = std::sqrt(double(d.positions[3 * i]) * d.positions[3 * i] +
                                   double(d.positions[3 * i + 1]) * d.positions[3 * i + 1] +
                                   double(d.positions[3 * i + 2]) * d.positions[3 * i + 2]);
        EXPECT_NEAR(r, 1.0, 0.1);
    }
}

TEST(ComparisonHtml, IsOnePageWithTheJsonReportAndNoExternalResource)
{
    const BunnyReport r;
    const nlohmann::json j = comparison_json(r.c);
    HtmlOptions o;
    o.command = "meshdiff a b --html </script><b>x";
    const std::string page = comparison_html(r.c, r.a.mesh, r.b.mesh, j, o);
    EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_EQ(nlohmann::json::parse(element(page, "meshdiff-report")), j);
    // The command cannot end its element early: "</" is written "<\/" (the same JSON string).
    EXPECT_EQ(nlohmann::json::parse(element(page, "meshdiff-meta"))["command"], o.command);
    for (const char* external : {"<script src", "<link", "@import", "<img", "<iframe"})
        EXPECT_EQ(page.find(external), std::string::npos) << external;
    const nlohmann::json view = nlohmann::json::parse(element(page, "meshdiff-view"));
    std::vector<std::string> fields;
    for (const auto& f : view["fields"]) fields.push_back(f["name"]);
    EXPECT_EQ(fields, (std::vector<std::string>{"distance", "D_1", "D_2", "D_global"}));
    EXPECT_EQ(view["meshes"][0]["vertices"], r.a.mesh.n_vertices());
    EXPECT_EQ(view["meshes"][1]["faces"], r.b.mesh.n_faces());
    EXPECT_EQ(view["meshes"][0]["reduced"], false);
    // The default distance range: [0, the 99th percentile of both meshes' vertex distances].
    std::vector<double> all = r.c.original_vertex_distance;
    all.insert(all.end(), r.c.processed_vertex_distance.begin(), r.c.processed_vertex_distance.end());
    std::sort(all.begin(), all.end());
    EXPECT_EQ(view["fields"][0]["range"][1], all[std::size_t(std::llround(0.99 * double(all.size() - 1)))]);
    EXPECT_LT(view["fields"][0]["range"][1], all.back());
}

TEST(ComparisonHtml, RefusesABudgetBelow1000AndABadColourRange)
{
    const BunnyReport r;
    const nlohmann::json j = comparison_json(r.c);
    HtmlOptions o;
    o.face_budget = 999;
    EXPECT_THROW(comparison_html(r.c, r.a.mesh, r.b.mesh, j, o), InvalidArgumentError);
    o.face_budget = 1000;
    o.color_range = std::pair{0.5, 0.5};
    EXPECT_THROW(comparison_html(r.c, r.a.mesh, r.b.mesh, j, o), InvalidArgumentError);
}

TEST(WriteHtmlFile, NamesTheFileItCannotWrite)
{
    const std::string path = "/nonexistent-meshdiff-folder/r.html";
    try {
        write_html_file(path, "<!DOCTYPE html>");
        FAIL() << "no IoError";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(ProfileHtml, EmbedsTheProfileJsonAndOffersHAndEveryLevel)
{
    const LoadedMesh m = read_mesh(data("fandisk.ply"));
    ProfileOptions options;
    options.levels = {1, 3};
    options.keep_vertex_data = true;
    const RoughnessProfile p = roughness_profile(m.mesh, options);
    const nlohmann::json j = profile_json(mesh_facts(m), p);
    const std::string page = profile_html(p, m.mesh, m.input.path, j);
    EXPECT_EQ(nlohmann::json::parse(element(page, "meshdiff-report")), j);
    const nlohmann::json view = nlohmann::json::parse(element(page, "meshdiff-view"));
    std::vector<std::string> fields;
    for (const auto& f : view["fields"]) fields.push_back(f["name"]);
    EXPECT_EQ(fields, (std::vector<std::string>{"H", "D_1", "D_3", "D_global"}));
    // H on the vertex data map's range: robust_symmetric_range(H).
    EXPECT_EQ(view["fields"][0]["range"][1], robust_symmetric_range(p.H));
    EXPECT_EQ(view["meshes"].size(), 1u);
    EXPECT_EQ(view["meshes"][0]["faces"], m.mesh.n_faces());
}

namespace {

// The text of the element `<script type="application/json" id="ID">` of \p page, as JSON.
nlohmann::json embedded_json(const std::string& page, const std::string& id)
{
    const std::string open = "<script type=\"application/json\" id=\"" + id + "\">";
    const auto start = page.find(open);
    if (start == std::string::npos) return nullptr;
    const auto from = start + open.size();
    std::string text = page.substr(from, page.find("</script>", from) - from);
    for (auto p = text.find("<\\/"); p != std::string::npos; p = text.find("<\\/", p)) text.erase(p + 1, 1);
    return nlohmann::json::parse(text);
}

std::size_t count(const std::string& s, const std::string& what)
{
    std::size_t n = 0;
    for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + what.size())) ++n;
    return n;
}

}  // namespace

TEST(BatchSummaryHtml, OneRowPerRecordWithTheRecordsEmbeddedAndTheLinks)
{
    const nlohmann::json result = {
        {"surface_distance",
         {{"hausdorff", {{"method", "certified"}, {"upper", 0.25}, {"relative", {{"upper", 0.125}}}}},
          {"forward", {{"mean", 0.01}, {"rms", 0.02}}},
          {"backward", {{"mean", 0.03}, {"rms", 0.04}}}}},
        {"roughness_distance",
         {{"levels", {1, 2, 5}},
          {"distance", {1.5, 2.5, 5.5}},
          {"global", {{"distance", 9.5}}},
          {"local", {{"levels", {1, 2, 5}}, {"rms", {0.5, nullptr, 0.75}}, {"global", 0.875}}}}}};
    const nlohmann::json records = {{{"id", "a&b"},
                                     {"status", "ok"},
                                     {"original", "x.ply"},
                                     {"processed", "y.ply"},
                                     {"result", result},
                                     {"html", "pages/a b.html"}},
                                    {{"id", "bad"}, {"status", "error"}, {"error", "y.ply: no such file </script>"}},
                                    {{"id", "gone"}, {"status", "missing"}}};
    SummaryHtmlOptions o;
    o.command = "meshdiff batch-summary r.jsonl --html out/s.html";
    o.page_dir = "out";
    const std::string page = batch_summary_html(records, o);

    EXPECT_EQ(embedded_json(page, "meshdiff-summary"), records);
    EXPECT_EQ(embedded_json(page, "meshdiff-meta")["command"], o.command);
    EXPECT_EQ(count(page, "<tr data-index="), records.size());
    EXPECT_EQ(count(page, "<a href="), 1u);
    EXPECT_NE(page.find("<a href=\"../pages/a%20b.html\">"), std::string::npos);
    EXPECT_NE(page.find("data-path=\"result.surface_distance.hausdorff.upper\" data-value=\"0.25\">0.25<"),
              std::string::npos);
    EXPECT_NE(page.find("data-path=\"result.roughness_distance.distance.2\" data-value=\"5.5\""), std::string::npos);
    EXPECT_NE(page.find("data-path=\"result.roughness_distance.local.rms.2\" data-value=\"0.75\""), std::string::npos);
    EXPECT_NE(page.find("<td data-key=\"local_L2\"></td>"), std::string::npos);  // a null: an empty cell
    EXPECT_NE(page.find(">a&amp;b</td>"), std::string::npos);
    EXPECT_NE(page.find("no such file &lt;/script&gt;</td>"), std::string::npos);
    EXPECT_EQ(count(page, "</script>"), 3u);  // the two JSON elements and the script: nothing ends one early
    EXPECT_EQ(page.find("<script src"), std::string::npos);
    EXPECT_EQ(page.find("http://"), page.find("http://www.w3.org/2000/svg"));  // no network address but SVG's
    EXPECT_THROW(batch_summary_html(nlohmann::json::object()), InvalidArgumentError);
}
