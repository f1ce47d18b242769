#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"

#include <fmt/format.h>

#include <algorithm>

namespace meshdiff {

nlohmann::json smoothing_json(const SmoothingRecord& r, const SmoothingOptions& o, const RecordOptions& ro,
                              const std::string& input, const std::string& output)
{
    nlohmann::json j;
    j["schema"] = "meshdiff.smoothing/1";
    j["input"] = input;
    j["output"] = output;
    j["method"] = to_string(o.method);
    j["update"] = to_string(o.update);
    j["parameters"] = {{"iterations", o.iterations},
                       {"lambda", o.lambda},
                       {"mu", o.mu},
                       {"step", o.step},
                       {"damping", o.damping},
                       {"epsilon", o.epsilon},
                       {"implicit", o.implicit},
                       {"step_control", to_string(o.step_control)},
                       {"stability", o.stability}};
    j["curvature"] = to_string(ro.profile.curvature.method);
    j["profile_every"] = ro.every;
    j["iterations"] = r.iterations;
    j["levels"] = ro.profile.levels;
    j["sigma"] = r.sigma;
    j["sigma_global"] = r.sigma_global;
    j["curvature_undefined"] = r.undefined;
    if (!r.distance.empty()) {
        nlohmann::json distance = nlohmann::json::array();
        for (const SurfaceDistance& d : r.distance)
            distance.push_back(
                {{"hausdorff", d.hausdorff},
                 {"hausdorff_relative", d.hausdorff / d.diagonal},
                 {"forward", {{"max", d.forward.max}, {"mean", d.forward.mean}, {"rms", d.forward.rms}}},
                 {"backward", {{"max", d.backward.max}, {"mean", d.backward.mean}, {"rms", d.backward.rms}}},
                 {"diagonal", d.diagonal},
                 {"samples", d.forward.n_samples()}});
        j["distance_to_input"] = distance;
    }
    const SmoothingReport& report = r.report;
    if (!report.steps.empty()) {
        // Flow time at each recorded iteration, in units of the initial mean edge length squared.
        j["flow"] = {{"mean_edge", report.mean_edge},
                     {"time", r.flow_time},
                     {"steps", report.steps},
                     {"stability_ratio", report.stability_ratio},
                     {"unstable_iterations", report.unstable_iterations}};
    }
    return j;
}

std::string smoothing_text(const std::string& output, const SmoothingOptions& options, std::size_t vertices,
                           const SmoothingReport& report)
{
    std::string s = fmt::format("{}: {} {}-updating, {} iterations, {} vertices\n", output, to_string(options.method),
                                to_string(options.update), options.iterations, vertices);
    if (!report.steps.empty())
        s += fmt::format("flow time {:.6g} e^2 (e = {:.6g}, the initial mean edge length)\n", report.time,
                         report.mean_edge);
    return s;
}

std::optional<std::string> smoothing_warning(const std::string& input, const SmoothingOptions& options,
                                             const SmoothingReport& report)
{
    if (report.unstable_iterations == 0) return std::nullopt;
    return fmt::format(
        "warning: {}: {} of {} explicit steps exceeded the stability bound (up to {:.3g} times); the flow "
        "may diverge: use a smaller --step, --step-control adaptive or --implicit (mcf)\n",
        input, report.unstable_iterations, options.iterations, report.max_stability_ratio());
}

std::string noise_description(const NoiseOptions& o, const NoiseReport& r)
{
    const std::string law = o.distribution == NoiseDistribution::Uniform
                                ? fmt::format("uniform [-{}, {})", o.amplitude, o.amplitude)
                                : fmt::format("gaussian sigma {}", o.amplitude);
    switch (o.unit) {
        case NoiseUnit::MeanEdge:
            return fmt::format("{} x mean edge length {:.6g}", law, r.unit_length);
        case NoiseUnit::BBoxDiagonal:
            return fmt::format("{} x bbox diagonal {:.6g}", law, r.unit_length);
        case NoiseUnit::Absolute:
            break;
    }
    return law + " in mesh units";
}

namespace {
std::string noise_along(const NoiseOptions& o)
{
    return o.direction == NoiseDirection::Normal ? "along vertex normals" : "along random directions";
}
}  // namespace

std::string noise_comment(const std::string& input, const NoiseOptions& options, const NoiseReport& r)
{
    std::string comment = fmt::format("meshdiff noise: {} moved {} by {} = amplitude {:.6g}, seed {}, boundary {}",
                                      input, noise_along(options), noise_description(options, r), r.amplitude,
                                      options.seed, options.move_boundary ? "moved" : "fixed");
    std::replace_if(
        comment.begin(), comment.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    return comment;
}

std::string noise_text(const std::string& output, const NoiseOptions& options, const NoiseReport& r)
{
    return fmt::format(
        "{}: {} vertices moved, {} skipped ({} boundary, {} without direction, {} isolated); amplitude {:.6g} ({}) "
        "{}, seed {}\n",
        output, r.moved, r.skipped(), r.skipped_boundary, r.skipped_no_direction, r.skipped_isolated, r.amplitude,
        noise_description(options, r), noise_along(options), options.seed);
}

std::string shape_text(const std::string& output, const Shape& shape, const std::string& description)
{
    const auto [lo, hi] = std::minmax_element(shape.exact_H.begin(), shape.exact_H.end());
    return fmt::format("{}: {} vertices, {} faces, exact H in [{:.6g}, {:.6g}] ({})\n", output, shape.mesh.n_vertices(),
                       shape.mesh.n_faces(), *lo, *hi, description);
}

}  // namespace meshdiff
