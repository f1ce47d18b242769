#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"

#include "meshdiff/version.h"

#include "sections.h"

#include <fmt/format.h>

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
            dist.push_back(l.distance);
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
        j["global"] = {{"distance", d.global.distance},
                       {"relative_change", d.global.relative_change_defined ? nlohmann::json(d.global.relative_change)
                                                                            : nlohmann::json(nullptr)},
                       {"reference_zero", d.global.reference_zero}};
    if (!d.radii.empty())
        arrays(
            d.radii, [](const auto& l) { return l.radius; }, "radii", "distance_radii", "relative_change_radii",
            "reference_zero_radii");
    return j;
}

nlohmann::json corsini_distance_json(const CorsiniDistance& d)
{
    auto change = [](const LevelDistance& l) {
        return l.relative_change_defined ? nlohmann::json(l.relative_change) : nlohmann::json(nullptr);
    };
    auto one = [&](const LevelDistance& l) {
        return nlohmann::json{
            {"distance", l.distance}, {"relative_change", change(l)}, {"reference_zero", l.reference_zero}};
    };
    nlohmann::json levels = nlohmann::json::array(), dist = nlohmann::json::array(), rel = nlohmann::json::array();
    nlohmann::json zero = nlohmann::json::array();
    for (const auto& l : d.levels) {
        levels.push_back(l.level);
        dist.push_back(l.distance);
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
        if (!c.roughness->radii.empty())
            s += fmt::format("  {:>7} {:>13} {:>13} {:>10} {:>9}   (metric levels, area-weighted)\n", "radius",
                             "sigma orig", "sigma proc", "change", "d_r");
        for (const auto& d : c.roughness->radii) {
            double sa = 0, sb = 0;
            for (const auto& l : pa.radii)
                if (l.radius == d.radius) sa = l.sigma;
            for (const auto& l : pb.radii)
                if (l.radius == d.radius) sb = l.sigma;
            row(fmt::format("{:g}", d.radius), sa, sb, d);
        }
        if (pa.curvature_undefined || pb.curvature_undefined)
            s += fmt::format("  undefined curvature: {} and {} vertices left out\n", pa.curvature_undefined,
                             pb.curvature_undefined);
        for (const auto* p : {&pa, &pb})
            for (const auto& w : warnings(p == &pa ? c.original : c.processed, p))
                if (w.kind == WarningKind::OutliersDominate || w.kind == WarningKind::CappedNeighbourhoods)
                    s += fmt::format("  ! {}: {}\n", p == &pa ? "original" : "processed", w.text);
    }
    if (c.corsini) {
        const auto& pa = *c.original_corsini;
        const auto& pb = *c.processed_corsini;
        s += "\nCorsini roughness (variance of dihedral angles, rad^2; Corsini et al. 2007, METHOD.md 6a)\n";
        s += fmt::format("  R(M, M') = ln(|R' - R| / R + k) - ln(k), k = {:g}; change = (R' - R) / R\n", c.corsini->k);
        s += fmt::format("  {:>7} {:>13} {:>13} {:>10} {:>9}\n", "level", "R orig", "R proc", "change", "R(M,M')");
        auto row = [&](const std::string& name, double ra, double rb, const LevelDistance& d) {
            const std::string change =
                d.relative_change_defined ? fmt::format("{:+.2f}%", 100.0 * d.relative_change) : "undef";
            s += fmt::format("  {:>7} {:>13.6g} {:>13.6g} {:>10} {:>9.4f}\n", name, ra, rb, change, d.distance);
        };
        for (const auto& d : c.corsini->levels) {
            double ra = 0, rb = 0;
            for (const auto& l : pa.levels)
                if (l.level == d.level) ra = l.roughness;
            for (const auto& l : pb.levels)
                if (l.level == d.level) rb = l.roughness;
            row(std::to_string(d.level), ra, rb, d);
        }
        if (c.corsini->has_global) row("global", pa.global.roughness, pb.global.roughness, c.corsini->global);
        if (c.corsini->has_multiscale) row("multi", pa.multiscale, pb.multiscale, c.corsini->multiscale);
    }
    if (!c.roughness_unavailable.empty()) s += fmt::format("\nRoughness: skipped: {}\n", c.roughness_unavailable);
    if (c.distance) s += detail::surface_distance_text(c);
    s += same_connectivity_text(c);
    return s;
}

}  // namespace meshdiff
