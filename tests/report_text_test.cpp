#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/compare.h"
#include "meshdiff/io/io.h"
#include "meshdiff/studies/shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace meshdiff;
using meshdiff::test::data;

namespace {

// printf's %.6g, which is what fmt's {:.6g} prints for these numbers.
std::string g6(double x)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// icosphere(4) with vertex 0 pushed out by 5% of the radius: it and its
// neighbours make most of sigma^2 at every level.
LoadedMesh spiky_sphere()
{
    LoadedMesh m;
    m.mesh = icosphere(4).mesh;
    m.mesh.points[0] *= 1.05;
    m.input.path = "spiky.ply";
    return m;
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

TEST(ComparisonText, HasTheSummaryAndSameConnectivityLines)
{
    // A flat grid against a copy raised by 0.25: the area-weighted means are
    // 0.25, Chamfer L1 0.5, and every vertex moved by 0.25.
    LoadedMesh a;
    a.mesh = plane_grid(6, 6, 0.2).mesh;
    a.input.path = "plane.ply";
    LoadedMesh b = a;
    for (Vec3& p : b.mesh.points) p.z() += 0.25;
    CompareOptions o;
    o.roughness = false;
    o.summary.fscore_thresholds = {0.5};
    std::string text = comparison_text(compare_meshes(a, b, o));
    EXPECT_NE(text.find("area-weighted mean   forward 0.25 ("), std::string::npos) << text;
    EXPECT_NE(text.find("Chamfer L1 (mean forward + mean backward)        0.5 ("), std::string::npos) << text;
    EXPECT_NE(text.find("F-score at 0.5 x diagonal"), std::string::npos) << text;
    EXPECT_NE(text.find("vertex displacement  RMS 0.25 ("), std::string::npos) << text;
    EXPECT_NE(text.find("face normal angle    RMS 0 deg, max 0 deg"), std::string::npos) << text;
    // Identical planes: face-sample distances 0 exactly, an infinite PSNR written "inf".
    text = comparison_text(compare_meshes(a, a, o));
    EXPECT_NE(text.find("mean squared inf, Hausdorff "), std::string::npos) << text;
}

TEST(ComparisonText, ListsTheOutliersDominateWarningsOfASpikyOriginal)
{
    LoadedMesh clean;
    clean.mesh = icosphere(4).mesh;
    CompareOptions o;
    o.profile.levels = {1, 2};
    o.distance = false;
    const Comparison c = compare_meshes(spiky_sphere(), clean, o);
    const std::string text = comparison_text(c);
    std::size_t listed = 0;
    for (const auto& w : warnings(c.original, &*c.original_profile))
        if (w.kind == WarningKind::OutliersDominate) {
            ++listed;
            EXPECT_TRUE(contains(text, "  ! original: " + w.text + "\n")) << w.text;
        }
    EXPECT_EQ(listed, 3u);  // levels 1, 2 and global
    EXPECT_TRUE(contains(text, "  ! original: level 1: "));
    EXPECT_TRUE(contains(text, "  ! original: global level: "));
    EXPECT_FALSE(contains(text, "  ! processed: "));
}

TEST(ProfileText, HasOneRowPerLevelAndTheGlobalRow)
{
    const LoadedMesh m = read_mesh(data("torus_R1_r025.ply"));
    ProfileOptions o;
    o.levels = {1, 2, 7};
    o.curvature.method = CurvatureMethod::GoldfeatherCubic;
    const RoughnessProfile p = roughness_profile(m.mesh, o);
    const auto rows = lines(profile_text(mesh_facts(m), p));
    std::size_t header = 0;
    while (header < rows.size() && !contains(rows[header], "level        sigma")) ++header;
    ASSERT_LT(header + 4, rows.size());
    const char* names[] = {"       1 ", "       2 ", "       7 ", "  global "};
    for (int k = 0; k < 4; ++k) EXPECT_EQ(rows[header + 1 + k].rfind(names[k], 0), 0u) << rows[header + 1 + k];
    EXPECT_TRUE(contains(rows[header + 1], g6(p.levels[0].sigma))) << rows[header + 1];
    EXPECT_TRUE(contains(rows[header + 4], g6(p.global.sigma))) << rows[header + 4];
    EXPECT_TRUE(header + 5 == rows.size() || rows[header + 5].empty());  // nothing else in the table
    const std::string counts = "2-ring " + std::to_string(p.curvature_widened) + ", normal rows dropped " +
                               std::to_string(p.curvature_normal_rows_dropped) + ", quadric fallback " +
                               std::to_string(p.curvature_fallback);
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](const std::string& r) { return contains(r, counts); }))
        << counts;
    // The jet's own line.
    o.curvature.method = CurvatureMethod::Jet;
    const RoughnessProfile q = roughness_profile(m.mesh, o);
    const std::string jet = "curvature  jet (2-ring, rows weighted 1/|d|^4); undefined " +
                            std::to_string(q.curvature_undefined) + ", 3-ring " + std::to_string(q.curvature_widened) +
                            ", degree-2 fallback " + std::to_string(q.curvature_fallback) + ", steep " +
                            std::to_string(q.curvature_steep) + "\n";
    EXPECT_TRUE(contains(profile_text(mesh_facts(m), q), jet)) << jet;
}

