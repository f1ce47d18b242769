#include "commands.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/roughness.h"
#include "meshdiff/smoothing.h"
#include "meshdiff/surface_distance.h"
#include "options.h"

#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace meshdiff::cli {

namespace {

struct SmoothArgs
{
    std::string in;
    std::string out;
    std::string method = "laplacian";
    std::string update = "post";
    std::string step_control = "fixed";
    SmoothingOptions options;  // numeric fields bound to the options below
    int profile_every = 0;     // 0: no profile recording
    std::string json;          // profile recording target ("-" for stdout)
    ProfileCliOptions profile;
    int threads = 0;
    bool no_distance = false;          // do not record the surface distance to the input
    std::size_t distance_samples = 0;  // samples per direction of the recorded distance; 0: compare's default
};

// Roughness profiles recorded during smoothing, as the JSON document
// meshdiff.smoothing/1.
struct Recording
{
    std::vector<int> iterations;
    std::vector<std::vector<double>> sigma;  // per recorded iteration, per level
    std::vector<double> sigma_global;
    std::vector<std::size_t> undefined;                 // vertices with undefined H
    nlohmann::json distance = nlohmann::json::array();  // surface distance to the input, per record
};

nlohmann::json recording_json(const SmoothArgs& a, const SmoothingOptions& o, const ProfileOptions& p,
                              const Recording& r, const SmoothingReport& report)
{
    nlohmann::json j;
    j["schema"] = "meshdiff.smoothing/1";
    j["input"] = a.in;
    j["output"] = a.out;
    j["method"] = smoothing_method_name(o.method);
    j["update"] = smoothing_update_name(o.update);
    j["parameters"] = {{"iterations", o.iterations},
                       {"lambda", o.lambda},
                       {"mu", o.mu},
                       {"step", o.step},
                       {"damping", o.damping},
                       {"epsilon", o.epsilon},
                       {"implicit", o.implicit},
                       {"step_control", step_control_name(o.step_control)},
                       {"stability", o.stability}};
    j["curvature"] = to_string(p.curvature.method);
    j["profile_every"] = a.profile_every;
    j["iterations"] = r.iterations;
    j["levels"] = p.levels;
    j["sigma"] = r.sigma;
    j["sigma_global"] = r.sigma_global;
    j["curvature_undefined"] = r.undefined;
    if (!r.distance.empty()) j["distance_to_input"] = r.distance;
    if (!report.steps.empty()) {
        // Flow time at each recorded iteration, in units of the initial mean edge length squared.
        std::vector<double> time;
        for (int k : r.iterations) {
            double t = 0;
            for (std::size_t i = 0; i < std::size_t(k) && i < report.steps.size(); ++i) t += report.steps[i];
            time.push_back(t);
        }
        j["flow"] = {{"mean_edge", report.mean_edge},
                     {"time", time},
                     {"steps", report.steps},
                     {"stability_ratio", report.stability_ratio},
                     {"unstable_iterations", report.unstable_iterations}};
    }
    return j;
}

int run_smooth(const SmoothArgs& a)
{
    SmoothingOptions options = a.options;
    options.method = parse_smoothing_method(a.method);
    options.update = parse_smoothing_update(a.update);
    options.step_control = parse_step_control(a.step_control);
    if (a.profile_every < 0)
        throw InvalidArgumentError(fmt::format("--profile-every must be >= 1 (got {})", a.profile_every));
    if (a.profile_every > 0 && a.json.empty()) throw InvalidArgumentError("--profile-every needs --json FILE");
    const bool record = !a.json.empty();
    ProfileOptions profile_options;
    Recording recording;
    if (record) {
        set_threads(a.threads);
        profile_options = to_profile_options(a.profile, false);
        // Every K iterations, or only at the start and the end.
        const int every = a.profile_every > 0 ? a.profile_every : std::max(1, options.iterations);
        const int last = options.iterations;
        options.callback = [&, every, last](int k, const Mesh& mesh) {
            if (k % every != 0 && k != last) return;
            const RoughnessProfile p = roughness_profile(mesh, profile_options);
            recording.iterations.push_back(k);
            std::vector<double> sigma;
            for (const auto& l : p.levels) sigma.push_back(l.sigma);
            recording.sigma.push_back(std::move(sigma));
            if (p.has_global) recording.sigma_global.push_back(p.global.sigma);
            recording.undefined.push_back(p.curvature_undefined);
        };
    }
    LoadedMesh loaded = read_mesh(a.in);
    if (record && !a.no_distance) {
        // Metro-style distance of each recorded state to the input surface.
        auto profile_callback = options.callback;
        const Mesh input = loaded.mesh;
        const int every = a.profile_every > 0 ? a.profile_every : std::max(1, options.iterations);
        const int last = options.iterations;
        SamplingOptions sampling;
        if (a.distance_samples > 0) sampling.samples = a.distance_samples;
        options.callback = [&recording, profile_callback, input, every, last, sampling](int k, const Mesh& mesh) {
            profile_callback(k, mesh);
            if (k % every != 0 && k != last) return;
            const SurfaceDistance d = surface_distance(input, mesh, sampling);
            recording.distance.push_back(
                {{"hausdorff", d.hausdorff},
                 {"hausdorff_relative", d.hausdorff / d.diagonal},
                 {"forward", {{"max", d.forward.max}, {"mean", d.forward.mean}, {"rms", d.forward.rms}}},
                 {"backward", {{"max", d.backward.max}, {"mean", d.backward.mean}, {"rms", d.backward.rms}}},
                 {"diagonal", d.diagonal},
                 {"samples", d.forward.n_samples()}});
        };
    }
    const SmoothingReport report = smooth(loaded.mesh, options);
    write_mesh(a.out, loaded.mesh);
    if (record) write_json(a.json, recording_json(a, options, profile_options, recording, report));
    if (a.json != "-") {
        std::cout << fmt::format("{}: {} {}-updating, {} iterations, {} vertices\n", a.out, a.method, a.update,
                                 options.iterations, loaded.mesh.n_vertices());
        if (!report.steps.empty()) {
            const double worst = *std::max_element(report.stability_ratio.begin(), report.stability_ratio.end());
            std::cout << fmt::format("flow time {:.6g} e^2 (e = {:.6g}, the initial mean edge length)\n", report.time,
                                     report.mean_edge);
            if (report.unstable_iterations > 0)
                std::cerr << fmt::format(
                    "warning: {}: {} of {} explicit steps exceeded the stability bound (up to {:.3g} times); the flow "
                    "may diverge: use a smaller --step, --step-control adaptive or --implicit (mcf)\n",
                    a.in, report.unstable_iterations, options.iterations, worst);
        }
    }
    return 0;
}

}  // namespace

