#include "meshdiff/frontend/options.h"

#include "meshdiff/distance/surface_distance.h"
#include "meshdiff/roughness/metric_levels.h"
#include "meshdiff/roughness/roughness.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>
#include <system_error>
#include <thread>

namespace meshdiff {

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

// The items of a comma-separated list ("" has none).
std::vector<std::string> items(const std::string& text)
{
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) out.push_back(item);
    return out;
}

}  // namespace

const std::vector<std::string>& option_fields()
{
    static const std::vector<std::string> fields = {
        "profile.levels",
        "profile.radii",
        "profile.global",
        "profile.curvature.method",
        "profile.curvature.weighting",
        "profile.outlier_fraction",
        "profile.normalize",
        "profile.trim",
        "profile.bootstrap",
        "profile.bootstrap_seed",
        "profile.paper",
        "measure",
        "local",
        "local_trim",
        "corsini_unbiased",
        "k",
        "roughness",
        "distance",
        "sampling.samples",
        "sampling.density",
        "sampling.face_scheme",
        "sampling.seed",
        "sampling.vertices",
        "sampling.edges",
        "sampling.faces",
        "hausdorff",
        "hausdorff.relative_tolerance",
        "hausdorff.absolute_tolerance",
        "hausdorff.max_evaluations",
        "hausdorff.max_round_triangles",
        "summary.fscore_thresholds",
        "summary.histogram_bins",
        "threads",
        "outputs.json",
        "outputs.distance_map",
        "outputs.distance_map_original",
        "outputs.distance_maps",
        "outputs.samples_out",
        "outputs.html",
        "outputs.color_range",
        "outputs.html_face_budget",
        "outputs.vertex_data",
        "outputs.exact",
        "outputs.exact_property",
    };
    return fields;
}

int parse_level(const std::string& item)
{
    const char* field = "profile.levels";
    const bool digits = !item.empty() && std::all_of(item.begin() + (item[0] == '-' ? 1 : 0), item.end(),
                                                     [](char c) { return c >= '0' && c <= '9'; });
    if (!digits || item == "-") throw OptionError(field, fmt::format("'{}' is not a level (a whole number)", item));
    errno = 0;
    const long long v = std::strtoll(item.c_str(), nullptr, 10);
    if (errno == ERANGE || v < 1 || v > kMaxLevel)
        throw OptionError(field, fmt::format("level {} is out of 1..{}", item, kMaxLevel));
    return int(v);
}

std::vector<int> parse_levels(const std::string& text)
{
    const char* field = "profile.levels";
    auto malformed = [&] { return OptionError(field, fmt::format("'{}' is not a list like 1,2,5 or 1-20", text)); };
    auto to_int = [&](const std::string& s) {
        try {
            return parse_level(s);
        } catch (const OptionError&) {
            if (s.empty() || s.find_first_not_of("-0123456789") != std::string::npos) throw malformed();
            throw;
        }
    };
    std::vector<int> levels;
    for (const std::string& item : items(text)) {
        const auto dash = item.find('-', 1);
        if (dash == std::string::npos) {
            levels.push_back(to_int(item));
        } else {
            const int a = to_int(item.substr(0, dash)), b = to_int(item.substr(dash + 1));
            if (b < a) throw OptionError(field, fmt::format("empty range '{}'", item));
            if (std::size_t(b - a) >= kMaxLevels)
                throw OptionError(field,
                                  fmt::format("the range '{}' has more than the limit of {} levels", item, kMaxLevels));
            for (int l = a; l <= b; ++l) levels.push_back(l);
        }
        if (levels.size() > kMaxLevels)
            throw OptionError(field, fmt::format("'{}' lists more than the limit of {} levels", text, kMaxLevels));
    }
    if (levels.empty() && !text.empty()) throw malformed();
    return levels;
}

std::vector<double> parse_radii(const std::string& text)
{
    const char* field = "profile.radii";
    if (text == "default") return default_radii();
    std::vector<double> radii;
    for (const std::string& item : items(text)) {
        const auto v = finite_number(item);
        if (!v)
            throw OptionError(field, fmt::format("'{}' is not a list of numbers like 0.05,0.1,0.2 or 'default'", text));
        radii.push_back(*v);
        if (radii.size() > kMaxRadii)
            throw OptionError(field, fmt::format("'{}' lists more than the limit of {} radii", text, kMaxRadii));
    }
    if (radii.empty() && !text.empty())
        throw OptionError(field, fmt::format("'{}' is not a list of numbers like 0.05,0.1,0.2 or 'default'", text));
    check_radii(radii);
    return radii;
}

