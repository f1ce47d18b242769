#include "options.h"

#include "meshdiff/error.h"
#include "meshdiff/metric_levels.h"
#include "meshdiff/output_file.h"

#include <fmt/format.h>
#include <omp.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace meshdiff::cli {

namespace {

// The whole of \p text as a finite number, or nothing.
std::optional<double> finite_number(const std::string& text)
{
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (used != text.size() || text.empty() || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace

CLI::Validator in_range(double lo, double hi, bool integer)
{
    const std::string range = fmt::format("{} {} to {}", integer ? "a whole number from" : "a number from", lo, hi);
    return CLI::Validator(
        [lo, hi, integer, range](std::string& text) -> std::string {
            const auto v = finite_number(text);
            if (!v || *v < lo || *v > hi || (integer && *v != std::floor(*v)))
                return fmt::format("'{}' is not {}", text, range);
            return std::string();
        },
        range);
}

CLI::Validator positive(double hi)
{
    return CLI::Validator(
        [hi](std::string& text) -> std::string {
            const auto v = finite_number(text);
            if (!v || !(*v > 0.0) || *v > hi)
                return fmt::format("'{}' is not a finite number > 0{}", text,
                                   hi < 1e300 ? fmt::format(" and <= {}", hi) : "");
            return std::string();
        },
        "a number > 0");
}

std::vector<int> parse_levels(const std::string& text)
{
    std::vector<int> levels;
    std::stringstream ss(text);
    std::string item;
    auto to_int = [&](const std::string& s) {
        std::size_t used = 0;
        int v = 0;
        try {
            v = std::stoi(s, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != s.size() || s.empty())
            throw InvalidArgumentError(fmt::format("--levels: '{}' is not a list like 1,2,5 or 1-20", text));
        if (v < 1 || v > 100000) throw InvalidArgumentError(fmt::format("--levels: level {} is out of 1..100000", v));
        return v;
    };
    while (std::getline(ss, item, ',')) {
        const auto dash = item.find('-');
        if (dash == std::string::npos) {
            levels.push_back(to_int(item));
        } else {
            const int a = to_int(item.substr(0, dash)), b = to_int(item.substr(dash + 1));
            if (b < a) throw InvalidArgumentError(fmt::format("--levels: empty range '{}'", item));
            if (std::size_t(b - a) >= kMaxLevels)
                throw InvalidArgumentError(
                    fmt::format("--levels: the range '{}' has more than the limit of {} levels", item, kMaxLevels));
            for (int l = a; l <= b; ++l) levels.push_back(l);
        }
    }
    if (levels.size() > kMaxLevels)
        throw InvalidArgumentError(
            fmt::format("--levels: '{}' lists {} levels, more than the limit of {}", text, levels.size(), kMaxLevels));
    if (levels.empty() && !text.empty())
        throw InvalidArgumentError(fmt::format("--levels: '{}' is not a list like 1,2,5 or 1-20", text));
    return levels;
}

std::vector<double> parse_radii(const std::string& text)
{
    if (text == "default") return default_radii();
    std::vector<double> radii;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const auto v = finite_number(item);
        if (!v)
            throw InvalidArgumentError(
                fmt::format("--radii: '{}' is not a list of numbers like 0.05,0.1,0.2 or 'default'", text));
        if (!(*v > 0.0) || *v > kMaxRadius)
            throw InvalidArgumentError(fmt::format("--radii: radius {} is not in (0, {}]", item, kMaxRadius));
        radii.push_back(*v);
        if (radii.size() > kMaxRadii)
            throw InvalidArgumentError(
                fmt::format("--radii: '{}' lists more than the limit of {} radii", text, kMaxRadii));
    }
    if (radii.empty() && !text.empty())
        throw InvalidArgumentError(
            fmt::format("--radii: '{}' is not a list of numbers like 0.05,0.1,0.2 or 'default'", text));
    return radii;
}

std::vector<double> parse_fscore(const std::string& text)
{
    std::vector<double> thresholds;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const auto v = finite_number(item);
        if (!v)
            throw InvalidArgumentError(fmt::format(
                "--fscore: '{}' is not a list of thresholds like 0.001,0.005 (relative to the diagonal)", text));
        if (!(*v > 0.0) || *v > 1e6)
            throw InvalidArgumentError(fmt::format("--fscore: threshold {} is not in (0, 1e6]", item));
        thresholds.push_back(*v);
        if (thresholds.size() > kMaxFscoreThresholds)
            throw InvalidArgumentError(
                fmt::format("--fscore: '{}' lists more than the limit of {} thresholds", text, kMaxFscoreThresholds));
    }
    if (thresholds.empty() && !text.empty())
        throw InvalidArgumentError(fmt::format(
            "--fscore: '{}' is not a list of thresholds like 0.001,0.005 (relative to the diagonal)", text));
    return thresholds;
}

void add_profile_options(CLI::App* sub, ProfileCliOptions& o, bool with_radii)
{
    sub->add_option("--levels", o.levels, "ring levels, e.g. 1,2,5,10,20 or 1-20")->capture_default_str();
    if (with_radii)
        sub->add_option("--radii", o.radii,
                        "metric levels: radii on the unit-scaled mesh, e.g. 0.05,0.1,0.2, or 'default' "
                        "(0.0125 * 2^(k/2), k = 0..8: 0.0125 to 0.2)");
    sub->add_flag("--no-global", o.no_global, "leave out the global level");
    sub->add_option("--curvature", o.curvature, "mean curvature estimator")
        ->check(CLI::IsMember(enum_names<CurvatureMethod>()))
        ->capture_default_str();
    sub->add_option("--weighting", o.weighting, "row weighting of the fitting estimators")
        ->check(CLI::IsMember(enum_names<RowWeighting>()))
        ->capture_default_str();
}

void add_measure_options(CLI::App* sub, ProfileCliOptions& o)
{
    sub->add_option("--measure", o.measure,
                    "sigma: the paper's curvature-deviation profile; corsini: Corsini et al.'s dihedral-angle "
                    "roughness (variance of dihedral angles per ring level, METHOD.md 6a)")
        ->check(CLI::IsMember(enum_names<RoughnessMeasure>()))
        ->capture_default_str();
    sub->add_flag("--unbiased-variance", o.unbiased_variance,
                  "with --measure corsini: variance with divisor n - 1 instead of n");
}

CorsiniOptions to_corsini_options(const ProfileCliOptions& o)
{
    if (!o.radii.empty()) throw InvalidArgumentError("--radii: metric levels are not defined for --measure corsini");
    CorsiniOptions c;
    c.levels = parse_levels(o.levels);
    c.global = !o.no_global;
    c.unbiased = o.unbiased_variance;
    return c;
}

ProfileOptions to_profile_options(const ProfileCliOptions& o, bool keep_vertex_data)
{
    ProfileOptions p;
    p.levels = parse_levels(o.levels);
    p.radii = parse_radii(o.radii);
    p.global = !o.no_global;
    p.curvature.method = parse_enum<CurvatureMethod>(o.curvature);
    p.curvature.weighting = parse_enum<RowWeighting>(o.weighting);
    p.keep_vertex_data = keep_vertex_data;
    return p;
}

void add_compare_options(CLI::App* sub, CompareCliOptions& o)
{
    add_profile_options(sub, o.profile);
    sub->add_option("-k,--k", o.k, "constant k of the roughness distance (eq. 10)")
        ->check(positive())
        ->capture_default_str();
    sub->add_flag("--no-roughness", o.no_roughness, "skip the roughness half");
    sub->add_flag("--no-distance", o.no_distance, "skip the surface distance half");
    sub->add_option("-n,--samples", o.samples, "samples per direction (default: 10 x the larger face count, as Metro)")
        ->check(in_range(1, double(kMaxSamples), true));
    sub->add_option("--density", o.density,
                    fmt::format("samples per unit area instead of a count (density x area <= {})", kMaxSamples))
        ->check(positive());
    sub->add_option("--face-sampling", o.face_sampling, "face sampling scheme")
        ->check(CLI::IsMember(enum_names<FaceSampling>()))
        ->capture_default_str();
    sub->add_option("--seed", o.seed, "seed of Monte Carlo sampling")
        ->check(in_range(0, 1.8e19, true))
        ->capture_default_str();
    sub->add_flag("--no-vertex-samples", o.no_vertex_samples, "do not sample vertices");
    sub->add_flag("--no-edge-samples", o.no_edge_samples, "do not sample edges");
    sub->add_flag("--no-face-samples", o.no_face_samples, "do not sample faces");
    sub->add_option("--hausdorff", o.hausdorff,
                    "certified: also an interval [lower, upper] holding the true one-sided Hausdorff distances, "
                    "and where they are attained; sampled: the sampled maxima only (Metro)")
        ->check(CLI::IsMember({"certified", "sampled"}))
        ->capture_default_str();
    sub->add_option("--hausdorff-tolerance", o.hausdorff_tolerance,
                    "width of the certified interval relative to the value (default 1e-4: four certain digits)")
        ->check(in_range(1e-12, 0.5));
    sub->add_option("--hausdorff-abs-tolerance", o.hausdorff_abs_tolerance,
                    "width of the certified interval in the meshes' unit instead (with both tolerances, the "
                    "larger wins)")
        ->check(in_range(1e-300, 1e300));
    sub->add_option("--hausdorff-budget", o.hausdorff_budget,
                    "most triangle bounds per direction before the interval reached is reported (default "
                    "2,000,000 + 20 x the faces of both meshes)")
        ->check(in_range(1, kMaxHausdorffBudget, true));
    sub->add_option("--fscore", o.fscore,
                    "F-score thresholds relative to the original's bounding-box diagonal, e.g. 0.001,0.005 "
                    "(area-weighted face samples; in the JSON and the text report)");
    sub->add_option("--histogram", o.histogram,
                    "N bins over [0, max] of each direction's sample distances, in the JSON report")
        ->check(in_range(1, double(kMaxHistogramBins), true));
}

CompareOptions to_compare_options(const CompareCliOptions& o)
{
    CompareOptions c;
    c.profile = to_profile_options(o.profile, false);
    c.measure = parse_enum<RoughnessMeasure>(o.profile.measure);
    if (c.measure == RoughnessMeasure::Corsini) {
        const CorsiniOptions co = to_corsini_options(o.profile);
        c.corsini_unbiased = co.unbiased;
    } else if (o.profile.unbiased_variance) {
        throw InvalidArgumentError("--unbiased-variance needs --measure corsini");
    }
    c.k = o.k;
    c.roughness = !o.no_roughness;
    c.distance = !o.no_distance;
    if (o.samples > 0 && o.density > 0.0) throw InvalidArgumentError("--samples and --density exclude each other");
    if (o.samples > 0) c.sampling.samples = o.samples;
    if (o.density < 0.0) throw InvalidArgumentError("--density must be > 0");
    if (o.density > 0.0) c.sampling.density = o.density;
    c.sampling.face_scheme = parse_enum<FaceSampling>(o.face_sampling);
    c.sampling.seed = o.seed;
    c.sampling.vertices = !o.no_vertex_samples;
    c.sampling.edges = !o.no_edge_samples;
    c.sampling.faces = !o.no_face_samples;
    validate(c.sampling);
    c.summary.fscore_thresholds = parse_fscore(o.fscore);
    c.summary.histogram_bins = o.histogram;
    if (o.hausdorff == "sampled") {
        c.hausdorff.reset();
    } else {
        c.hausdorff->relative_tolerance =
            o.hausdorff_tolerance > 0.0 ? o.hausdorff_tolerance : (o.hausdorff_abs_tolerance > 0.0 ? 0.0 : 1e-4);
        c.hausdorff->absolute_tolerance = o.hausdorff_abs_tolerance;
        c.hausdorff->max_evaluations = o.hausdorff_budget;
        validate(*c.hausdorff);
    }
    return c;
}

void set_threads(int threads)
{
    if (threads < 0 || threads > kMaxThreads)
        throw InvalidArgumentError(fmt::format("--threads: {} is outside 0..{} (0: all cores)", threads, kMaxThreads));
    if (threads > 0) omp_set_num_threads(threads);
}

void refuse_overwriting_inputs(const std::string& what, const std::string& output,
                               const std::vector<std::string>& inputs)
{
    if (output.empty() || output == "-") return;
    for (const auto& in : inputs)
        if (same_file(output, in))
            throw InvalidArgumentError(fmt::format(
                "{}: '{}' is the input file '{}'; meshdiff does not overwrite its inputs", what, output, in));
}

void write_json(const std::string& target, const nlohmann::json& j)
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

}  // namespace meshdiff::cli
