#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"

#include "meshdiff/version.h"

#include "sections.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <utility>

namespace meshdiff {

nlohmann::json roughness_distance_json(const RoughnessDistance& d)
{
    nlohmann::json j;
    j["k"] = d.k;
    j["formula"] = "d = ln(|s' - s| / s + k) - ln(k); relative_change = (s' - s) / s";
    // The arrays of one kind of level (rings or radii): the keys, d, the
    // relative change (null where undefined) and the keys where sigma = 0.
    auto arrays = [&](const auto& list, auto key, const char* keys, const char* distance, const char* change,
                      const char* zero) {
        nlohmann::json k = nlohmann::json::array(), dist = nlohmann::json::array(), rel = nlohmann::json::array();
        nlohmann::json undefined = nlohmann::json::array();
        for (const auto& l : list) {
            k.push_back(key(l));
            dist.push_back(l.defined ? nlohmann::json(l.distance) : nlohmann::json(nullptr));
            rel.push_back(l.relative_change_defined ? nlohmann::json(l.relative_change) : nlohmann::json(nullptr));
            if (l.reference_zero) undefined.push_back(key(l));
        }
        j[keys] = k;
        j[distance] = dist;
        j[change] = rel;
        j[zero] = undefined;
    };
    arrays(
        d.levels, [](const auto& l) { return l.level; }, "levels", "distance", "relative_change",
        "reference_zero_levels");
    if (d.has_global)
        j["global"] = {{"distance", d.global.defined ? nlohmann::json(d.global.distance) : nlohmann::json(nullptr)},
                       {"relative_change", d.global.relative_change_defined ? nlohmann::json(d.global.relative_change)
                                                                            : nlohmann::json(nullptr)},
                       {"reference_zero", d.global.reference_zero}};
    if (!d.radii.empty())
        arrays(
            d.radii, [](const auto& l) { return l.radius; }, "radii", "distance_radii", "relative_change_radii",
            "reference_zero_radii");
    return j;
}

nlohmann::json local_roughness_json(const LocalRoughnessDistance& d)
{
    auto numbers = [](const std::vector<double>& v) {
        nlohmann::json a = nlohmann::json::array();
        for (double x : v) a.push_back(std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr));
        return a;
    };
    nlohmann::json j;
    j["definition"] =
        "rms_L = sqrt(area-weighted mean over the processed mesh's vertices i of (F(i) - mean of F over the "
        "processed L-ring of i)^2), F(i) = H'(i) - H(cp(i)) the change of mean curvature, H of the original "
        "interpolated at its closest point to i (global: all other vertices); rms_radii: the same over the "
        "original's vertices and balls, F = H - H'(cp); the largest |values| trimmed";
    j["levels"] = d.levels;
    j["rms"] = numbers(d.rms);
    j["vertices_used"] = d.used;
    j["radii"] = d.radii;
    j["rms_radii"] = numbers(d.rms_radii);
    j["global"] = d.has_global && std::isfinite(d.global) ? nlohmann::json(d.global) : nlohmann::json(nullptr);
    j["vertices"] = d.vertices;
    j["vertices_radii"] = d.vertices_radii;
    j["trim"] = d.trim;
    return j;
}

nlohmann::json corsini_distance_json(const CorsiniDistance& d)
{
    auto change = [](const LevelDistance& l) {
        return l.relative_change_defined ? nlohmann::json(l.relative_change) : nlohmann::json(nullptr);
    };
    auto one = [&](const LevelDistance& l) {
        return nlohmann::json{{"distance", l.defined ? nlohmann::json(l.distance) : nlohmann::json(nullptr)},
                              {"relative_change", change(l)},
                              {"reference_zero", l.reference_zero}};
    };
    nlohmann::json levels = nlohmann::json::array(), dist = nlohmann::json::array(), rel = nlohmann::json::array();
    nlohmann::json zero = nlohmann::json::array();
    for (const auto& l : d.levels) {
        levels.push_back(l.level);
        dist.push_back(l.defined ? nlohmann::json(l.distance) : nlohmann::json(nullptr));
        rel.push_back(change(l));
        if (l.reference_zero) zero.push_back(l.level);
    }
    nlohmann::json j;
    j["k"] = d.k;
    j["formula"] = "R(M, M') = ln(|R' - R| / R + k) - ln(k); relative_change = (R' - R) / R";
    j["levels"] = levels;
    j["distance"] = dist;
    j["relative_change"] = rel;
    j["reference_zero_levels"] = zero;
    j["global"] = d.has_global ? one(d.global) : nlohmann::json(nullptr);
    j["multiscale"] = d.has_multiscale ? one(d.multiscale) : nlohmann::json(nullptr);
    return j;
}

