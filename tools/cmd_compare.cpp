#include "cli.h"
#include "commands.h"
#include "interrupt.h"
#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/io/io.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/outputs.h"
#include "meshdiff/report/text.h"
#include "options.h"
#include "progress_display.h"

#include <fmt/format.h>
#include <omp.h>

#include <future>
#include <iostream>
#include <memory>
#include <optional>

namespace meshdiff::cli {

namespace {

struct CompareArgs
{
    std::string original, processed;
    CompareCliOptions compare;
    CompareOutputCliOptions outputs;
    Given threads;
    ProgressCliOptions progress;
};

int run_compare(const CompareArgs& a)
{
    set_threads(a.threads);
    CompareOutputs outputs = to_compare_outputs(a.outputs);
    outputs.command = command_line();
    const CompareOptions checked = to_compare_options(a.compare);
    validate(outputs, checked, {a.original, a.processed});
    CompareOptions options = with_outputs(checked, outputs);
    install_interrupt_handlers();
    // Either input may be a point cloud (vertices, no faces): cloud_distance.h.
    ProgressDisplay progress(a.progress);
    options.progress = &progress;
    progress.stage("reading", 2);
    // Both files at once, unless --threads 1; the original's error, if any,
    // is still the one reported, as when they were read one after the other.
    auto processed_read = std::async(omp_get_max_threads() > 1 ? std::launch::async : std::launch::deferred,
                                     [&a] { return read_mesh_or_cloud(a.processed); });
    const LoadedMesh original = read_mesh_or_cloud(a.original);
    progress.advance(1);
    check_cancelled(&progress);
    const LoadedMesh processed = processed_read.get();
    progress.advance(2);
    const Comparison c = compare_meshes(original, processed, options);
    check_cancelled(&progress);  // once interrupted, nothing is written
    progress.finish();
    // Every output file at once at the end, or none (a failing run leaves nothing behind).
    StagedOutputs staged;
    const std::string legend = write_outputs(c, original, processed, outputs, a.original, a.processed);
    const nlohmann::json j = comparison_json(c);
    if (!outputs.json.empty() && outputs.json != "-") write_json_file(outputs.json, j);
    staged.commit();
    if (outputs.json == "-")
        write_json_file("-", j);
    else
        std::cout << comparison_text(c) << legend;
    return 0;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<CompareArgs>();
    auto* sub = app.add_subcommand("compare",
                                   "compare an original and a processed mesh: roughness profiles, per-level "
                                   "roughness distance, Metro-style surface distance (the default command)");
    sub->add_option("ORIGINAL", args->original,
                    "original mesh (.ply .obj .off .stl), or a point cloud (a .ply .obj .off file with vertices and no "
                    "faces)")
        ->required();
    sub->add_option("PROCESSED", args->processed, "processed mesh or point cloud")->required();
    add_compare_options(sub, args->compare);
    add_compare_output_options(sub, args->outputs);
    add_threads_option(sub, args->threads);
    add_progress_options(sub, args->progress);
    sub->callback([args, &action] { action = [args] { return run_compare(*args); }; });
}

}  // namespace meshdiff::cli