std::vector<double> parse_fscore(const std::string& text)
{
    const char* field = "summary.fscore_thresholds";
    SummaryOptions s;
    for (const std::string& item : items(text)) {
        const auto v = finite_number(item);
        if (!v)
            throw OptionError(
                field,
                fmt::format("'{}' is not a list of thresholds like 0.001,0.005 (relative to the diagonal)", text));
        s.fscore_thresholds.push_back(*v);
        if (s.fscore_thresholds.size() > kMaxFscoreThresholds) break;  // validate() says so
    }
    if (s.fscore_thresholds.empty() && !text.empty())
        throw OptionError(
            field, fmt::format("'{}' is not a list of thresholds like 0.001,0.005 (relative to the diagonal)", text));
    validate(s);
    return s.fscore_thresholds;
}

double parse_number(const char* field, const std::string& text)
{
    // strtod: beyond the range of double is +-inf or (nearly) 0, for the rules to judge as values.
    char* end = nullptr;
    const double v = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || std::isspace(static_cast<unsigned char>(text[0])))
        throw OptionError(field, fmt::format("'{}' is not a number", text));
    return v;
}

std::uint64_t parse_whole_number(const char* field, const std::string& text)
{
    const bool digits = !text.empty() && text.size() <= 20 &&
                        std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    errno = 0;
    const unsigned long long v = digits ? std::strtoull(text.c_str(), nullptr, 10) : 0;
    if (!digits || errno == ERANGE)
        throw OptionError(field, fmt::format("'{}' is not a whole number from 0 to {}", text,
                                             std::numeric_limits<std::uint64_t>::max()));
    return std::uint64_t(v);
}

std::optional<HausdorffOptions> hausdorff_options(const HausdorffRequest& r)
{
    if (!is_known(r.method)) throw OptionError("hausdorff", "not a known Hausdorff method");
    if (r.method == HausdorffMethod::Sampled) {
        for (const auto& [given, field] : {std::pair{r.relative_tolerance.has_value(), "hausdorff.relative_tolerance"},
                                           {r.absolute_tolerance.has_value(), "hausdorff.absolute_tolerance"},
                                           {r.budget.has_value(), "hausdorff.max_evaluations"}})
            if (given) throw OptionError(field, "applies to {hausdorff} certified only, not sampled");
        return std::nullopt;
    }
    HausdorffOptions o;
    if (r.relative_tolerance && !(*r.relative_tolerance > 0.0))
        throw OptionError("hausdorff.relative_tolerance", fmt::format("{} is outside [{}, {}]", *r.relative_tolerance,
                                                                      kMinHausdorffTolerance, kMaxHausdorffTolerance));
    if (r.absolute_tolerance && !(*r.absolute_tolerance > 0.0))
        throw OptionError("hausdorff.absolute_tolerance",
                          fmt::format("{} must be finite and > 0", *r.absolute_tolerance));
    if (r.budget && *r.budget == 0)
        throw OptionError("hausdorff.max_evaluations", fmt::format("0 is outside 1..{}", kMaxHausdorffBudget));
    o.relative_tolerance = r.relative_tolerance.value_or(r.absolute_tolerance ? 0.0 : kDefaultHausdorffTolerance);
    o.absolute_tolerance = r.absolute_tolerance.value_or(0.0);
    o.max_evaluations = r.budget.value_or(0);
    validate(o);
    return o;
}

int usable_threads(long long threads, std::string& warning)
{
    validate_threads(threads);
    warning.clear();
    const int want = int(threads);
    if (want <= 1 || want <= omp_get_num_procs()) return want;
    // Start want - 1 threads (OpenMP's team besides the calling thread), with the
    // default stack size OpenMP uses too, and stop them again.
    std::vector<std::thread> probe;
    probe.reserve(std::size_t(want - 1));
    std::mutex m;
    std::condition_variable cv;
    bool go = false;
    try {
        for (int i = 1; i < want; ++i)
            probe.emplace_back([&] {
                std::unique_lock<std::mutex> lock(m);
                cv.wait(lock, [&] { return go; });
            });
    } catch (const std::system_error&) {}
    {
        const std::lock_guard<std::mutex> lock(m);
        go = true;
    }
    cv.notify_all();
    for (auto& t : probe) t.join();
    const int started = int(probe.size()) + 1;
    if (started < want) {
        const int use = std::max(1, started / 2);  // leave room for the rest of the run
        warning = fmt::format("only {} of the {} threads asked for could be started; using {}", started, want, use);
        return use;
    }
    return want;
}

void validate_threads(long long threads)
{
    if (threads < 0 || threads > kMaxThreads)
        throw OptionError("threads", fmt::format("{} is outside 0..{} (0: all cores)", threads, kMaxThreads));
}

void validate_shard(std::size_t index, std::size_t count, const std::string& text)
{
    if (count == 0 || index >= count || count > kMaxShards)
        throw OptionError("batch.shard", fmt::format("'{}' needs 0 <= I < N <= {}", text, kMaxShards));
}

void validate_pair_timeout(double seconds)
{
    if (!(seconds >= 0.0 && seconds <= kMaxPairTimeout))
        throw OptionError("batch.pair_timeout",
                          fmt::format("{} is outside 0..{:g} seconds (0: no limit)", seconds, kMaxPairTimeout));
}

}  // namespace meshdiff
