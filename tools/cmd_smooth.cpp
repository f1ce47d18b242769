#include "commands.h"
#include "meshdiff/error.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/io/io.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/outputs.h"
#include "meshdiff/report/text.h"
#include "meshdiff/studies/smoothing.h"
#include "meshdiff/studies/smoothing_record.h"
#include "options.h"

#include <fmt/format.h>

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
    Given threads;
    bool no_distance = false;  // do not record the surface distance to the input
    Given distance_samples;    // samples per direction of the recorded distance; not given: compare's default
};

int run_smooth(const SmoothArgs& a)
{
    SmoothingOptions options = a.options;
    options.method = parse_enum_option<SmoothingMethod>("smooth.method", a.method);
    options.update = parse_enum_option<SmoothingUpdate>("smooth.update", a.update);
    options.step_control = parse_enum_option<StepControl>("smooth.step_control", a.step_control);
    validate(options);
    check_recording(a.profile_every, !a.json.empty());
    refuse_overwriting_inputs("OUT", a.out, {a.in});
    refuse_overwriting_inputs("--json", a.json, {a.in, a.out});
    const bool record = !a.json.empty();
    set_threads(a.threads);  // the smoothing itself is parallel too
    RecordOptions record_options;
    if (record) {
        record_options.every = a.profile_every;
        record_options.profile = to_profile_options(a.profile, record_profile_defaults());
        record_options.distance = !a.no_distance;
        if (a.distance_samples.given()) {
            record_options.sampling.samples = parse_whole_number("record.sampling.samples", a.distance_samples.text);
            try {
                validate(record_options.sampling);
            } catch (const OptionError& e) {
                throw OptionError("record.sampling.samples", e.problem());
            }
        }
    }
    LoadedMesh loaded = read_mesh(a.in);
    SmoothingRecord recording;
    if (record)
        recording = smooth_and_record(loaded.mesh, options, record_options);
    else
        recording.report = smooth(loaded.mesh, options);
    // Both outputs at once at the end, or none (a failing run leaves nothing behind).
    StagedOutputs staged;
    write_mesh(a.out, loaded.mesh);
    nlohmann::json j;
    if (record) j = smoothing_json(recording, options, record_options, a.in, a.out);
    if (record && a.json != "-") write_json_file(a.json, j);
    staged.commit();
    if (record && a.json == "-") write_json_file("-", j);
    if (a.json != "-") {
        std::cout << smoothing_text(a.out, options, loaded.mesh.n_vertices(), recording.report);
        if (const auto warning = smoothing_warning(a.in, options, recording.report)) std::cerr << *warning;
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
        ->check(CLI::IsMember(enum_names<SmoothingMethod>()))
        ->capture_default_str();
    sub->add_option("--update", args->update,
                    "post (Jacobi, from the previous positions) | pre (Gauss-Seidel, in "
                    "place in vertex order)")
        ->check(CLI::IsMember(enum_names<SmoothingUpdate>()))
        ->capture_default_str();
    SmoothingOptions& o = args->options;
    sub->add_option("--iterations", o.iterations, "iterations (a Taubin iteration is a lambda and a mu step)")
        ->capture_default_str();
    sub->add_option("--lambda", o.lambda, "Laplacian / Taubin step, in (0, 1]")->capture_default_str();
    sub->add_option("--mu", o.mu, "Taubin negative step, < -lambda")->capture_default_str();
    sub->add_option("--step", o.step, "mcf / modified-mcf time step in units of the squared mean edge length")
        ->capture_default_str();
    sub->add_option("--step-control", args->step_control,
                    "explicit mcf / modified-mcf: fixed (always --step; may diverge; the default step 0.1 is our "
                    "choice, the paper gives no step and its reference [4] uses implicit fairing) | adaptive (shorten "
                    "a step beyond the stability bound)")
        ->check(CLI::IsMember(enum_names<StepControl>()))
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
    args->distance_samples.option =
        sub->add_option("--distance-samples", args->distance_samples.text,
                        "samples per direction of the recorded surface distance (default: 10 x the face count, as "
                        "compare)")
            ->type_name("UINT");
    sub->add_option("--profile-every", args->profile_every,
                    "record the roughness profile at iteration 0 and every K iterations (and the last); needs --json")
        ->capture_default_str();
    sub->add_option("--json", args->json,
                    "write the recorded profiles (schema meshdiff.smoothing/1) to FILE, or '-' for stdout; "
                    "without --profile-every only the first and last iterations are recorded");
    add_profile_options(sub, args->profile, false, false, record_profile_defaults());
    add_threads_option(sub, args->threads);
    sub->callback([args, &action] { action = [args] { return run_smooth(*args); }; });
}

}  // namespace meshdiff::cli
