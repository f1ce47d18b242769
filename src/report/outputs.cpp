#include "meshdiff/report/outputs.h"

#include "meshdiff/core/progress.h"
#include "meshdiff/distance/sample_cloud.h"
#include "meshdiff/error.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/io/facts.h"
#include "meshdiff/io/output_file.h"
#include "meshdiff/report/html.h"
#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"
#include "meshdiff/report/vertex_maps.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <future>
#include <iostream>
#include <tuple>

namespace meshdiff {

namespace {

// Refuses an output that is one of the inputs, or a second output onto the same file.
void check_targets(const std::vector<std::pair<const char*, std::string>>& outputs,
                   const std::vector<std::string>& inputs)
{
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& [field, path] = outputs[i];
        if (path.empty() || path == "-") continue;
        refuse_overwriting_inputs(field, path, inputs);
        for (std::size_t j = 0; j < i; ++j) {
            const auto& [other, other_path] = outputs[j];
            if (!other_path.empty() && other_path != "-" && (other_path == path || same_file(other_path, path)))
                throw OptionError(field,
                                  fmt::format("'{}' is also the file of {{{}}}: one file per output", path, other));
        }
    }
}

// The topology report on a thread of its own, unless OpenMP is limited to one thread.
std::launch facts_policy()
{
    return omp_get_max_threads() > 1 ? std::launch::async : std::launch::deferred;
}

// The HTML report's face budget: at least kMinHtmlFaceBudget; other than the
// default only with an HTML report to draw.
void check_face_budget(std::size_t budget, const std::string& html)
{
    if (budget < kMinHtmlFaceBudget)
        throw OptionError("outputs.html_face_budget",
                          fmt::format("{} is below {} faces per mesh", budget, kMinHtmlFaceBudget));
    if (budget != kDefaultHtmlFaceBudget && html.empty())
        throw OptionError("outputs.html_face_budget", "needs {outputs.html} (the HTML report it is for)");
}

}  // namespace

std::pair<std::string, std::string> map_paths(const CompareOutputs& o)
{
    if (!o.distance_maps.empty()) return {o.distance_maps + "_original.ply", o.distance_maps + "_processed.ply"};
    return {o.distance_map_original, o.distance_map};
}

void validate(const CompareOutputs& o, const CompareOptions& options, const std::vector<std::string>& inputs)
{
    if (!o.distance_maps.empty() && !o.distance_map.empty())
        throw OptionError("outputs.distance_maps", "writes both maps: leave out {outputs.distance_map}");
    if (!o.distance_maps.empty() && !o.distance_map_original.empty())
        throw OptionError("outputs.distance_maps", "writes both maps: leave out {outputs.distance_map_original}");
    if (o.color_range && !(std::isfinite(o.color_range->first) && std::isfinite(o.color_range->second) &&
                           o.color_range->first < o.color_range->second))
        throw OptionError("outputs.color_range", fmt::format("[{}, {}] is not MIN MAX with MIN < MAX, both finite",
                                                             o.color_range->first, o.color_range->second));
    if (o.color_range && o.color_percentile)
        throw OptionError("outputs.color_range", "a fixed range or a percentile, not both");
    if (o.color_percentile && !(*o.color_percentile > 0.0 && *o.color_percentile <= 100.0))
        throw OptionError("outputs.color_range", fmt::format("percentile {} is not in (0, 100]", *o.color_percentile));
    const auto [original_map, processed_map] = map_paths(o);
    const char* original_field = o.distance_maps.empty() ? "outputs.distance_map_original" : "outputs.distance_maps";
    const char* processed_field = o.distance_maps.empty() ? "outputs.distance_map" : "outputs.distance_maps";
    if (!options.distance) {
        if (!o.samples_out.empty())
            throw OptionError("outputs.samples_out", "needs the surface distance: leave out {distance} off");
        if (!processed_map.empty()) throw OptionError(processed_field, "needs the surface distance");
        if (!original_map.empty()) throw OptionError(original_field, "needs the surface distance");
    }
    if (o.html == "-") throw OptionError("outputs.html", "is a file: '-' (standard output) is not offered");
    check_face_budget(o.html_face_budget, o.html);
    check_targets({{"outputs.json", o.json},
                   {processed_field, processed_map},
                   {original_field, original_map},
                   {"outputs.samples_out", o.samples_out},
                   {"outputs.html", o.html}},
                  inputs);
}

