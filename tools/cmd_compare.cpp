#include "commands.h"
#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"
#include "meshdiff/vertex_maps.h"
#include "options.h"

#include <iostream>
#include <memory>
#include <optional>
#include <utility>

namespace meshdiff::cli {

namespace {

struct CompareArgs
{
    std::string original, processed;
    CompareCliOptions compare;
    std::string json;
    std::string distance_map;
    std::vector<double> color_range;
    int threads = 0;
};

int run_compare(const CompareArgs& a)
{
    set_threads(a.threads);
    for (const auto& [what, out] : {std::pair{"--json", a.json}, {"--distance-map", a.distance_map}})
        refuse_overwriting_inputs(what, out, {a.original, a.processed});
    CompareOptions options = to_compare_options(a.compare);
    options.vertex_distances = !a.distance_map.empty();
    std::optional<std::pair<double, double>> range;
    if (!a.color_range.empty()) {
        if (!(a.color_range.size() == 2 && a.color_range[0] < a.color_range[1]))
            throw InvalidArgumentError("--color-range needs MIN MAX with MIN < MAX");
        range = std::pair{a.color_range[0], a.color_range[1]};
    }
    const LoadedMesh original = read_mesh(a.original);
    const LoadedMesh processed = read_mesh(a.processed);
    const Comparison c = compare_meshes(original, processed, options);
    if (!a.distance_map.empty()) write_ply(a.distance_map, processed.mesh, distance_map(c, range));
    if (!a.json.empty()) write_json(a.json, comparison_json(c));
    if (a.json != "-") std::cout << comparison_text(c);
    return 0;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action)
{
    auto args = std::make_shared<CompareArgs>();
    auto* sub = app.add_subcommand("compare",
                                   "compare an original and a processed mesh: roughness profiles, per-level "
                                   "roughness distance, Metro-style surface distance (the default command)");
    sub->add_option("ORIGINAL", args->original, "original mesh (.ply .obj .off .stl)")->required();
    sub->add_option("PROCESSED", args->processed, "processed mesh")->required();
    add_compare_options(sub, args->compare);
    add_measure_options(sub, args->compare.profile);
    sub->add_option("--json", args->json, "write the JSON report to FILE, or '-' for stdout");
    sub->add_option("--distance-map", args->distance_map,
                    "write the processed mesh with per-vertex distance to the original and a colour ramp as PLY");
    sub->add_option("--color-range", args->color_range, "fix the distance colour range: MIN MAX")
        ->expected(2)
        ->check(in_range(-1e300, 1e300));
    sub->add_option("--threads", args->threads, "worker threads (0: all cores)")->capture_default_str();
    sub->callback([args, &action] { action = [args] { return run_compare(*args); }; });
}

}  // namespace meshdiff::cli
