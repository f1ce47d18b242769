#include "options.h"

#include "meshdiff/error.h"

#include <fmt/format.h>
#include <omp.h>

#include <fstream>
#include <iostream>
#include <sstream>

namespace meshdiff::cli {

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
            for (int l = a; l <= b; ++l) levels.push_back(l);
        }
    }
    if (levels.empty() && !text.empty())
        throw InvalidArgumentError(fmt::format("--levels: '{}' is not a list like 1,2,5 or 1-20", text));
    return levels;
}

void add_profile_options(CLI::App* sub, ProfileCliOptions& o)
{
    sub->add_option("--levels", o.levels, "ring levels, e.g. 1,2,5,10,20 or 1-20")->capture_default_str();
    sub->add_flag("--no-global", o.no_global, "leave out the global level");
    sub->add_option("--curvature", o.curvature, "mean curvature estimator")
        ->check(CLI::IsMember(enum_names<CurvatureMethod>()))
        ->capture_default_str();
    sub->add_option("--weighting", o.weighting, "row weighting of the fitting estimators")
        ->check(CLI::IsMember(enum_names<RowWeighting>()))
        ->capture_default_str();
}

ProfileOptions to_profile_options(const ProfileCliOptions& o, bool keep_vertex_data)
{
    ProfileOptions p;
    p.levels = parse_levels(o.levels);
    p.global = !o.no_global;
    p.curvature.method = parse_enum<CurvatureMethod>(o.curvature);
    p.curvature.weighting = parse_enum<RowWeighting>(o.weighting);
    p.keep_vertex_data = keep_vertex_data;
    return p;
}

void add_compare_options(CLI::App* sub, CompareCliOptions& o)
{
    add_profile_options(sub, o.profile);
    sub->add_option("-k,--k", o.k, "constant k of the roughness distance (eq. 10)")->capture_default_str();
    sub->add_flag("--no-roughness", o.no_roughness, "skip the roughness half");
    sub->add_flag("--no-distance", o.no_distance, "skip the surface distance half");
    sub->add_option("-n,--samples", o.samples, "samples per direction (default: 10 x the larger face count, as Metro)");
    sub->add_option("--density", o.density, "samples per unit area instead of a count");
    sub->add_option("--face-sampling", o.face_sampling, "face sampling scheme")
        ->check(CLI::IsMember(enum_names<FaceSampling>()))
        ->capture_default_str();
    sub->add_option("--seed", o.seed, "seed of Monte Carlo sampling")->capture_default_str();
    sub->add_flag("--no-vertex-samples", o.no_vertex_samples, "do not sample vertices");
    sub->add_flag("--no-edge-samples", o.no_edge_samples, "do not sample edges");
    sub->add_flag("--no-face-samples", o.no_face_samples, "do not sample faces");
}

CompareOptions to_compare_options(const CompareCliOptions& o)
{
    CompareOptions c;
    c.profile = to_profile_options(o.profile, false);
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
    return c;
}

void set_threads(int threads)
{
    if (threads < 0) throw InvalidArgumentError(fmt::format("--threads: {} must be >= 0 (0: all cores)", threads));
    if (threads > 0) omp_set_num_threads(threads);
}

void write_json(const std::string& target, const nlohmann::json& j)
{
    if (target == "-") {
        std::cout << j.dump(2) << "\n";
        return;
    }
    std::ofstream out(target);
    if (!out) throw IoError(fmt::format("{}: cannot open for writing", target));
    out << j.dump(2) << "\n";
    if (!out) throw IoError(fmt::format("{}: write failed", target));
}

}  // namespace meshdiff::cli