nlohmann::json same_connectivity_json(const SameConnectivity& s, double diagonal)
{
    return {{"vertices", s.vertices},
            {"faces", s.faces},
            {"degenerate_faces_skipped", s.degenerate_faces},
            {"displacement",
             {{"rms", s.displacement_rms},
              {"max", s.displacement_max},
              {"max_vertex", s.max_vertex},
              {"relative", {{"rms", s.displacement_rms / diagonal}, {"max", s.displacement_max / diagonal}}}}},
            {"normal_deviation_deg", {{"rms", s.normal_rms_deg}, {"max", s.normal_max_deg}, {"max_face", s.max_face}}},
            {"definition",
             "displacement |p' - p| per vertex; normal deviation: angle between the unit normals of the same face in "
             "both meshes, faces non-degenerate in both; RMS and max over vertices (faces), each counted once"}};
}

nlohmann::json comparison_json(const Comparison& c)
{
    nlohmann::json j;
    j["schema"] = "meshdiff.compare/2";
    j["meshdiff_version"] = MESHDIFF_VERSION;
    auto side = [&](const MeshFacts& f, const std::optional<RoughnessProfile>& p) {
        if (p) return profile_json(f, *p);
        nlohmann::json o;
        o["schema"] = "meshdiff.profile/1";
        o["mesh"] = mesh_json(f);
        o["warnings"] = warnings_json(warnings(f));
        return o;
    };
    j["original"] = side(c.original, c.original_profile);
    j["processed"] = side(c.processed, c.processed_profile);
    j["roughness_distance"] = c.roughness ? roughness_distance_json(*c.roughness) : nlohmann::json(nullptr);
    if (c.roughness && c.local_roughness) j["roughness_distance"]["local"] = local_roughness_json(*c.local_roughness);
    if (c.corsini) {  // only with --measure corsini: other reports are unchanged
        j["measure"] = "corsini";
        j["original"]["corsini"] = corsini_json(*c.original_corsini);
        j["processed"]["corsini"] = corsini_json(*c.processed_corsini);
        j["corsini_distance"] = corsini_distance_json(*c.corsini);
    }
    j["roughness_unavailable"] =
        c.roughness_unavailable.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.roughness_unavailable);
    if (c.distance) {
        j["surface_distance"] = surface_distance_json(*c.distance, c.options.sampling);
    } else {
        j["surface_distance"] = nullptr;
    }
    if (c.same_connectivity) {
        j["same_connectivity"] = same_connectivity_json(*c.same_connectivity, c.original.box.diagonal());
        j["same_connectivity_unavailable"] = nullptr;
    } else {
        j["same_connectivity"] = nullptr;
        j["same_connectivity_unavailable"] = c.same_connectivity_unavailable;
    }
    return j;
}

nlohmann::json batch_ok_json(const std::string& id, const std::string& original, const std::string& processed,
                             const Comparison& c)
{
    return batch_ok_json(id, original, processed, comparison_json(c));
}

nlohmann::json batch_ok_json(const std::string& id, const std::string& original, const std::string& processed,
                             nlohmann::json result)
{
    return {
        {"id", id}, {"original", original}, {"processed", processed}, {"result", std::move(result)}, {"status", "ok"}};
}

nlohmann::json batch_error_json(const std::string& id, const std::string& original, const std::string& processed,
                                const std::string& error, int exit_code)
{
    return {{"id", id},          {"original", original}, {"processed", processed},
            {"status", "error"}, {"error", error},       {"exit_code", exit_code}};
}