CompareOptions with_outputs(CompareOptions options, const CompareOutputs& o)
{
    const auto [original_map, processed_map] = map_paths(o);
    options.vertex_distances = !original_map.empty() || !processed_map.empty();
    options.keep_samples = !o.samples_out.empty();
    if (!o.html.empty()) {
        options.vertex_distances = options.distance;
        options.profile.keep_vertex_data = true;
        if (options.summary.histogram_bins == 0) options.summary.histogram_bins = kHtmlHistogramBins;
    }
    return options;
}

std::string write_outputs(const Comparison& c, const LoadedMesh& original, const LoadedMesh& processed,
                          const CompareOutputs& o, const std::string& original_name, const std::string& processed_name)
{
    const auto [map_original, map_processed] = map_paths(o);
    // Both maps share one colour scale: the given range or percentile, else
    // kDefaultColorPercentile of both meshes' vertex distances (when both are
    // there; else each map its own [0, largest]).
    std::optional<std::pair<double, double>> range = o.color_range;
    const bool maps = !map_processed.empty() || !map_original.empty();
    const bool both = c.processed_vertex_distance.size() == c.processed.topology.vertices &&
                      c.original_vertex_distance.size() == c.original.topology.vertices;
    if (!range && maps && (o.color_percentile || both))
        range = distance_color_range(c, o.color_percentile.value_or(kDefaultColorPercentile));
    std::string legend;
    for (const auto& [path, side, mesh] : {std::tuple{map_original, MapSide::Original, &original.mesh},
                                           std::tuple{map_processed, MapSide::Processed, &processed.mesh}}) {
        if (path.empty()) continue;
        const VertexMap map = distance_map(c, side, range);
        write_ply(path, *mesh, map);
        const bool has_signed = std::any_of(map.scalars.begin(), map.scalars.end(),
                                            [](const VertexScalar& s) { return s.name == "signed_distance"; });
        legend += fmt::format("Distance map of the {}: {} (vertex property 'distance' to the {} surface{}; {})\n",
                              side == MapSide::Original ? "original" : "processed", path,
                              side == MapSide::Original ? "processed" : "original",
                              has_signed ? ", and 'signed_distance', positive outside it" : "", map.comments[1]);
    }
    if (!o.samples_out.empty())
        write_sample_cloud(o.samples_out, original.mesh, c.forward_samples, processed.mesh, c.backward_samples,
                           {"original " + original_name, "processed " + processed_name});
    if (!o.html.empty()) {
        HtmlOptions html;
        html.command = o.command;
        html.face_budget = o.html_face_budget;
        html.color_range = o.color_range;
        if (o.color_percentile && !c.original_vertex_distance.empty()) {
            html.color_range = distance_color_range(c, *o.color_percentile);
            html.color_rule =
                fmt::format("0 to the {:g}th percentile of both meshes' vertex distances", *o.color_percentile);
        }
        write_html_file(o.html, comparison_html(c, original.mesh, processed.mesh, comparison_json(c), html));
        legend += fmt::format("HTML report: {}\n", o.html);
    }
    return legend;
}

void parse_color_range(const std::string& text, CompareOutputs& o)
{
    const char* field = "outputs.color_range";
    o.color_range.reset();
    o.color_percentile.reset();
    if (text == "max") {
        o.color_percentile = 100.0;
    } else if (text.size() > 1 && text[0] == 'p') {
        o.color_percentile = parse_number(field, text.substr(1));
    } else if (const auto colon = text.find(':'); colon != std::string::npos) {
        o.color_range =
            std::pair{parse_number(field, text.substr(0, colon)), parse_number(field, text.substr(colon + 1))};
    } else {
        throw OptionError(field, fmt::format("'{}' is not max, pNN (a percentile) or LO:HI", text));
    }
}