void add_smooth_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<SmoothArgs>();
    auto* sub =
        app.add_subcommand("smooth", "smooth a mesh (boundary vertices fixed) with one of the paper's five methods");
    sub->add_option("IN", args->in, "input mesh (.ply .obj .off .stl)")->required();
    sub->add_option("OUT", args->out, "output mesh (.ply .obj .off .stl)")->required();
    sub->add_option("--method", args->method, "laplacian | taubin | bilaplacian | mcf | modified-mcf")
        ->capture_default_str();
    sub->add_option("--update", args->update,
                    "post (Jacobi, from the previous positions) | pre (Gauss-Seidel, in "
                    "place in vertex order)")
        ->capture_default_str();
    SmoothingOptions& o = args->options;
    sub->add_option("--iterations", o.iterations, "iterations (a Taubin iteration is a lambda and a mu step)")
        ->capture_default_str();
    sub->add_option("--lambda", o.lambda, "Laplacian / Taubin step, in (0, 1]")->capture_default_str();
    sub->add_option("--mu", o.mu, "Taubin negative step, < -lambda")->capture_default_str();
    sub->add_option("--step", o.step, "mcf / modified-mcf time step in units of the squared mean edge length")
        ->capture_default_str();
    sub->add_option("--step-control", args->step_control,
                    "explicit mcf / modified-mcf: fixed (always --step, the paper's scheme; may diverge) | adaptive "
                    "(shorten a step beyond the stability bound)")
        ->capture_default_str();
    sub->add_option("--stability", o.stability,
                    "adaptive step control: fraction of the largest stable explicit step, in (0, 1]")
        ->capture_default_str();
    sub->add_flag("--implicit", o.implicit,
                  "mcf only: backward-Euler steps (Desbrun et al.), stable for large --step (up to 1000)");
    sub->add_option("--damping", o.damping, "bilaplacian relaxation factor, in (0, 1]")->capture_default_str();
    sub->add_option("--epsilon", o.epsilon,
                    "modified-mcf: vertices whose umbrella is within acos(eps) of "
                    "perpendicular to the curvature normal do not move")
        ->capture_default_str();
    sub->add_flag("--no-distance", args->no_distance,
                  "do not record the surface distance to the input beside each recorded profile");
    sub->add_option("--distance-samples", args->distance_samples,
                    "samples per direction of the recorded surface distance (default: 10 x the face count, as "
                    "compare)");
    sub->add_option("--profile-every", args->profile_every,
                    "record the roughness profile at iteration 0 and every K iterations (and the last); needs --json");
    sub->add_option("--json", args->json,
                    "write the recorded profiles (schema meshdiff.smoothing/1) to FILE, or '-' for stdout; "
                    "without --profile-every only the first and last iterations are recorded");
    args->profile.levels = "1,5,10,20";
    add_profile_options(sub, args->profile);
    sub->add_option("--threads", args->threads, "worker threads of the profile (0: all cores)")->capture_default_str();
    sub->callback([args, &action] { action = [args] { return run_smooth(*args); }; });
}

}  // namespace meshdiff::cli
