#include "commands.h"
#include "interrupt.h"
#include "meshdiff/compare.h"
#include "meshdiff/error.h"
#include "meshdiff/io.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"
#include "meshdiff/sample_cloud.h"
#include "meshdiff/vertex_maps.h"
#include "options.h"
#include "progress_display.h"

#include <fmt/format.h>
#include <omp.h>

#include <future>
#include <iostream>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>

namespace meshdiff::cli {

namespace {

struct CompareArgs
{
    std::string original, processed;
    CompareCliOptions compare;
    std::string json;
    std::string distance_map;           // the processed mesh's map
    std::string distance_map_original;  // the original's map
    std::string distance_maps;          // prefix of both
    std::string samples_out;
    std::vector<double> color_range;
    int threads = 0;
    ProgressCliOptions progress;
};

int run_compare(const CompareArgs& a)
{
    set_threads(a.threads);
    std::string map_processed = a.distance_map, map_original = a.distance_map_original;
    if (!a.distance_maps.empty()) {
        if (!map_processed.empty() || !map_original.empty())
            throw InvalidArgumentError(
                "--distance-maps PREFIX writes both maps: leave out --distance-map and "
                "--distance-map-original");
        map_processed = a.distance_maps + "_processed.ply";
        map_original = a.distance_maps + "_original.ply";
    }
    if (!map_processed.empty() && map_processed == map_original)
        throw InvalidArgumentError("--distance-map and --distance-map-original name the same file");
    for (const auto& [what, out] : {std::pair{"--json", a.json},
                                    {"--distance-map", map_processed},
                                    {"--distance-map-original", map_original},
                                    {"--samples-out", a.samples_out}})
        refuse_overwriting_inputs(what, out, {a.original, a.processed});
    CompareOptions options = to_compare_options(a.compare);
    options.vertex_distances = !map_processed.empty() || !map_original.empty();
    options.keep_samples = !a.samples_out.empty();
    if (options.keep_samples && !options.distance)
        throw InvalidArgumentError("--samples-out needs the surface distance: leave out --no-distance");
    std::optional<std::pair<double, double>> range;
    if (!a.color_range.empty()) {
        if (!(a.color_range.size() == 2 && a.color_range[0] < a.color_range[1]))
            throw InvalidArgumentError("--color-range needs MIN MAX with MIN < MAX");
        range = std::pair{a.color_range[0], a.color_range[1]};
    }
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
    // Both maps share one colour scale: the given range, else [0, the largest distance of both].
    if (!range && !map_processed.empty() && !map_original.empty()) range = distance_map_range(c);
    std::string legend;
    for (const auto& [path, side, mesh] : {std::tuple{map_original, MapSide::Original, &original.mesh},
                                           std::tuple{map_processed, MapSide::Processed, &processed.mesh}}) {
        if (path.empty()) continue;
        const VertexMap map = distance_map(c, side, range);
        write_ply(path, *mesh, map);
        const bool has_signed = map.scalars.size() > 1;
        legend += fmt::format("Distance map of the {}: {} (vertex property 'distance' to the {} surface{}; {})\n",
                              side == MapSide::Original ? "original" : "processed", path,
                              side == MapSide::Original ? "processed" : "original",
                              has_signed ? ", and 'signed_distance', positive outside it" : "", map.comments[1]);
    }
    if (!a.samples_out.empty())
        write_sample_cloud(a.samples_out, original.mesh, c.forward_samples, processed.mesh, c.backward_samples,
                           {"original " + a.original, "processed " + a.processed});
    if (!a.json.empty()) write_json(a.json, comparison_json(c));
    if (a.json != "-") std::cout << comparison_text(c) << legend;
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
    add_measure_options(sub, args->compare.profile);
    sub->add_option("--json", args->json, "write the JSON report to FILE, or '-' for stdout");
    sub->add_option("--distance-map", args->distance_map,
                    "write the processed mesh with per-vertex distance to the original and a colour ramp as PLY");
    sub->add_option("--distance-map-original", args->distance_map_original,
                    "write the original mesh with per-vertex distance to the processed one as PLY (with "
                    "--distance-map: one colour scale for both)");
    sub->add_option("--distance-maps", args->distance_maps,
                    "write both maps, PREFIX_original.ply and PREFIX_processed.ply, on one colour scale");
    sub->add_option("--samples-out", args->samples_out,
                    "write the samples of both directions with their distances as a binary PLY point cloud "
                    "(x y z distance signed_distance kind direction face)");
    sub->add_option("--color-range", args->color_range, "fix the distance colour range: MIN MAX")
        ->expected(2)
        ->check(in_range(-1e300, 1e300));
    sub->add_option("--threads", args->threads, "worker threads (0: all cores)")->capture_default_str();
    add_progress_options(sub, args->progress);
    sub->callback([args, &action] { action = [args] { return run_compare(*args); }; });
}

}  // namespace meshdiff::cli
