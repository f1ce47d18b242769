#include "options.h"

#include "meshdiff/error.h"
#include "meshdiff/frontend/options.h"
#include "meshdiff/report/html.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>

namespace meshdiff::cli {

std::string cli_spelling(const std::string& field)
{
    static const std::map<std::string, std::string> spelling = {
        {"profile.levels", "--levels"},
        {"profile.radii", "--radii"},
        {"profile.global", "--no-global"},
        {"profile.curvature.method", "--curvature"},
        {"profile.curvature.weighting", "--weighting"},
        {"profile.normalize", "--normalize"},
        {"profile.trim", "--trim"},
        {"measure", "--measure"},
        {"local", "--no-local"},
        {"local_trim", "--local-trim"},
        {"corsini_unbiased", "--unbiased-variance"},
        {"k", "--k"},
        {"roughness", "--no-roughness"},
        {"distance", "--no-distance"},
        {"sampling.samples", "--samples"},
        {"sampling.density", "--density"},
        {"sampling.face_scheme", "--face-sampling"},
        {"sampling.seed", "--seed"},
        {"sampling.vertices", "--no-vertex-samples"},
        {"sampling.edges", "--no-edge-samples"},
        {"sampling.faces", "--no-face-samples"},
        {"hausdorff", "--hausdorff"},
        {"hausdorff.relative_tolerance", "--hausdorff-tolerance"},
        {"hausdorff.absolute_tolerance", "--hausdorff-abs-tolerance"},
        {"hausdorff.max_evaluations", "--hausdorff-budget"},
        {"summary.fscore_thresholds", "--fscore"},
        {"summary.histogram_bins", "--histogram"},
        {"threads", "--threads"},
        {"outputs.json", "--json"},
        {"outputs.distance_map", "--distance-map"},
        {"outputs.distance_map_original", "--distance-map-original"},
        {"outputs.distance_maps", "--distance-maps"},
        {"outputs.samples_out", "--samples-out"},
        {"outputs.html", "--html"},
        {"outputs.color_range", "--color-range"},
        {"outputs.html_face_budget", "--html-face-budget"},
        {"profile.bootstrap", "--bootstrap"},
        {"profile.bootstrap_seed", "--bootstrap-seed"},
        {"profile.paper", "--paper"},
        {"outputs.vertex_data", "--vertex-data"},
        {"outputs.exact", "--exact"},
        {"outputs.exact_property", "--exact-property"},
        {"batch.shard", "--shard"},
        {"batch.pair_timeout", "--pair-timeout"},
        {"generate.kind", "SHAPE"},
        {"generate.subdivisions", "--subdivisions"},
        {"generate.frequency", "--frequency"},
        {"generate.radius", "--radius"},
        {"generate.noise", "--noise"},
        {"generate.axes", "--axes"},
        {"generate.major", "--major"},
        {"generate.minor", "--minor"},
        {"generate.n", "--n"},
        {"generate.vertices", "--vertices"},
        {"generate.amplitude", "--amplitude"},
        {"generate.spacing", "--spacing"},
        {"generate.seed", "--seed"},
        {"smooth.method", "--method"},
        {"smooth.update", "--update"},
        {"smooth.step_control", "--step-control"},
        {"smooth.iterations", "--iterations"},
        {"smooth.lambda", "--lambda"},
        {"smooth.mu", "--mu"},
        {"smooth.step", "--step"},
        {"smooth.implicit", "--implicit"},
        {"smooth.damping", "--damping"},
        {"smooth.epsilon", "--epsilon"},
        {"smooth.stability", "--stability"},
        {"record.every", "--profile-every"},
        {"record.output", "--json"},
        {"record.sampling.samples", "--distance-samples"},
        {"noise.seed", "--seed"},
        {"noise.amplitude", "--amplitude"},
        {"noise.unit", "--unit"},
        {"noise.direction", "--direction"},
        {"noise.distribution", "--distribution"},
    };
    const auto it = spelling.find(field);
    return it == spelling.end() ? std::string() : it->second;
}

namespace {

// The choices of an option enum, for its help text: "a | b | c".
template <class E>
std::string choices()
{
    std::string s;
    for (const auto& name : enum_names<E>()) s += (s.empty() ? "" : " | ") + name;
    return s;
}

// Registers --NAME as a text option of \p g, with \p default_text as the default shown in --help.
void add(CLI::App* sub, const std::string& name, Given& g, const std::string& help,
         const std::string& default_text = "", const char* type = "TEXT")
{
    g.option = sub->add_option(name, g.text, help)->type_name(type);
    if (!default_text.empty()) g.option->default_str(default_text);
}

std::string levels_text(const std::vector<int>& levels)
{
    std::string s;
    std::size_t i = 0;
    while (i < levels.size()) {
        std::size_t j = i;
        while (j + 1 < levels.size() && levels[j + 1] == levels[j] + 1) ++j;
        s += (s.empty() ? "" : ",") +
             (j > i + 1 ? fmt::format("{}-{}", levels[i], levels[j]) : fmt::format("{}", levels[i]));
        if (j == i + 1) s += fmt::format(",{}", levels[j]);
        i = j + 1;
    }
    return s;
}

}  // namespace

void add_profile_options(CLI::App* sub, ProfileCliOptions& o, bool with_radii, bool with_measure,
                         const ProfileOptions& defaults)
{
    add(sub, "--levels", o.levels, "ring levels, e.g. 1,2,5,10,20 or 1-20", levels_text(defaults.levels));
    if (with_radii)
        add(sub, "--radii", o.radii,
            "metric levels: radii on the unit-scaled mesh, e.g. 0.05,0.1,0.2, or 'default' "
            "(0.0125 * 2^(k/2), k = 0..8: 0.0125 to 0.2)");
    sub->add_flag("--no-global", o.no_global, "leave out the global level");
    sub->add_flag("--paper", o.paper,
                  "the paper's exact method: the goldfeather fit without row weights, the paper's normalisation, "
                  "untrimmed sigma (refused beside a --curvature, --weighting, --normalize or --trim that differs)");
    add(sub, "--curvature", o.curvature, "mean curvature estimator: " + choices<CurvatureMethod>(),
        to_string(defaults.curvature.method));
    add(sub, "--weighting", o.weighting,
        "row weighting of the goldfeather and quadric fits (not jet): " + choices<RowWeighting>(),
        to_string(defaults.curvature.weighting));
    add(sub, "--normalize", o.normalize,
        "scaling before curvature: paper (vertex centroid, mean vertex distance 1), area (area-weighted centroid, "
        "sqrt(area / 4 pi) = 1; does not drift under decimation), original (compare only: both meshes in the "
        "original's paper frame)",
        to_string(defaults.normalize));
    add(sub, "--trim", o.trim,
        fmt::format("trimmed sigma: leave out this share of the vertices with the largest |D| at every level, in "
                    "[0, {:g}]; 0: the paper's sigma",
                    kMaxTrim),
        fmt::format("{:g}", defaults.trim), "NUMBER");
    o.levels.option->type_name("LIST");
    if (with_radii) o.radii.option->type_name("LIST");
    if (!with_measure) return;
    add(sub, "--bootstrap", o.bootstrap,
        fmt::format("N resamples of the vertices for a {:g}% bootstrap interval of sigma at every level (0: none; at "
                    "most {}): whether a change of sigma is beyond the vertex sampling",
                    100.0 * kBootstrapConfidence, kMaxBootstrap),
        std::to_string(defaults.bootstrap), "UINT");
    add(sub, "--bootstrap-seed", o.bootstrap_seed, "seed of the bootstrap resamples",
        std::to_string(defaults.bootstrap_seed), "UINT");
    add(sub, "--measure", o.measure,
        "sigma: the paper's curvature-deviation profile; corsini: Corsini et al.'s dihedral-angle roughness "
        "(variance of dihedral angles per ring level, METHOD.md 6a)",
        to_string(CompareOptions{}.measure));
    sub->add_flag("--unbiased-variance", o.unbiased_variance,
                  "with --measure corsini: variance with divisor n - 1 instead of n");
}

ProfileOptions to_profile_options(const ProfileCliOptions& o, ProfileOptions defaults)
{
    ProfileOptions p = o.paper ? paper_profile_options(std::move(defaults)) : std::move(defaults);
    if (o.levels.given()) p.levels = parse_levels(o.levels.text);
    if (o.radii.given()) p.radii = parse_radii(o.radii.text);
    p.global = !o.no_global;
    if (o.trim.given()) p.trim = parse_number("profile.trim", o.trim.text);
    if (o.bootstrap.given()) p.bootstrap = std::size_t(parse_whole_number("profile.bootstrap", o.bootstrap.text));
    if (o.bootstrap_seed.given())
        p.bootstrap_seed = parse_whole_number("profile.bootstrap_seed", o.bootstrap_seed.text);
    if (o.normalize.given()) p.normalize = parse_enum_option<NormalizeMethod>("profile.normalize", o.normalize.text);
    if (o.curvature.given())
        p.curvature.method = parse_enum_option<CurvatureMethod>("profile.curvature.method", o.curvature.text);
    if (o.weighting.given())
        p.curvature.weighting = parse_enum_option<RowWeighting>("profile.curvature.weighting", o.weighting.text);
    validate(p);
    return p;
}

RoughnessMeasure to_measure(const ProfileCliOptions& o)
{
    return o.measure.given() ? parse_enum_option<RoughnessMeasure>("measure", o.measure.text)
                             : CompareOptions{}.measure;
}

void add_compare_options(CLI::App* sub, CompareCliOptions& o)
{
    const CompareOptions defaults;
    add_profile_options(sub, o.profile);
    o.k.option = sub->add_option("-k,--k", o.k.text, "constant k of the roughness distance (eq. 10)")
                     ->default_str(fmt::format("{}", defaults.k));
    sub->add_flag("--no-roughness", o.no_roughness, "skip the roughness half");
    sub->add_flag("--no-local", o.no_local,
                  "skip the local roughness difference (per level, the RMS over the processed mesh's vertices of the "
                  "detail on its L-rings of the change of H from the original's at the closest point)");
    add(sub, "--local-trim", o.local_trim,
        fmt::format("share of the vertices with the largest |difference| left out of each local RMS, in "
                    "[0, {:g}]",
                    kMaxTrim),
        fmt::format("{:g}", defaults.local_trim), "NUMBER");
    sub->add_flag("--no-distance", o.no_distance, "skip the surface distance half");
    o.samples.option = sub->add_option("-n,--samples", o.samples.text,
                                       "samples per direction (default: 10 x the larger face count, as Metro)");
    add(sub, "--density", o.density, "samples per unit area instead of a count");
    add(sub, "--face-sampling", o.face_sampling, "face sampling scheme: " + choices<FaceSampling>(),
        to_string(defaults.sampling.face_scheme));
    add(sub, "--seed", o.seed, "seed of Monte Carlo sampling", fmt::format("{}", defaults.sampling.seed));
    sub->add_flag("--no-vertex-samples", o.no_vertex_samples, "do not sample vertices");
    sub->add_flag("--no-edge-samples", o.no_edge_samples, "do not sample edges");
    sub->add_flag("--no-face-samples", o.no_face_samples, "do not sample faces");
    add(sub, "--hausdorff", o.hausdorff,
        "certified: also an interval [lower, upper] holding the true one-sided Hausdorff distances, and where "
        "they are attained; sampled: the sampled maxima only (Metro)",
        to_string(HausdorffMethod::Certified));
    add(sub, "--hausdorff-tolerance", o.hausdorff_tolerance,
        fmt::format("width of the certified interval relative to the value (default {:g}: four certain digits; "
                    "none when only --hausdorff-abs-tolerance is given)",
                    kDefaultHausdorffTolerance));
    add(sub, "--hausdorff-abs-tolerance", o.hausdorff_abs_tolerance,
        "width of the certified interval in the meshes' unit; with both tolerances the interval stops at "
        "max(relative x value, absolute), as Python's math.isclose");
    add(sub, "--hausdorff-budget", o.hausdorff_budget,
        "most triangle bounds per direction before the interval reached is reported (default 2,000,000 + 20 x "
        "the faces of both meshes)");
    add(sub, "--fscore", o.fscore,
        "F-score thresholds relative to the original's bounding-box diagonal, e.g. 0.001,0.005 (area-weighted "
        "face samples; in the JSON and the text report)");
    add(sub, "--histogram", o.histogram,
        "N bins over [0, max] of each direction's sample distances, in the JSON report (0: none)");
    for (Given* g : {&o.k, &o.density, &o.hausdorff_tolerance, &o.hausdorff_abs_tolerance})
        g->option->type_name("NUMBER");
    for (Given* g : {&o.samples, &o.seed, &o.hausdorff_budget, &o.histogram}) g->option->type_name("UINT");
    o.fscore.option->type_name("LIST");
}

CompareOptions to_compare_options(const CompareCliOptions& o)
{
    CompareOptions c;
    c.profile = to_profile_options(o.profile);  // validated again with the measure below
    c.measure = to_measure(o.profile);
    c.corsini_unbiased = o.profile.unbiased_variance;
    if (o.k.given()) c.k = parse_number("k", o.k.text);
    c.roughness = !o.no_roughness;
    c.local = !o.no_local;
    if (o.local_trim.given()) c.local_trim = parse_number("local_trim", o.local_trim.text);
    c.distance = !o.no_distance;
    if (o.samples.given()) c.sampling.samples = parse_whole_number("sampling.samples", o.samples.text);
    if (o.density.given()) c.sampling.density = parse_number("sampling.density", o.density.text);
    if (o.face_sampling.given())
        c.sampling.face_scheme = parse_enum_option<FaceSampling>("sampling.face_scheme", o.face_sampling.text);
    if (o.seed.given()) c.sampling.seed = parse_whole_number("sampling.seed", o.seed.text);
    c.sampling.vertices = !o.no_vertex_samples;
    c.sampling.edges = !o.no_edge_samples;
    c.sampling.faces = !o.no_face_samples;
    if (o.fscore.given()) c.summary.fscore_thresholds = parse_fscore(o.fscore.text);
    if (o.histogram.given()) c.summary.histogram_bins = parse_whole_number("summary.histogram_bins", o.histogram.text);
    HausdorffRequest h;
    if (o.hausdorff.given()) h.method = parse_enum_option<HausdorffMethod>("hausdorff", o.hausdorff.text);
    if (o.hausdorff_tolerance.given())
        h.relative_tolerance = parse_number("hausdorff.relative_tolerance", o.hausdorff_tolerance.text);
    if (o.hausdorff_abs_tolerance.given())
        h.absolute_tolerance = parse_number("hausdorff.absolute_tolerance", o.hausdorff_abs_tolerance.text);
    if (o.hausdorff_budget.given()) h.budget = parse_whole_number("hausdorff.max_evaluations", o.hausdorff_budget.text);
    c.hausdorff = hausdorff_options(h);
    validate(c);
    return c;
}

void add_compare_output_options(CLI::App* sub, CompareOutputCliOptions& o)
{
    CompareOutputs& out = o.outputs;
    sub->add_option("--json", out.json, "write the JSON report to FILE, or '-' for stdout");
    sub->add_option("--distance-map", out.distance_map,
                    "write the processed mesh with per-vertex distance to the original and a colour ramp as PLY");
    sub->add_option("--distance-map-original", out.distance_map_original,
                    "write the original mesh with per-vertex distance to the processed one as PLY (with "
                    "--distance-map: one colour scale for both)");
    sub->add_option("--distance-maps", out.distance_maps,
                    "write both maps, PREFIX_original.ply and PREFIX_processed.ply, on one colour scale");
    sub->add_option("--samples-out", out.samples_out,
                    "write the samples of both directions with their distances as a binary PLY point cloud "
                    "(x y z distance signed_distance kind direction face)");
    sub->add_option("--html", out.html,
                    "write the HTML report to FILE: one self-contained page (no network) with the summary, plots and "
                    "both meshes in 3D coloured by distance or roughness D_L (docs/cli.md)");
    sub->add_option("--color-range", o.color_range,
                    "the distance colour range of the maps and the HTML report: MIN MAX, LO:HI, max, or pNN (0 to "
                    "that percentile of both meshes' vertex distances; default: p99 for both)")
        ->expected(1, 2);
    add_html_face_budget_option(sub, o.html_face_budget);
}

void add_html_face_budget_option(CLI::App* sub, Given& budget)
{
    budget.option = sub->add_option("--html-face-budget", budget.text,
                                    fmt::format("with --html: most faces drawn per mesh (default {}, at least {}); a "
                                                "larger mesh is drawn clustered, the page says so, and every number "
                                                "is that of the full mesh",
                                                kDefaultHtmlFaceBudget, kMinHtmlFaceBudget));
    budget.option->type_name("UINT");
}

std::size_t html_face_budget(const Given& budget)
{
    if (!budget.given()) return kDefaultHtmlFaceBudget;
    return std::size_t(parse_whole_number("outputs.html_face_budget", budget.text));
}

CompareOutputs to_compare_outputs(const CompareOutputCliOptions& o)
{
    CompareOutputs out = o.outputs;
    out.html_face_budget = html_face_budget(o.html_face_budget);
    if (o.color_range.size() == 1) parse_color_range(o.color_range[0], out);
    if (o.color_range.size() == 2)
        out.color_range = std::pair{parse_number("outputs.color_range", o.color_range.at(0)),
                                    parse_number("outputs.color_range", o.color_range.at(1))};
    return out;
}

void add_threads_option(CLI::App* sub, Given& threads)
{
    add(sub, "--threads", threads, "worker threads (0: all cores)", "0", "UINT");
}

void set_threads(const Given& threads)
{
    if (!threads.given()) return;
    const std::uint64_t n = parse_whole_number("threads", threads.text);
    std::string warning;
    const int use = usable_threads((long long)std::min<std::uint64_t>(n, std::uint64_t(LLONG_MAX)), warning);
    if (!warning.empty()) std::cerr << "meshdiff: warning: " << cli_spelling("threads") << ": " << warning << "\n";
    if (use > 0) omp_set_num_threads(use);
}

}  // namespace meshdiff::cli
