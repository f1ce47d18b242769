#include "cli.h"
#include "commands.h"
#include "interrupt.h"
#include "meshdiff/error.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/io/io.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/outputs.h"
#include "meshdiff/report/text.h"
#include "meshdiff/roughness/roughness.h"
#include "options.h"
#include "progress_display.h"

#include <fmt/format.h>
#include <omp.h>

#include <iostream>
#include <memory>

namespace meshdiff::cli {

namespace {

struct ProfileArgs
{
    std::string mesh;
    ProfileCliOptions profile;
    ProfileRequest request;  // outputs bound to the options below
    Given color_range;
    Given html_face_budget;
    Given threads;
    ProgressCliOptions progress;
};

int run_profile(const ProfileArgs& a)
{
    set_threads(a.threads);
    install_interrupt_handlers();
    ProfileRequest r = a.request;
    r.command = command_line();
    r.measure = to_measure(a.profile);
    r.corsini_unbiased = a.profile.unbiased_variance;
    r.profile = to_profile_options(a.profile);
    if (a.color_range.given()) r.color_range = parse_number("outputs.color_range", a.color_range.text);
    r.html_face_budget = html_face_budget(a.html_face_budget);
    validate(r, {a.mesh});
    ProgressDisplay progress(a.progress);
    r.profile.progress = &progress;
    const ProgressScope scope(&progress);
    progress.stage("reading", 1);
    const LoadedMesh loaded = read_mesh(a.mesh);
    progress.advance(1);
    check_cancelled(&progress);
    // Every output file at once at the end, or none (a failing run leaves nothing behind).
    StagedOutputs staged;
    const ProfileReport report = profile_report(loaded, r);
    check_cancelled(&progress);  // once interrupted, nothing is written
    progress.finish();
    if (!r.json.empty() && r.json != "-") write_json_file(r.json, report.json);
    staged.commit();
    if (r.json == "-")
        write_json_file("-", report.json);
    else
        std::cout << report.text;
    return 0;
}

}  // namespace

void add_profile_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<ProfileArgs>();
    auto* sub = app.add_subcommand("profile", "roughness profile of one mesh");
    sub->add_option("MESH", args->mesh, "mesh file (.ply .obj .off .stl)")->required();
    add_profile_options(sub, args->profile);
    sub->add_option("--json", args->request.json, "write the JSON report to FILE, or '-' for stdout");
    sub->add_option("--vertex-data", args->request.vertex_data,
                    "write the normalised mesh with per-vertex H, D_L and an H colour map as PLY");
    sub->add_option("--html", args->request.html,
                    "write the HTML report to FILE: one self-contained page with the profile and the mesh in 3D "
                    "coloured by H or D_L (docs/cli.md)");
    args->color_range.option =
        sub->add_option("--color-range", args->color_range.text,
                        "fix the symmetric H colour range [-R, R] (default: 95th percentile of |H|)");
    add_html_face_budget_option(sub, args->html_face_budget);
    sub->add_flag("--exact", args->request.exact,
                  "also compute the profile from a per-vertex H stored in the PLY (the true profile of a generated "
                  "surface) and the error of the estimated H");
    sub->add_option("--exact-property", args->request.exact_property, "the PLY vertex property holding the exact H")
        ->capture_default_str();
    add_threads_option(sub, args->threads);
    add_progress_options(sub, args->progress);
    sub->callback([args, &action] { action = [args] { return run_profile(*args); }; });
}

}  // namespace meshdiff::cli
