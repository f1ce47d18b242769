#include "meshdiff/compare.h"

#include "meshdiff/error.h"
#include "meshdiff/version.h"

#include <fmt/format.h>

#include <future>

namespace meshdiff {

Comparison compare_meshes(const LoadedMesh& a, const LoadedMesh& b, const CompareOptions& options)
{
    if (!options.roughness && !options.distance)
        throw InvalidArgumentError("compare: both halves are switched off (--no-roughness and --no-distance)");
    if (!(options.k > 0.0) || !std::isfinite(options.k))
        throw InvalidArgumentError(fmt::format("compare: k = {} must be > 0", options.k));
    validate(options.sampling);
    Comparison c;
    c.options = options;
    // The serial topology reports overlap the (partly serial) analyses.
    auto facts_a = std::async(std::launch::async, [&a] { return mesh_facts(a); });
    auto facts_b = std::async(std::launch::async, [&b] { return mesh_facts(b); });
    if (options.roughness) {
        c.original_profile = roughness_profile(a.mesh, options.profile);
        c.processed_profile = roughness_profile(b.mesh, options.profile);
        c.roughness = roughness_distance(*c.original_profile, *c.processed_profile, options.k);
    }
    if (options.distance) c.distance = surface_distance(a.mesh, b.mesh, options.sampling);
    c.original = facts_a.get();
    c.processed = facts_b.get();
    return c;
}

nlohmann::json distance_stats_json(const DistanceStats& s, double diagonal)
{
    auto block = [](const DistanceStats& d) {
        return nlohmann::json{{"min", d.min},    {"max", d.max}, {"mean", d.mean}, {"rms", d.rms},
                              {"std", d.stddev}, {"p50", d.p50}, {"p95", d.p95},   {"p99", d.p99}};
    };
    nlohmann::json j = block(s);
    j["samples"] = s.n_samples();
    j["samples_by_kind"] = {{"vertex", s.n_vertex}, {"edge", s.n_edge}, {"face", s.n_face}};
    j["relative"] = block(relative_to(s, diagonal));
    return j;
}

nlohmann::json comparison_json(const Comparison& c)
{
    nlohmann::json j;
    j["schema"] = "meshdiff.compare/1";
    j["meshdiff_version"] = MESHDIFF_VERSION;
    auto side = [&](const MeshFacts& f, const std::optional<RoughnessProfile>& p) {
        if (p) return profile_json(f, *p);
        nlohmann::json o;
        o["schema"] = "meshdiff.profile/1";
        o["mesh"] = mesh_json(f);
        o["warnings"] = profile_warnings(f, nullptr);
        return o;
    };
    j["original"] = side(c.original, c.original_profile);
    j["processed"] = side(c.processed, c.processed_profile);
    j["roughness_distance"] = c.roughness ? roughness_distance_json(*c.roughness) : nlohmann::json(nullptr);
    if (c.distance) {
        const auto& d = *c.distance;
        const auto& so = c.options.sampling;
        j["surface_distance"] = {
            {"forward", distance_stats_json(d.forward, d.diagonal)},
            {"backward", distance_stats_json(d.backward, d.diagonal)},
            {"hausdorff", d.hausdorff},
            {"hausdorff_relative", d.hausdorff / d.diagonal},
            {"diagonal", d.diagonal},
            {"diagonal_of", "bounding box of the original mesh"},
            {"metro_diagonal", d.metro_diagonal},
            {"hausdorff_relative_metro", d.hausdorff / d.metro_diagonal},
            {"metro_diagonal_of", "union bounding box of both meshes widened by 2% of its diagonal on every side"},
            {"sampling",
             {{"face_scheme", so.face_scheme == FaceSampling::SimilarTriangles ? "similar-triangles" : "monte-carlo"},
              {"vertices", so.vertices},
              {"edges", so.edges},
              {"faces", so.faces},
              {"samples_requested", so.samples ? nlohmann::json(*so.samples) : nlohmann::json(nullptr)},
              {"density_requested", so.density ? nlohmann::json(*so.density) : nlohmann::json(nullptr)},
              {"seed", so.seed}}},
            {"forward_is", "samples on the original, distances to the processed surface"},
            {"cutoff", nullptr}};
    } else {
        j["surface_distance"] = nullptr;
    }
    return j;
}

namespace {

std::string facts_text(const std::string& title, const MeshFacts& f)
{
    const auto& t = f.topology;
    std::string s = fmt::format("{}: {}\n", title, f.input.path);
    s += fmt::format("  {} vertices, {} faces, {} component{}, {}, area {:.6g}, bbox diagonal {:.6g}\n", t.vertices,
                     t.faces, t.components, t.components == 1 ? "" : "s",
                     t.closed() ? "closed" : fmt::format("open ({} boundary loops)", t.boundary_loops), f.area,
                     f.box.diagonal());
    const auto w = profile_warnings(f, nullptr);
    for (const auto& line : w) s += "  ! " + line + "\n";
    return s;
}

std::string stats_text(const std::string& title, const DistanceStats& s, double diag)
{
    std::string out = fmt::format("{}\n", title);
    out += fmt::format("  samples: {} ({} vertex, {} edge, {} face)\n", s.n_samples(), s.n_vertex, s.n_edge, s.n_face);
    out += fmt::format("  {:>5} {:>14} {:>14}\n", "", "absolute", "wrt diagonal");
    const std::pair<const char*, double> rows[] = {{"min", s.min},    {"max", s.max}, {"mean", s.mean}, {"RMS", s.rms},
                                                   {"std", s.stddev}, {"p50", s.p50}, {"p95", s.p95},   {"p99", s.p99}};
    for (const auto& [name, v] : rows) out += fmt::format("  {:>5} {:>14.6g} {:>14.6g}\n", name, v, v / diag);
    return out;
}

}  // namespace

std::string comparison_text(const Comparison& c)
{
    std::string s = fmt::format("meshdiff {}: original vs processed\n\n", MESHDIFF_VERSION);
    s += facts_text("Mesh 1 (original)", c.original);
    s += facts_text("Mesh 2 (processed)", c.processed);
    if (c.roughness) {
        const auto& pa = *c.original_profile;
        const auto& pb = *c.processed_profile;
        s += fmt::format(
            "\nRoughness profiles ({} mean curvature on each mesh scaled to unit mean radius: s = {:.6g} "
            "and {:.6g})\n",
            to_string(pa.curvature_options.method), pa.normalization.scale, pb.normalization.scale);
        s += fmt::format("  d_L = ln(|s' - s| / s + k) - ln(k), k = {:g}; change = (s' - s) / s\n", c.roughness->k);
        s += fmt::format("  {:>7} {:>13} {:>13} {:>10} {:>9}\n", "level", "sigma orig", "sigma proc", "change", "d_L");
        auto row = [&](const std::string& name, double sa, double sb, const LevelDistance& d) {
            const std::string change =
                d.relative_change_defined ? fmt::format("{:+.2f}%", 100.0 * d.relative_change) : "undef";
            s += fmt::format("  {:>7} {:>13.6g} {:>13.6g} {:>10} {:>9.4f}\n", name, sa, sb, change, d.distance);
        };
        for (const auto& d : c.roughness->levels) {
            double sa = 0, sb = 0;
            for (const auto& l : pa.levels)
                if (l.level == d.level) sa = l.sigma;
            for (const auto& l : pb.levels)
                if (l.level == d.level) sb = l.sigma;
            row(std::to_string(d.level), sa, sb, d);
        }
        if (c.roughness->has_global) row("global", pa.global.sigma, pb.global.sigma, c.roughness->global);
        if (pa.curvature_undefined || pb.curvature_undefined)
            s += fmt::format("  undefined curvature: {} and {} vertices left out\n", pa.curvature_undefined,
                             pb.curvature_undefined);
        for (const auto* p : {&pa, &pb})
            for (const auto& w : profile_warnings(p == &pa ? c.original : c.processed, p))
                if (w.find("outliers") != std::string::npos)
                    s += fmt::format("  ! {}: {}\n", p == &pa ? "original" : "processed", w);
    }
    if (c.distance) {
        const auto& d = *c.distance;
        const auto& so = c.options.sampling;
        s += fmt::format("\nSurface distance (Metro-style: exact point-to-triangle distances, {} face sampling{})\n",
                         so.face_scheme == FaceSampling::SimilarTriangles ? "similar-triangles" : "Monte Carlo",
                         so.face_scheme == FaceSampling::MonteCarlo ? fmt::format(", seed {}", so.seed) : "");
        s += fmt::format("  diagonal = bounding-box diagonal of the original = {:.6g}\n", d.diagonal);
        s += stats_text("Forward distance (M1 -> M2):", d.forward, d.diagonal);
        s += stats_text("Backward distance (M2 -> M1):", d.backward, d.diagonal);
        s += fmt::format(
            "Hausdorff distance: {:.6g} ({:.6g} wrt bounding box diagonal; {:.6g} wrt Metro's "
            "widened union box, diagonal {:.6g})\n",
            d.hausdorff, d.hausdorff / d.diagonal, d.hausdorff / d.metro_diagonal, d.metro_diagonal);
    }
    return s;
}

}  // namespace meshdiff