namespace {

std::string facts_text(const std::string& title, const MeshFacts& f)
{
    const auto& t = f.topology;
    std::string s = fmt::format("{}: {}\n", title, f.input.path);
    if (f.input.point_cloud)
        return s +
               fmt::format("  point cloud: {} points, no faces, bbox diagonal {:.6g}\n", t.vertices, f.box.diagonal());
    s += fmt::format("  {} vertices, {} faces, {} component{}, {}, area {:.6g}, bbox diagonal {:.6g}\n", t.vertices,
                     t.faces, t.components, t.components == 1 ? "" : "s",
                     t.closed() ? "closed" : fmt::format("open ({} boundary loops)", t.boundary_loops), f.area,
                     f.box.diagonal());
    for (const auto& w : warnings(f)) s += "  ! " + w.text + "\n";
    return s;
}

// One row of a per-level table: its name, the distance (with both values)
// and the local difference (when the table has that column; NaN: no data).
struct LevelRow
{
    std::string name;
    const LevelDistance* d;
    double local;
    // The two profiles' levels, for their bootstrap intervals (nullptr: none).
    const LevelRoughness* original = nullptr;
    const LevelRoughness* processed = nullptr;
};

struct LevelColumns
{
    const char* key;
    const char* original;
    const char* processed;
    const char* distance;
    bool local;
    const char* note = "";
    bool bootstrap = false;  //!< a column saying whether the two bootstrap intervals of sigma overlap
};

// The table of a per-level measure (sigma, Corsini's R): a value without data
// and a distance or change that is no number print as "-".
std::string level_table(const LevelColumns& c, const std::vector<LevelRow>& rows)
{
    std::string s =
        fmt::format("  {:>7} {:>13} {:>13} {:>10} {:>9}", c.key, c.original, c.processed, "change", c.distance);
    s += (c.local ? fmt::format(" {:>11}", "local") : std::string()) +
         (c.bootstrap ? fmt::format(" {:>10}", "intervals") : std::string()) + c.note + "\n";
    auto value = [](bool has, double x) { return has ? fmt::format("{:.6g}", x) : std::string("-"); };
    for (const auto& r : rows) {
        const LevelDistance& d = *r.d;
        const std::string change = d.relative_change_defined ? fmt::format("{:+.2f}%", 100.0 * d.relative_change)
                                   : d.defined               ? "undef"
                                                             : "-";
        s += fmt::format("  {:>7} {:>13} {:>13} {:>10} {:>9}", r.name, value(d.original_data, d.original),
                         value(d.processed_data, d.processed), change,
                         d.defined ? fmt::format("{:.4f}", d.distance) : std::string("-"));
        if (c.local) s += fmt::format(" {:>11}", std::isfinite(r.local) ? fmt::format("{:.6g}", r.local) : "-");
        if (c.bootstrap) {
            const auto* a = r.original ? &r.original->sigma_interval : nullptr;
            const auto* b = r.processed ? &r.processed->sigma_interval : nullptr;
            std::string verdict = "-";
            if (a && b && *a && *b)
                verdict = (*a)->second < (*b)->first || (*b)->second < (*a)->first ? "apart" : "overlap";
            s += fmt::format(" {:>10}", verdict);
        }
        s += "\n";
    }
    return s;
}

std::string same_connectivity_text(const Comparison& c)
{
    if (!c.same_connectivity)
        return fmt::format("\nSame connectivity: no ({}); no displacement or normal deviation\n",
                           c.same_connectivity_unavailable);
    const SameConnectivity& m = *c.same_connectivity;
    const double diag = c.original.box.diagonal();
    std::string s = fmt::format("\nSame connectivity ({} vertices, {} faces compared", m.vertices, m.faces);
    if (m.degenerate_faces) s += fmt::format(", {} degenerate left out", m.degenerate_faces);
    s += "):\n";
    s += fmt::format("  vertex displacement  RMS {:.6g} ({:.6g} wrt diagonal), max {:.6g} ({:.6g}) at vertex {}\n",
                     m.displacement_rms, m.displacement_rms / diag, m.displacement_max, m.displacement_max / diag,
                     m.max_vertex);
    s += fmt::format("  face normal angle    RMS {:.6g} deg, max {:.6g} deg at face {}\n", m.normal_rms_deg,
                     m.normal_max_deg, m.max_face);
    return s;
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
        if (pa.normalization.method == NormalizeMethod::Paper)
            s += fmt::format(
                "\nRoughness profiles ({} mean curvature on each mesh scaled to unit mean radius: s = {:.6g} "
                "and {:.6g})\n",
                to_string(pa.curvature_options.method), pa.normalization.scale, pb.normalization.scale);
        else
            s += fmt::format("\nRoughness profiles ({} mean curvature; normalisation {}: s = {:.6g} and {:.6g}, {})\n",
                             to_string(pa.curvature_options.method), to_string(pa.normalization.method),
                             pa.normalization.scale, pb.normalization.scale,
                             detail::scale_meaning(pa.normalization.method));
        s += fmt::format("  d_L = ln(|s' - s| / s + k) - ln(k), k = {:g}; change = (s' - s) / s\n", c.roughness->k);
        const LocalRoughnessDistance* local = c.local_roughness ? &*c.local_roughness : nullptr;
        if (pa.trim > 0.0)
            s += fmt::format("  sigma trimmed: the {:g}% of vertices with the largest |D| left out\n", 100.0 * pa.trim);
        if (local)
            s += fmt::format(
                "  local = RMS over the processed mesh's vertices of the detail at its level L of the change of H "
                "(the original's H at the closest point){}{}\n",
                local->trim > 0.0 ? fmt::format(" (the {:g}% largest left out)", 100.0 * local->trim) : "",
                local->radii.empty() ? "" : "; at a radius the same over the original's vertices and balls");
        auto local_at = [&](const std::vector<int>& keys, const std::vector<double>& rms, int key) {
            for (std::size_t i = 0; i < keys.size(); ++i)
                if (keys[i] == key) return rms[i];
            return std::nan("");
        };
        const bool bootstrap = pa.bootstrap > 0;
        if (bootstrap)
            s += fmt::format(
                "  intervals: the {:g}% bootstrap intervals of the two sigmas ({} resamples of the vertices, seed {}) "
                "are apart (a change beyond the vertex sampling) or overlap\n",
                100.0 * kBootstrapConfidence, pa.bootstrap, pa.bootstrap_seed);
        // The profiles' level with the distance's level (both profiles have the same levels, in order).
        auto level_of = [](const RoughnessProfile& p, int level) -> const LevelRoughness* {
            for (const auto& l : p.levels)
                if (l.level == level) return &l;
            return nullptr;
        };
        std::vector<LevelRow> rows;
        for (const auto& d : c.roughness->levels)
            rows.push_back({std::to_string(d.level), &d, local ? local_at(local->levels, local->rms, d.level) : 0.0,
                            level_of(pa, d.level), level_of(pb, d.level)});
        if (c.roughness->has_global)
            rows.push_back({"global", &c.roughness->global, local && local->has_global ? local->global : std::nan(""),
                            pa.has_global ? &pa.global : nullptr, pb.has_global ? &pb.global : nullptr});
        LevelColumns columns{"level", "sigma orig", "sigma proc", "d_L", local != nullptr};
        columns.bootstrap = bootstrap;
        s += level_table(columns, rows);
        if (!c.roughness->radii.empty()) {
            rows.clear();
            auto radius_of = [](const RoughnessProfile& p, double r) -> const LevelRoughness* {
                for (const auto& l : p.radii)
                    if (l.radius == r) return &l;
                return nullptr;
            };
            for (const auto& d : c.roughness->radii) {
                double l = std::nan("");
                if (local)
                    for (std::size_t i = 0; i < local->radii.size(); ++i)
                        if (local->radii[i] == d.radius) l = local->rms_radii[i];
                rows.push_back(
                    {fmt::format("{:g}", d.radius), &d, l, radius_of(pa, d.radius), radius_of(pb, d.radius)});
            }
            LevelColumns radius_columns{"radius", "sigma orig",     "sigma proc",
                                        "d_r",    local != nullptr, "   (metric levels, area-weighted)"};
            radius_columns.bootstrap = bootstrap;
            s += level_table(radius_columns, rows);
        }
        if (pa.curvature_undefined || pb.curvature_undefined)
            s += fmt::format("  undefined curvature: {} and {} vertices left out\n", pa.curvature_undefined,
                             pb.curvature_undefined);
        for (const auto* p : {&pa, &pb})
            for (const auto& w : warnings(p == &pa ? c.original : c.processed, p))
                if (w.kind == WarningKind::OutliersDominate || w.kind == WarningKind::CappedNeighbourhoods ||
                    w.kind == WarningKind::NoDefinedD || w.kind == WarningKind::SparseNeighbourhoods ||
                    w.kind == WarningKind::SteepFits)
                    s += fmt::format("  ! {}: {}\n", p == &pa ? "original" : "processed", w.text);
    }
    if (c.corsini) {
        s += "\nCorsini roughness (variance of dihedral angles, rad^2; Corsini et al. 2007, METHOD.md 6a)\n";
        s += fmt::format("  R(M, M') = ln(|R' - R| / R + k) - ln(k), k = {:g}; change = (R' - R) / R\n", c.corsini->k);
        std::vector<LevelRow> rows;
        for (const auto& d : c.corsini->levels) rows.push_back({std::to_string(d.level), &d, 0.0});
        if (c.corsini->has_global) rows.push_back({"global", &c.corsini->global, 0.0});
        if (c.corsini->has_multiscale) rows.push_back({"multi", &c.corsini->multiscale, 0.0});
        s += level_table({"level", "R orig", "R proc", "R(M,M')", false}, rows);
    }
    if (!c.roughness_unavailable.empty()) s += fmt::format("\nRoughness: skipped: {}\n", c.roughness_unavailable);
    if (c.distance) s += detail::surface_distance_text(c);
    s += same_connectivity_text(c);
    return s;
}

}  // namespace meshdiff