TEST(ExactProfileText, NamesThePropertyAndTheHErrorWithARowPerLevel)
{
    const Shape t = torus(64, 24);
    ProfileOptions o;
    o.levels = {1, 4};
    o.keep_vertex_data = true;
    const RoughnessProfile estimated = roughness_profile(t.mesh, o);
    const ExactProfile exact = exact_profile(t.mesh, t.exact_H, o, estimated);
    const std::string text = exact_profile_text(estimated, exact, "exact_H");
    EXPECT_TRUE(contains(text, "'exact_H'"));
    EXPECT_TRUE(contains(text, "over " + std::to_string(t.mesh.n_vertices()) + " vertices"));
    char rms[32];
    std::snprintf(rms, sizeof rms, "RMS %.4g", exact.h_error.rms);
    EXPECT_TRUE(contains(text, rms)) << text;
    EXPECT_TRUE(contains(text, g6(exact.profile.levels[1].sigma)));
    EXPECT_TRUE(contains(text, "  global "));
    // A closed torus: every vertex is interior.
    EXPECT_TRUE(contains(text, "  interior: " + std::string(rms))) << text;
    EXPECT_TRUE(contains(text, "over " + std::to_string(t.mesh.n_vertices()) + "; boundary: no vertex\n")) << text;
    EXPECT_EQ(lines(text).size(), 4u + 3u);  // blank, title, interior/boundary, header, 2 levels, global
}

TEST(ExactProfile, ReportsInteriorAndBoundaryVerticesApart)
{
    // issue 28: a height field's boundary vertices (4 (n - 1) of them) fit
    // one-sided neighbourhoods; their error is reported apart from the
    // interior's, and the two parts make up the whole.
    const Shape s = heightfield(33);
    ProfileOptions o;
    o.levels = {1};
    o.keep_vertex_data = true;
    for (auto m : {CurvatureMethod::GoldfeatherCubic, CurvatureMethod::Jet}) {
        o.curvature.method = m;
        const RoughnessProfile estimated = roughness_profile(s.mesh, o);
        const ExactProfile exact = exact_profile(s.mesh, s.exact_H, o, estimated);
        EXPECT_EQ(exact.h_error_boundary.compared, 4u * 32u);
        EXPECT_EQ(exact.h_error_interior.compared + exact.h_error_boundary.compared, exact.h_error.compared);
        EXPECT_GT(exact.h_error_boundary.rms, exact.h_error_interior.rms) << to_string(m);
        EXPECT_DOUBLE_EQ(std::max(exact.h_error_interior.max, exact.h_error_boundary.max), exact.h_error.max);
        const double whole = std::sqrt(
            (exact.h_error_interior.rms * exact.h_error_interior.rms * double(exact.h_error_interior.compared) +
             exact.h_error_boundary.rms * exact.h_error_boundary.rms * double(exact.h_error_boundary.compared)) /
            double(exact.h_error.compared));
        EXPECT_NEAR(whole, exact.h_error.rms, 1e-12 * exact.h_error.rms);
        const nlohmann::json j = exact_profile_json(estimated, exact, "exact_H");
        EXPECT_EQ(j["h_error"]["boundary"]["vertices"], 4u * 32u);
        EXPECT_DOUBLE_EQ(j["h_error"]["interior"]["rms"].get<double>(), exact.h_error_interior.rms);
    }
}

TEST(SmoothingText, StatesTheRunAndTheFlowTimeOfExplicitFlows)
{
    SmoothingOptions o;
    o.iterations = 4;
    Mesh m = noisy_sphere(2, 0.05, 3).mesh;
    const SmoothingReport lap = smooth(m, o);
    const std::string text = smoothing_text("out.ply", o, m.n_vertices(), lap);
    EXPECT_EQ(text, "out.ply: laplacian post-updating, 4 iterations, 162 vertices\n");
    o.method = SmoothingMethod::MeanCurvatureFlow;
    const SmoothingReport mcf = smooth(m, o);
    const std::string flow = smoothing_text("out.ply", o, m.n_vertices(), mcf);
    EXPECT_TRUE(contains(flow, "mcf post-updating"));
    EXPECT_TRUE(contains(flow, "flow time " + g6(mcf.time) + " e^2 (e = " + g6(mcf.mean_edge)));
}

