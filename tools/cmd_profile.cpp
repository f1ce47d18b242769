#include "commands.h"
#include "interrupt.h"
#include "meshdiff/corsini.h"
#include "meshdiff/error.h"
#include "meshdiff/facts.h"
#include "meshdiff/io.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"
#include "meshdiff/roughness.h"
#include "meshdiff/vertex_maps.h"
#include "options.h"
#include "progress_display.h"

#include <fmt/format.h>
#include <omp.h>

#include <future>
#include <iostream>
#include <memory>

namespace meshdiff::cli {

namespace {

// The topology report runs on a thread of its own, unless --threads 1.
std::launch facts_policy()
{
    return omp_get_max_threads() > 1 ? std::launch::async : std::launch::deferred;
}

struct ProfileArgs
{
    std::string mesh;
    ProfileCliOptions profile;
    std::string json;
    std::string vertex_data;
    double color_range = 0.0;
    int threads = 0;
    ProgressCliOptions progress;
    bool exact = false;
    std::string exact_property = "exact_H";
};

// profile --measure corsini: Corsini et al.'s roughness (corsini.h).
int run_corsini(const ProfileArgs& a)
{
    if (!a.vertex_data.empty() || a.exact || a.color_range > 0.0)
        throw InvalidArgumentError("--vertex-data, --exact and --color-range need --measure sigma");
    const CorsiniOptions options = to_corsini_options(a.profile);
    ProgressDisplay progress(a.progress);
    progress.stage("reading", 1);
    const LoadedMesh loaded = read_mesh(a.mesh);
    progress.advance(1);
    auto facts_future = std::async(facts_policy(), [&loaded, &progress] {
        const ProgressScope in_this_thread(&progress);  // it stops on Ctrl-C too
        return mesh_facts(loaded);
    });
    progress.stage("corsini", 1);
    const CorsiniProfile profile = corsini_profile(loaded.mesh, options);
    progress.advance(1);
    const MeshFacts facts = facts_future.get();
    check_cancelled(&progress);  // once interrupted, nothing is written
    progress.finish();
    if (!a.json.empty()) write_json(a.json, corsini_profile_json(facts, profile));
    if (a.json != "-") std::cout << corsini_profile_text(facts, profile);
    return 0;
}

int run_profile(const ProfileArgs& a)
{
    set_threads(a.threads);
    install_interrupt_handlers();
    for (const auto& [what, out] : {std::pair{"--json", a.json}, {"--vertex-data", a.vertex_data}})
        refuse_overwriting_inputs(what, out, {a.mesh});
    if (a.color_range < 0.0) throw InvalidArgumentError("--color-range must be > 0");
    if (parse_enum<RoughnessMeasure>(a.profile.measure) == RoughnessMeasure::Corsini) return run_corsini(a);
    if (a.profile.unbiased_variance) throw InvalidArgumentError("--unbiased-variance needs --measure corsini");
    ProfileOptions options = to_profile_options(a.profile, !a.vertex_data.empty() || a.exact);
    ProgressDisplay progress(a.progress);
    options.progress = &progress;
    progress.stage("reading", 1);
    const LoadedMesh loaded = read_mesh(a.mesh);
    progress.advance(1);
    check_cancelled(&progress);
    // The topology report is serial; it overlaps the serial stages of the
    // profile (normalisation, adjacency, normals) on another thread.
    auto facts_future = std::async(facts_policy(), [&loaded, &progress] {
        const ProgressScope in_this_thread(&progress);  // it stops on Ctrl-C too
        return mesh_facts(loaded);
    });
    const RoughnessProfile profile = roughness_profile(loaded.mesh, options);
    const MeshFacts facts = facts_future.get();

    if (!a.vertex_data.empty())
        write_ply(a.vertex_data, apply_normalization(loaded.mesh, profile.normalization),
                  profile_map(profile, a.mesh, a.color_range));
    nlohmann::json j = profile_json(facts, profile);
    std::string text = profile_text(facts, profile);
    if (a.exact) {
        const VertexScalar* H = nullptr;
        try {
            H = &vertex_scalar(loaded, a.exact_property);
        } catch (const InvalidArgumentError& e) {
            throw InvalidArgumentError(fmt::format("--exact: {} (meshdiff generate writes exact_H)", e.what()));
        }
        const ExactProfile e = exact_profile(loaded.mesh, H->values, options, profile);
        text += exact_profile_text(profile, e, a.exact_property);
        j["exact"] = exact_profile_json(profile, e, a.exact_property);
    }
    check_cancelled(&progress);  // once interrupted, nothing is written
    progress.finish();
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
    add_measure_options(sub, args->profile);
    sub->add_option("--json", args->json, "write the JSON report to FILE, or '-' for stdout");
    sub->add_option("--vertex-data", args->vertex_data,
                    "write the normalised mesh with per-vertex H, D_L and an H colour map as PLY");
    sub->add_option("--color-range", args->color_range,
                    "fix the symmetric H colour range [-R, R] (default: 95th percentile of |H|)")
        ->check(in_range(0, 1e300));
    sub->add_flag("--exact", args->exact,
                  "also compute the profile from a per-vertex H stored in the PLY (the true profile of a generated "
                  "surface) and the error of the estimated H");
    sub->add_option("--exact-property", args->exact_property, "the PLY vertex property holding the exact H")
        ->capture_default_str();
    sub->add_option("--threads", args->threads, "worker threads (0: all cores)")->capture_default_str();
    add_progress_options(sub, args->progress);
    sub->callback([args, &action] { action = [args] { return run_profile(*args); }; });
}

}  // namespace meshdiff::cli
