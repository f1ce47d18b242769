#include "meshdiff/report/json.h"

#include <gtest/gtest.h>

#include "support/data.h"

#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/text.h"
#include "meshdiff/studies/shapes.h"

#include <cmath>
#include <cstdio>
#include <functional>

using namespace meshdiff;
using meshdiff::test::data;

namespace {

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

// The sorted keys of an object.
std::vector<std::string> keys(const nlohmann::json& j)
{
    std::vector<std::string> k;
    for (const auto& item : j.items()) k.push_back(item.key());
    return k;
}

nlohmann::json smoothing(SmoothingMethod method, bool implicit, bool distance)
{
    SmoothingOptions o;
    o.method = method;
    o.implicit = implicit;
    o.iterations = 5;
    RecordOptions ro;
    ro.every = 2;
    ro.profile.levels = {1, 3};
    ro.distance = distance;
    ro.sampling.samples = 3000;
    Mesh m = noisy_sphere(2, 0.05, 3).mesh;
    const SmoothingRecord r = smooth_and_record(m, o, ro);
    return smoothing_json(r, o, ro, "in.ply", "out.ply");
}

}  // namespace

TEST(ProfileJson, HasTheSchemaKeysAndOnlyFiniteNumbers)
{
    const LoadedMesh m = read_mesh(data("teapot.obj"));
    ProfileOptions o;
    o.levels = {1, 2, 5};
    const RoughnessProfile p = roughness_profile(m.mesh, o);
    const auto j = profile_json(mesh_facts(m), p);
    EXPECT_EQ(j["schema"], "meshdiff.profile/1");
    for (const char* key : {"mesh", "curvature", "levels", "sigma", "sigma_global", "level_details", "warnings"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["levels"], nlohmann::json({1, 2, 5}));
    EXPECT_EQ(j["mesh"]["components"], 4);
    EXPECT_TRUE(j["curvature"].contains("undefined_vertices"));
    // The jet (the default) names its own neighbourhood and counters.
    EXPECT_EQ(j["curvature"]["method"], "jet");
    EXPECT_EQ(j["curvature"]["widened_to_3_ring"], p.curvature_widened);
    EXPECT_EQ(j["curvature"]["degree2_fallback"], p.curvature_fallback);
    EXPECT_EQ(j["curvature"]["steep_fits"], p.curvature_steep);
    for (const char* key : {"widened_to_2_ring", "normal_rows_dropped", "quadric_fallback", "row_weighting",
                            "min_neighbors", "max_normal_angle_deg"})
        EXPECT_FALSE(j["curvature"].contains(key)) << key;
    EXPECT_FALSE(j["curvature"].contains("capped_neighbourhoods"));  // only when a fit was capped
    EXPECT_GT(j["mesh"]["scale_factor"].get<double>(), 0.0);
    EXPECT_TRUE(all_finite(j));
    EXPECT_FALSE(j["warnings"].empty());
    // The paper's cubic fit: its rules' counters.
    o.curvature.method = CurvatureMethod::GoldfeatherCubic;
    const RoughnessProfile g = roughness_profile(m.mesh, o);
    const auto jg = profile_json(mesh_facts(m), g);
    EXPECT_EQ(jg["curvature"]["method"], "goldfeather");
    EXPECT_EQ(jg["curvature"]["widened_to_2_ring"], g.curvature_widened);
    EXPECT_EQ(jg["curvature"]["normal_rows_dropped"], g.curvature_normal_rows_dropped);
    EXPECT_EQ(jg["curvature"]["quadric_fallback"], g.curvature_fallback);
    EXPECT_FALSE(jg["curvature"].contains("steep_fits"));
    EXPECT_TRUE(all_finite(jg));
}

TEST(ProfileJson, BootstrapIntervalsOnlyWhenAsked)
{
    const LoadedMesh m = read_mesh(data("fandisk.ply"));
    ProfileOptions o;
    o.levels = {1, 2};
    const auto plain = profile_json(mesh_facts(m), roughness_profile(m.mesh, o));
    EXPECT_FALSE(plain.contains("bootstrap"));
    EXPECT_FALSE(plain["level_details"][0].contains("sigma_interval"));
    o.bootstrap = 100;
    o.bootstrap_seed = 7;
    const RoughnessProfile p = roughness_profile(m.mesh, o);
    const auto j = profile_json(mesh_facts(m), p);
    EXPECT_EQ(j["bootstrap"]["resamples"], 100);
    EXPECT_EQ(j["bootstrap"]["seed"], 7);
    EXPECT_EQ(j["bootstrap"]["confidence"], kBootstrapConfidence);
    EXPECT_EQ(j["level_details"][1]["sigma_interval"][0].get<double>(), p.levels[1].sigma_interval->first);
    EXPECT_EQ(j["global"]["sigma_interval"][1].get<double>(), p.global.sigma_interval->second);
    // Every other key is the plain report's.
    nlohmann::json stripped = j;
    stripped.erase("bootstrap");
    for (auto& l : stripped["level_details"]) l.erase("sigma_interval");
    stripped["global"].erase("sigma_interval");
    EXPECT_EQ(stripped, plain);
    const std::string text = profile_text(mesh_facts(m), p);
    EXPECT_NE(text.find("95% interval"), std::string::npos);
    char row[64];
    std::snprintf(row, sizeof row, "[%.6g, %.6g]", p.levels[0].sigma_interval->first,
                  p.levels[0].sigma_interval->second);
    EXPECT_NE(text.find(row), std::string::npos) << text;
}

TEST(ProfileJson, CappedNeighbourhoodsAreListedOnlyWhenThereAreSome)
{
    // A fan of 400 triangles: its 400 rim vertices fit on capped 2-rings.
    LoadedMesh m;
    m.mesh.points.emplace_back(0.0, 0.0, 0.1);
    for (int i = 0; i < 400; ++i) m.mesh.points.emplace_back(std::cos(i * M_PI / 200), std::sin(i * M_PI / 200), 0.0);
    for (int i = 0; i < 400; ++i) m.mesh.faces.push_back({0, 1 + i, 1 + (i + 1) % 400});
    ProfileOptions o;
    o.levels = {1};
    const auto j = profile_json(mesh_facts(m), roughness_profile(m.mesh, o));
    EXPECT_EQ(j["curvature"]["capped_neighbourhoods"], 400);
    EXPECT_EQ(j["curvature"]["capped_vertices"], nlohmann::json({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
    EXPECT_EQ(j["curvature"]["max_fit_neighbors"], kMaxFitNeighbors);
    bool warned = false;
    for (const auto& w : j["warnings"])
        warned = warned || w.get<std::string>().find("capped 2-ring") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(CompareJson, HasTheSchemaKeysAndHausdorffIsTheLargerMaximum)
{
    const LoadedMesh a = read_mesh(data("sphere_ico_2562.ply"));
    const LoadedMesh b = read_mesh(data("ellipsoid_150_100_100.ply"));
    CompareOptions o;
    o.profile.levels = {1, 10};
    o.sampling.samples = 20000;
    const auto j = comparison_json(compare_meshes(a, b, o));
    EXPECT_EQ(j["schema"], "meshdiff.compare/2");
    EXPECT_EQ(j["original"]["schema"], "meshdiff.profile/1");
    const auto& rd = j["roughness_distance"];
    for (const char* key : {"k", "levels", "distance", "relative_change", "global"}) EXPECT_TRUE(rd.contains(key));
    EXPECT_TRUE(rd["global"].contains("distance") && rd["global"].contains("relative_change"));
    const auto& sd = j["surface_distance"];
    for (const char* key : {"min", "max", "mean", "rms", "samples"}) {
        EXPECT_TRUE(sd["forward"].contains(key));
        EXPECT_TRUE(sd["backward"].contains(key));
    }
    EXPECT_EQ(sd["sampled_hausdorff"].get<double>(),
              std::max(sd["forward"]["max"].get<double>(), sd["backward"]["max"].get<double>()));
    // Certified by default: the interval holds the sampled maxima and is the
    // larger of the one-sided intervals.
    const auto& h = sd["hausdorff"];
    EXPECT_EQ(h["method"], "certified");
    EXPECT_TRUE(h["certified"].get<bool>());
    EXPECT_GE(h["lower"].get<double>(), sd["sampled_hausdorff"].get<double>());
    EXPECT_EQ(h["lower"].get<double>(), std::max(sd["forward"]["hausdorff"]["lower"].get<double>(),
                                                 sd["backward"]["hausdorff"]["lower"].get<double>()));
    EXPECT_EQ(h["upper"].get<double>(), std::max(sd["forward"]["hausdorff"]["upper"].get<double>(),
                                                 sd["backward"]["hausdorff"]["upper"].get<double>()));
    for (const char* dir : {"forward", "backward"}) {
        const auto& d = sd[dir]["hausdorff"];
        EXPECT_LE(d["upper"].get<double>() - d["lower"].get<double>(), d["tolerance"].get<double>());
        EXPECT_EQ(d["location"]["point"].size(), 3u);
        for (const char* key : {"face", "closest_point", "closest_face", "bound_evaluations"})
            EXPECT_TRUE(d["location"].contains(key) || d.contains(key)) << key;
    }
    // The stretched sphere reaches 0.5 beyond the unit sphere along x.
    EXPECT_NEAR(h["lower"].get<double>(), 0.5, 0.01);
    EXPECT_TRUE(all_finite(j));
    // --hausdorff sampled: the sampled maximum as the lower bound, no upper bound.
    o.hausdorff.reset();
    const auto s = comparison_json(compare_meshes(a, b, o))["surface_distance"];
    EXPECT_EQ(s["hausdorff"]["method"], "sampled");
    EXPECT_EQ(s["hausdorff"]["lower"], s["sampled_hausdorff"]);
    EXPECT_TRUE(s["hausdorff"]["upper"].is_null());
    EXPECT_TRUE(s["forward"]["hausdorff"].is_null());
}

TEST(CompareJson, SurfaceDistanceObjectIsSurfaceDistanceJson)
{
    const LoadedMesh a = read_mesh(data("bunny_res3.ply"));
    const LoadedMesh b = read_mesh(data("bunny_res4_ascii.ply"));
    CompareOptions o;
    o.roughness = false;
    o.sampling.samples = 8000;
    const Comparison c = compare_meshes(a, b, o);
    EXPECT_EQ(comparison_json(c)["surface_distance"], surface_distance_json(*c.distance, o.sampling));
    const auto j = surface_distance_json(surface_distance(a.mesh, b.mesh, o.sampling, false, o.hausdorff), o.sampling);
    EXPECT_EQ(j, comparison_json(c)["surface_distance"]);
    EXPECT_EQ(j["sampling"]["samples_requested"], 8000);
    EXPECT_TRUE(j["cutoff"].is_null());
}

TEST(CompareJson, EachHalfCanBeSwitchedOff)
{
    const LoadedMesh a = read_mesh(data("hemisphere.ply"));
    CompareOptions o;
    o.roughness = false;
    auto j = comparison_json(compare_meshes(a, a, o));
    EXPECT_TRUE(j["roughness_distance"].is_null());
    EXPECT_LT(j["surface_distance"]["hausdorff"]["upper"].get<double>(), 1e-12);
    o.roughness = true;
    o.distance = false;
    j = comparison_json(compare_meshes(a, a, o));
    EXPECT_TRUE(j["surface_distance"].is_null());
    o.roughness = false;
    EXPECT_THROW(compare_meshes(a, a, o), InvalidArgumentError);
}

TEST(CompareJson, FaceSchemeIsSpeltByToString)
{
    const LoadedMesh a = read_mesh(data("hemisphere.ply"));
    CompareOptions o;
    o.roughness = false;
    o.sampling.samples = 5000;
    for (const FaceSampling scheme : {FaceSampling::SimilarTriangles, FaceSampling::MonteCarlo}) {
        o.sampling.face_scheme = scheme;
        const auto j = comparison_json(compare_meshes(a, a, o));
        EXPECT_EQ(j["surface_distance"]["sampling"]["face_scheme"], to_string(scheme));
        EXPECT_EQ(j["surface_distance"]["sampling"]["samples_requested"], 5000);
    }
    EXPECT_EQ(to_string(FaceSampling::SimilarTriangles), "similar");
    EXPECT_EQ(to_string(FaceSampling::MonteCarlo), "montecarlo");
}

TEST(SmoothingJson, HasTheSchemaAndConsistentSizes)
{
    const auto j = smoothing(SmoothingMethod::Laplacian, false, true);
    EXPECT_EQ(j["schema"], "meshdiff.smoothing/1");
    EXPECT_EQ(j["input"], "in.ply");
    EXPECT_EQ(j["output"], "out.ply");
    EXPECT_EQ(j["method"], "laplacian");
    EXPECT_EQ(j["levels"], nlohmann::json({1, 3}));
    EXPECT_EQ(j["iterations"], nlohmann::json({0, 2, 4, 5}));
    ASSERT_EQ(j["sigma"].size(), 4u);
    for (const auto& s : j["sigma"]) EXPECT_EQ(s.size(), 2u);
    EXPECT_EQ(j["sigma_global"].size(), 4u);
    EXPECT_EQ(j["curvature_undefined"].size(), 4u);
    ASSERT_EQ(j["distance_to_input"].size(), 4u);
    EXPECT_LT(j["distance_to_input"][0]["hausdorff_relative"].get<double>(), 1e-12);
    EXPECT_FALSE(j.contains("flow"));  // not an explicit flow
    EXPECT_TRUE(all_finite(j));
}

TEST(SmoothingJson, FlowOnlyForExplicitFlowsAndDistanceOnlyWhenRecorded)
{
    const auto mcf = smoothing(SmoothingMethod::MeanCurvatureFlow, false, false);
    ASSERT_TRUE(mcf.contains("flow"));
    EXPECT_EQ(mcf["flow"]["time"].size(), mcf["iterations"].size());
    EXPECT_EQ(mcf["flow"]["steps"].size(), 5u);
    EXPECT_EQ(mcf["flow"]["stability_ratio"].size(), 5u);
    EXPECT_FALSE(mcf.contains("distance_to_input"));
    EXPECT_TRUE(smoothing(SmoothingMethod::ModifiedMeanCurvatureFlow, false, false).contains("flow"));
    EXPECT_FALSE(smoothing(SmoothingMethod::MeanCurvatureFlow, true, false).contains("flow"));  // implicit
    EXPECT_FALSE(smoothing(SmoothingMethod::Taubin, false, false).contains("flow"));
}

TEST(BatchJson, OkAndErrorLinesHaveTheirKeys)
{
    const LoadedMesh a = read_mesh(data("hemisphere.ply"));
    CompareOptions o;
    o.roughness = false;
    o.sampling.samples = 5000;
    const auto ok = batch_ok_json("p1", "a.ply", "b.ply", compare_meshes(a, a, o));
    EXPECT_EQ(keys(ok), (std::vector<std::string>{"id", "original", "processed", "result", "status"}));
    EXPECT_EQ(ok["status"], "ok");
    EXPECT_EQ(ok["id"], "p1");
    EXPECT_EQ(ok["result"]["schema"], "meshdiff.compare/2");
    const auto err = batch_error_json("p2", "a.ply", "missing.ply", "missing.ply: cannot open", 3);
    EXPECT_EQ(keys(err), (std::vector<std::string>{"error", "exit_code", "id", "original", "processed", "status"}));
    EXPECT_EQ(err["status"], "error");
    EXPECT_EQ(err["processed"], "missing.ply");
    EXPECT_EQ(err["error"], "missing.ply: cannot open");
    EXPECT_EQ(err["exit_code"], 3);
}

TEST(WarningsJson, IsTheTextsInOrder)
{
    const std::vector<Warning> w = {{WarningKind::OpenSurface, -1, 3.0, "open"},
                                    {WarningKind::Components, -1, 2.0, "two parts"},
                                    {WarningKind::NoDefinedD, 4, 0.0, "level 4: none"}};
    EXPECT_EQ(warnings_json(w), nlohmann::json({"open", "two parts", "level 4: none"}));
    EXPECT_EQ(warnings_json({}), nlohmann::json::array());
}

TEST(ExactProfileJson, HasTheExactSigmasAndASmallHError)
{
    const Shape torus_shape = torus(128, 32);
    ProfileOptions o;
    o.levels = {1, 2, 4};
    o.keep_vertex_data = true;
    const RoughnessProfile estimated = roughness_profile(torus_shape.mesh, o);
    const ExactProfile exact = exact_profile(torus_shape.mesh, torus_shape.exact_H, o, estimated);
    const auto j = exact_profile_json(estimated, exact, "exact_H");
    EXPECT_EQ(j["property"], "exact_H");
    EXPECT_EQ(j["levels"], nlohmann::json({1, 2, 4}));
    ASSERT_EQ(j["sigma"].size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(j["sigma"][k].get<double>(), exact.profile.levels[k].sigma);
    EXPECT_EQ(j["sigma_global"].get<double>(), exact.profile.global.sigma);
    EXPECT_EQ(j["undefined_vertices"], 0);
    const auto& e = j["h_error"];
    ASSERT_TRUE(e.contains("rms") && e.contains("max") && e.contains("vertices"));
    EXPECT_EQ(e["vertices"], torus_shape.mesh.n_vertices());
    EXPECT_EQ(e["rms"].get<double>(), exact.h_error.rms);
    // The scaled exact H spans [1.35, 2.44] on this torus; the cubic fit is within 2% of it.
    EXPECT_GT(e["rms"].get<double>(), 0.0);
    EXPECT_LT(e["rms"].get<double>(), 0.04);
    EXPECT_LE(e["rms"].get<double>(), e["max"].get<double>());
    EXPECT_TRUE(all_finite(j));
}

TEST(CompareJson, IdenticalPlanesGiveNullPsnrNeverInfinity)
{
    // A flat grid against itself: every face sample lies in the plane z = 0,
    // so the area-weighted mean square is 0 exactly and its PSNR infinite:
    // null in JSON (edge samples, rounded in x and y, get distances of 1e-17,
    // so the Hausdorff PSNR stays finite).
    LoadedMesh a;
    a.mesh = plane_grid(6, 6, 0.2).mesh;
    a.input.path = "plane.ply";
    CompareOptions o;
    o.roughness = false;
    o.summary.fscore_thresholds = {0.01};
    o.summary.histogram_bins = 3;
    const Comparison c = compare_meshes(a, a, o);
    ASSERT_TRUE(c.distance && c.distance->summary);
    EXPECT_EQ(c.distance->summary->psnr.mse, 0.0);
    const nlohmann::json j = comparison_json(c);
    const nlohmann::json& sd = j["surface_distance"];
    EXPECT_TRUE(all_finite(j));
    EXPECT_TRUE(sd["psnr"]["mse_db"].is_null());
    EXPECT_GT(sd["psnr"]["hausdorff_db"].get<double>(), 300.0);
    EXPECT_EQ(sd["psnr"]["factor"], 3.0);
    EXPECT_EQ(sd["chamfer"]["l1"], 0.0);
    EXPECT_EQ(sd["fscore"][0]["fscore"], 1.0);
    EXPECT_EQ(keys(sd["fscore"][0]),
              (std::vector<std::string>{"fscore", "precision", "recall", "threshold", "threshold_absolute"}));
    std::size_t total = 0;
    for (const auto& n : sd["forward"]["histogram"]["counts"]) total += n.get<std::size_t>();
    EXPECT_EQ(total, sd["forward"]["samples"].get<std::size_t>());
    EXPECT_TRUE(sd["summary_unavailable"].is_null());
    EXPECT_EQ(j["same_connectivity"]["displacement"]["max"], 0.0);
    EXPECT_EQ(j["same_connectivity"]["normal_deviation_deg"]["max"], 0.0);
    EXPECT_TRUE(j["same_connectivity_unavailable"].is_null());
}

TEST(CompareJson, SummaryAndSameConnectivityGiveTheirReasonsWhenUnavailable)
{
    const LoadedMesh a = read_mesh(data("bunny_res3.ply"));
    const LoadedMesh b = read_mesh(data("bunny_res4_ascii.ply"));
    CompareOptions o;
    o.roughness = false;
    o.sampling.faces = false;
    o.summary.fscore_thresholds = {0.01};
    const nlohmann::json j = comparison_json(compare_meshes(a, b, o));
    const nlohmann::json& sd = j["surface_distance"];
    for (const char* k : {"chamfer", "fscore", "psnr"}) EXPECT_TRUE(sd[k].is_null()) << k;
    EXPECT_TRUE(sd["forward"]["area_weighted"].is_null());
    EXPECT_FALSE(sd["forward"].contains("histogram"));
    EXPECT_NE(sd["summary_unavailable"].get<std::string>().find("no face sample"), std::string::npos);
    EXPECT_TRUE(j["same_connectivity"].is_null());
    EXPECT_EQ(j["same_connectivity_unavailable"], "vertex counts differ (1887 vs 453)");
    EXPECT_TRUE(all_finite(j));
}

TEST(CorsiniJson, OnlyWithTheCorsiniMeasureAndOnlyFiniteNumbers)
{
    const LoadedMesh a = read_mesh(data("sphere_ico_2562.ply"));
    const LoadedMesh b = read_mesh(data("ellipsoid_150_100_100.ply"));
    CompareOptions o;
    o.profile.levels = {1, 4};
    o.distance = false;
    const auto plain = comparison_json(compare_meshes(a, b, o));
    EXPECT_FALSE(plain.contains("measure") || plain.contains("corsini_distance") ||
                 plain["original"].contains("corsini"));
    o.measure = RoughnessMeasure::Corsini;
    const Comparison c = compare_meshes(a, b, o);
    const auto j = comparison_json(c);
    EXPECT_EQ(j["measure"], "corsini");
    EXPECT_TRUE(j["roughness_distance"].is_null());
    EXPECT_EQ(j["original"]["corsini"]["levels"], nlohmann::json({1, 4}));
    EXPECT_EQ(j["processed"]["corsini"]["roughness"][1], c.processed_corsini->levels[1].roughness);
    EXPECT_EQ(j["corsini_distance"]["multiscale"]["distance"], c.corsini->multiscale.distance);
    EXPECT_TRUE(all_finite(j));
    const auto p = corsini_profile_json(mesh_facts(a), *c.original_corsini);
    EXPECT_EQ(p["schema"], "meshdiff.corsini/1");
    EXPECT_EQ(p["corsini"], j["original"]["corsini"]);
}
