#include "commands.h"
#include "meshdiff/colormap.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/report.h"
#include "meshdiff/roughness.h"
#include "options.h"

#include <fmt/format.h>

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
};

int run_profile(const ProfileArgs& a)
{
    set_threads(a.threads);
    if (a.color_range < 0.0) throw InvalidArgumentError("--color-range must be > 0");
    const ProfileOptions options = to_profile_options(a.profile, !a.vertex_data.empty());
    const LoadedMesh loaded = read_mesh(a.mesh);
    const MeshFacts facts = mesh_facts(loaded);
    const RoughnessProfile profile = roughness_profile(loaded.mesh, options);

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
    if (!a.json.empty()) write_json(a.json, profile_json(facts, profile));
    if (a.json != "-") std::cout << profile_text(facts, profile);
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
    sub->add_option("--threads", args->threads, "worker threads (0: all cores)")->capture_default_str();
    sub->callback([args, &action] { action = [args] { return run_profile(*args); }; });
}

}  // namespace meshdiff::cli