TEST(SmoothingWarning, NoneForAStableRunAndNamesTheInputForAHugeMcfStep)
{
    SmoothingOptions o;
    o.method = SmoothingMethod::MeanCurvatureFlow;
    o.iterations = 2;
    o.step = 0.05;
    Mesh m = noisy_sphere(2, 0.05, 3).mesh;
    EXPECT_EQ(smoothing_warning("in.ply", o, smooth(m, o)), std::nullopt);
    o.method = SmoothingMethod::Laplacian;
    EXPECT_EQ(smoothing_warning("in.ply", o, smooth(m, o)), std::nullopt);
    o.method = SmoothingMethod::MeanCurvatureFlow;
    o.step = 10.0;
    o.iterations = 1;
    const SmoothingReport r = smooth(m, o);
    ASSERT_EQ(r.unstable_iterations, 1);
    const auto w = smoothing_warning("noisy-in.ply", o, r);
    ASSERT_TRUE(w.has_value());
    EXPECT_TRUE(contains(*w, "noisy-in.ply"));
    EXPECT_TRUE(contains(*w, "1 of 1 explicit steps"));
    EXPECT_TRUE(contains(*w, "--step"));
}

TEST(NoiseText, StatesTheCountsAmplitudeAndSeed)
{
    Mesh m = read_mesh(data("hemisphere.ply")).mesh;
    NoiseOptions o;
    o.amplitude = 0.25;
    o.seed = 17;
    const NoiseReport r = add_noise(m, o);
    ASSERT_EQ(r.skipped_boundary, 120u);  // one boundary loop of 120 vertices
    const std::string text = noise_text("noisy.ply", o, r);
    EXPECT_TRUE(contains(text, "noisy.ply: " + std::to_string(r.moved) + " vertices moved, 120 skipped (120 boundary"));
    EXPECT_TRUE(contains(text, "amplitude " + g6(r.amplitude)));
    EXPECT_TRUE(contains(text, "uniform [-0.25, 0.25) x mean edge length " + g6(r.unit_length)));
    EXPECT_TRUE(contains(text, "along vertex normals, seed 17"));
    EXPECT_EQ(noise_description(o, r), "uniform [-0.25, 0.25) x mean edge length " + g6(r.unit_length));
}

TEST(ShapeText, StatesTheCountsAndTheRangeOfExactH)
{
    const Shape t = torus(12, 8, 1.0, 0.25);
    const std::string text = shape_text("torus.ply", t, "torus R 1 r 0.25");
    // H on the inner equator (1 - 0.5) / (0.5 0.75) = 4/3, on the outer (1 + 0.5) / (0.5 1.25) = 2.4.
    EXPECT_EQ(text, "torus.ply: 96 vertices, 192 faces, exact H in [" + g6(4.0 / 3.0) + ", " + g6(2.4) +
                        "] (torus R 1 r 0.25)\n");
}

TEST(CorsiniText, ProfileAndComparisonHaveARowPerLevelWithTheRoughness)
{
    const LoadedMesh a = read_mesh(data("sphere_ico_2562.ply"));
    const LoadedMesh b = read_mesh(data("ellipsoid_150_100_100.ply"));
    CorsiniOptions co;
    co.levels = {1, 3};
    const CorsiniProfile p = corsini_profile(a.mesh, co);
    const auto rows = lines(corsini_profile_text(mesh_facts(a), p));
    std::size_t header = 0;
    while (header < rows.size() && !contains(rows[header], "level    roughness")) ++header;
    ASSERT_LT(header + 3, rows.size());
    EXPECT_EQ(rows[header + 1].rfind("       1 ", 0), 0u) << rows[header + 1];
    EXPECT_TRUE(contains(rows[header + 2], g6(p.levels[1].roughness))) << rows[header + 2];
    EXPECT_TRUE(contains(rows[header + 3], "global") && contains(rows[header + 3], g6(p.global.roughness)));
    CompareOptions o;
    o.profile.levels = {1, 3};
    o.distance = false;
    o.measure = RoughnessMeasure::Corsini;
    const std::string text = comparison_text(compare_meshes(a, b, o));
    EXPECT_TRUE(contains(text, "Corsini roughness"));
    EXPECT_FALSE(contains(text, "Roughness profiles"));
    EXPECT_TRUE(contains(text, "  multi "));
}