void validate(const ProfileRequest& r, const std::vector<std::string>& inputs)
{
    if (r.corsini_unbiased && r.measure != RoughnessMeasure::Corsini)
        throw OptionError("corsini_unbiased", "needs {measure} corsini");
    if (!is_known(r.measure)) throw OptionError("measure", "not a known roughness measure");
    if (r.measure == RoughnessMeasure::Corsini) {
        if (!r.profile.radii.empty())
            throw OptionError("profile.radii", "metric levels are not defined for {measure} corsini");
        if (!r.vertex_data.empty()) throw OptionError("outputs.vertex_data", "needs {measure} sigma");
        if (!r.html.empty()) throw OptionError("outputs.html", "needs {measure} sigma");
        if (r.exact) throw OptionError("outputs.exact", "needs {measure} sigma");
        if (r.color_range != 0.0) throw OptionError("outputs.color_range", "needs {measure} sigma");
        CorsiniOptions c;
        c.levels = r.profile.levels;
        c.global = r.profile.global;
        validate(c);
    } else {
        validate(r.profile);
    }
    if (!(std::isfinite(r.color_range) && r.color_range >= 0.0))
        throw OptionError("outputs.color_range",
                          fmt::format("{} must be finite and > 0 (0: the 95th percentile of |H|)", r.color_range));
    if (r.exact && r.exact_property.empty()) throw OptionError("outputs.exact_property", "is empty");
    if (r.html == "-") throw OptionError("outputs.html", "is a file: '-' (standard output) is not offered");
    check_face_budget(r.html_face_budget, r.html);
    check_targets({{"outputs.json", r.json}, {"outputs.vertex_data", r.vertex_data}, {"outputs.html", r.html}}, inputs);
}

ProfileReport profile_report(const LoadedMesh& loaded, const ProfileRequest& r)
{
    validate(r, {});
    Progress* progress = current_progress();
    // The topology report is serial; it overlaps the serial stages of the
    // profile (normalisation, adjacency, normals) on another thread.
    auto facts_future = std::async(facts_policy(), [&loaded, progress] {
        const ProgressScope in_this_thread(progress);  // it stops on Ctrl-C too
        return mesh_facts(loaded);
    });
    ProfileReport out;
    if (r.measure == RoughnessMeasure::Corsini) {
        CorsiniOptions options;
        options.levels = r.profile.levels;
        options.global = r.profile.global;
        options.unbiased = r.corsini_unbiased;
        if (progress) progress->stage("corsini", 1);
        const CorsiniProfile profile = corsini_profile(loaded.mesh, options);
        if (progress) progress->advance(1);
        const MeshFacts facts = facts_future.get();
        out.json = corsini_profile_json(facts, profile);
        out.text = corsini_profile_text(facts, profile);
        return out;
    }
    ProfileOptions options = r.profile;
    options.keep_vertex_data = options.keep_vertex_data || !r.vertex_data.empty() || r.exact || !r.html.empty();
    const RoughnessProfile profile = roughness_profile(loaded.mesh, options);
    const MeshFacts facts = facts_future.get();
    if (!r.vertex_data.empty())
        write_ply(r.vertex_data, apply_normalization(loaded.mesh, profile.normalization),
                  profile_map(profile, loaded.input.path, r.color_range));
    out.json = profile_json(facts, profile);
    out.text = profile_text(facts, profile);
    if (r.exact) {
        const VertexScalar* H = nullptr;
        try {
            H = &vertex_scalar(loaded, r.exact_property);
        } catch (const InvalidArgumentError& e) {
            throw OptionError("outputs.exact_property", fmt::format("{} (meshdiff generate writes exact_H)", e.what()));
        }
        const ExactProfile e = exact_profile(loaded.mesh, H->values, options, profile);
        out.text += exact_profile_text(profile, e, r.exact_property);
        out.json["exact"] = exact_profile_json(profile, e, r.exact_property);
    }
    if (!r.html.empty()) {
        HtmlOptions html;
        html.command = r.command;
        html.face_budget = r.html_face_budget;
        if (r.color_range > 0.0) html.color_range = std::pair{-r.color_range, r.color_range};
        write_html_file(r.html, profile_html(profile, loaded.mesh, loaded.input.path, out.json, html));
        out.text += fmt::format("HTML report: {}\n", r.html);
    }
    return out;
}

void write_json_file(const std::string& target, const nlohmann::json& j)
{
    // Bytes that are not UTF-8 (in a file name, say) become U+FFFD instead of an exception.
    const std::string text = j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
    if (target == "-") {
        std::cout << text;
        return;
    }
    write_atomically(target, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp);
        if (!out) throw IoError(fmt::format("{}: cannot open for writing", target));
        out << text;
        out.close();
        if (!out) throw IoError(fmt::format("{}: write failed", target));
    });
}

}  // namespace meshdiff
