#include "commands.h"
#include "meshdiff/colormap.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/report.h"
#include "meshdiff/roughness.h"
#include "options.h"

#include <fmt/format.h>

#include <cmath>
#include <future>
#include <iostream>
#include <memory>

namespace meshdiff::cli {

namespace {

struct ProfileArgs
{
    std::string mesh;
    ProfileCliOptions profile;
    std::string json;
    std::string vertex_data;
    double color_range = 0.0;
    int threads = 0;
    bool exact = false;
    std::string exact_property = "exact_H";
};

// The profile from a given per-vertex H beside the estimated one, and the
// error of the estimate, as text and JSON.
struct ExactComparison
{
    RoughnessProfile profile;
    double h_rms = 0.0, h_max = 0.0;
    std::size_t compared = 0;
};

ExactComparison exact_comparison(const LoadedMesh& loaded, const std::string& property, const ProfileOptions& base,
                                 const RoughnessProfile& estimated)
{
    const VertexScalar* H = nullptr;
    for (const auto& s : loaded.vertex_scalars)
        if (s.name == property) H = &s;
    if (!H)
        throw InvalidArgumentError(
            fmt::format("--exact: {} has no vertex property '{}' (meshdiff generate writes "
                        "exact_H)",
                        loaded.input.path, property));
    ProfileOptions o = base;
    o.keep_vertex_data = true;
    ExactComparison e;
    e.profile = roughness_profile_from_curvature(loaded.mesh, H->values, o);
    double sum = 0.0;
    for (std::size_t i = 0; i < estimated.H.size(); ++i) {
        const double d = estimated.H[i] - e.profile.H[i];
        if (std::isnan(d)) continue;
        sum += d * d;
        e.h_max = std::max(e.h_max, std::abs(d));
        ++e.compared;
    }
    e.h_rms = e.compared ? std::sqrt(sum / double(e.compared)) : 0.0;
    return e;
}

int run_profile(const ProfileArgs& a)
{
    set_threads(a.threads);
    if (a.color_range < 0.0) throw InvalidArgumentError("--color-range must be > 0");
    const ProfileOptions options = to_profile_options(a.profile, !a.vertex_data.empty() || a.exact);
    const LoadedMesh loaded = read_mesh(a.mesh);
    // The topology report is serial; it overlaps the serial stages of the
    // profile (normalisation, adjacency, normals) on another thread.
    auto facts_future = std::async(std::launch::async, [&loaded] { return mesh_facts(loaded); });
    const RoughnessProfile profile = roughness_profile(loaded.mesh, options);
    const MeshFacts facts = facts_future.get();

    if (!a.vertex_data.empty()) {
        const Mesh unit = apply_normalization(loaded.mesh, profile.normalization);
        std::vector<VertexScalar> props;
        props.push_back({"H", profile.H});
        for (std::size_t k = 0; k < profile.levels.size(); ++k)
            props.push_back({fmt::format("D_{}", profile.levels[k].level), profile.D[k]});
        if (profile.has_global) props.push_back({"D_global", profile.D_global});
        std::vector<double> worst(unit.n_vertices(), 0.0);
        std::vector<std::string> comments;
        auto mark = [&](const LevelRoughness& l, const std::string& name) {
            std::string ids;
            for (auto v : l.worst_vertices) {
                worst[v] = 1.0;
                ids += fmt::format(" {}", v);
            }
            comments.push_back(fmt::format("worst |D| vertices at {}:{}", name, ids));
        };
        for (const auto& l : profile.levels) mark(l, fmt::format("level {}", l.level));
        if (profile.has_global) mark(profile.global, "global");
        props.push_back({"worst", worst});
        const double range = a.color_range > 0.0 ? a.color_range : robust_symmetric_range(profile.H);
        comments.insert(comments.begin(),
                        fmt::format("colour: H on a blue-white-red map over [-{:.6g}, {:.6g}]", range, range));
        comments.insert(comments.begin(), fmt::format("source: {} scaled by 1/{:.9g} about its centroid", a.mesh,
                                                      profile.normalization.scale));
        write_ply(a.vertex_data, unit, props, diverging_colors(profile.H, range), comments);
    }
    nlohmann::json j = profile_json(facts, profile);
    std::string text = profile_text(facts, profile);
    if (a.exact) {
        const ExactComparison e = exact_comparison(loaded, a.exact_property, options, profile);
        nlohmann::json sigma = nlohmann::json::array();
        text += fmt::format(
            "\nexact profile from the vertex property '{}' (H error of the estimate on the scaled "
            "mesh: RMS {:.4g}, max {:.4g} over {} vertices)\n   level  sigma estimated  sigma exact\n",
            a.exact_property, e.h_rms, e.h_max, e.compared);
        for (std::size_t k = 0; k < profile.levels.size(); ++k) {
            sigma.push_back(e.profile.levels[k].sigma);
            text += fmt::format("{:>8} {:>16.6g} {:>12.6g}\n", profile.levels[k].level, profile.levels[k].sigma,
                                e.profile.levels[k].sigma);
        }
        if (profile.has_global)
            text += fmt::format("{:>8} {:>16.6g} {:>12.6g}\n", "global", profile.global.sigma, e.profile.global.sigma);
        j["exact"] = {
            {"property", a.exact_property},
            {"levels", j["levels"]},
            {"sigma", sigma},
            {"sigma_global", e.profile.has_global ? nlohmann::json(e.profile.global.sigma) : nlohmann::json(nullptr)},
            {"undefined_vertices", e.profile.curvature_undefined},
            {"h_error", {{"rms", e.h_rms}, {"max", e.h_max}, {"vertices", e.compared}}}};
    }
    if (!a.json.empty()) write_json(a.json, j);
    if (a.json != "-") std::cout << text;
    return 0;
}

}  // namespace

void add_profile_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<ProfileArgs>();
    auto* sub = app.add_subcommand("profile", "roughness profile of one mesh");
    sub->add_option("MESH", args->mesh, "mesh file (.ply .obj .off .stl)")->required();
    add_profile_options(sub, args->profile);
    sub->add_option("--json", args->json, "write the JSON report to FILE, or '-' for stdout");
    sub->add_option("--vertex-data", args->vertex_data,
                    "write the normalised mesh with per-vertex H, D_L and an H colour map as PLY");
    sub->add_option("--color-range", args->color_range,
                    "fix the symmetric H colour range [-R, R] (default: 95th percentile of |H|)");
    sub->add_flag("--exact", args->exact,
                  "also compute the profile from a per-vertex H stored in the PLY (the true profile of a generated "
                  "surface) and the error of the estimated H");
    sub->add_option("--exact-property", args->exact_property, "the PLY vertex property holding the exact H")
        ->capture_default_str();
    sub->add_option("--threads", args->threads, "worker threads (0: all cores)")->capture_default_str();
    sub->callback([args, &action] { action = [args] { return run_profile(*args); }; });
}

}  // namespace meshdiff::cli
