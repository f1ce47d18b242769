#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"

#include "meshdiff/version.h"

#include "sections.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

namespace meshdiff {

nlohmann::json number_or_null(double x)
{
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

nlohmann::json warnings_json(const std::vector<Warning>& warnings)
{
    nlohmann::json j = nlohmann::json::array();
    for (const auto& w : warnings) j.push_back(w.text);
    return j;
}

nlohmann::json mesh_json(const MeshFacts& f)
{
    const auto& t = f.topology;
    nlohmann::json j;
    j["path"] = f.input.path;
    j["vertices"] = t.vertices;
    j["faces"] = t.faces;
    j["edges"] = t.edges;
    j["components"] = t.components;
    j["closed"] = t.closed();
    j["boundary_edges"] = t.boundary_edges;
    j["boundary_loops"] = t.boundary_loops;
    j["non_manifold_edges"] = t.non_manifold_edges;
    j["non_manifold_vertices"] = t.non_manifold_vertices;
    j["degenerate_faces"] = t.degenerate_faces;
    j["duplicate_faces"] = t.duplicate_faces;
    j["orientation_conflicts"] = t.orientation_conflicts;
    j["file_vertices"] = f.input.file_vertices;
    j["file_faces"] = f.input.file_faces;
    j["unreferenced_vertices_removed"] = f.input.unreferenced_vertices;
    j["polygons_triangulated"] = f.input.polygons_triangulated;
    j["repeated_index_faces_removed"] = f.input.repeated_index_faces;
    j["area"] = f.area;
    j["point_cloud"] = f.input.point_cloud;
    if (f.input.point_cloud) j["closed"] = nullptr;  // no surface
    j["bbox"] = {{"min", {f.box.min.x(), f.box.min.y(), f.box.min.z()}},
                 {"max", {f.box.max.x(), f.box.max.y(), f.box.max.z()}},
                 {"diagonal", f.box.diagonal()}};
    return j;
}

namespace {
// sigma, or null at a level without data (no number where there is none).
nlohmann::json sigma_json(const LevelRoughness& l)
{
    return l.vertices_used ? number_or_null(l.sigma) : nlohmann::json(nullptr);
}
nlohmann::json level_json(const LevelRoughness& l)
{
    nlohmann::json j = {{"level", l.level},
                        {"sigma", sigma_json(l)},
                        {"vertices_used", l.vertices_used},
                        {"no_neighborhood", l.no_neighborhood},
                        {"top_share", number_or_null(l.top_share)},
                        {"worst_vertices", l.worst_vertices}};
    if (l.trimmed) j["trimmed"] = l.trimmed;  // only with a trim: other reports are unchanged
    if (l.sigma_interval)                     // only with a bootstrap
        j["sigma_interval"] = {number_or_null(l.sigma_interval->first), number_or_null(l.sigma_interval->second)};
    return j;
}
nlohmann::json radius_json(const LevelRoughness& l)
{
    nlohmann::json j = level_json(l);
    j.erase("level");
    j["radius"] = l.radius;
    return j;
}
// The per-level arrays of a profile under the three names of \p names: the
// keys (levels or radii), sigma, and the details of each level.
template <class KeyOf>
void level_arrays(nlohmann::json& j, const std::vector<LevelRoughness>& ls, const std::array<const char*, 3>& names,
                  KeyOf key_of, nlohmann::json (*details_of)(const LevelRoughness&))
{
    nlohmann::json keys = nlohmann::json::array(), sigma = nlohmann::json::array(), details = nlohmann::json::array();
    for (const auto& l : ls) {
        keys.push_back(key_of(l));
        sigma.push_back(sigma_json(l));
        details.push_back(details_of(l));
    }
    j[names[0]] = keys;
    j[names[1]] = sigma;
    j[names[2]] = details;
}
}  // namespace

nlohmann::json profile_json(const MeshFacts& f, const RoughnessProfile& p)
{
    nlohmann::json j;
    j["schema"] = "meshdiff.profile/1";
    j["meshdiff_version"] = MESHDIFF_VERSION;
    j["mesh"] = mesh_json(f);
    j["mesh"]["normalization"] = {
        {"center", {p.normalization.center.x(), p.normalization.center.y(), p.normalization.center.z()}},
        {"scale", p.normalization.scale},
        {"method", to_string(p.normalization.method)}};
    j["mesh"]["scale_factor"] = p.normalization.scale;
    if (p.curvature_options.method == CurvatureMethod::Jet)  // its own neighbourhood and weights (curvature.h)
        j["curvature"] = {
            {"method", to_string(p.curvature_options.method)},
            {"neighbourhood", fmt::format("2-ring, widened to the 3-ring below {} neighbours", kJetMinNeighbors)},
            {"row_weights", "1/|d|^4"},
            {"undefined_vertices", p.curvature_undefined},
            {"widened_to_3_ring", p.curvature_widened},
            {"degree2_fallback", p.curvature_fallback},
            {"steep_fits", p.curvature_steep}};
    else
        j["curvature"] = {{"method", to_string(p.curvature_options.method)},
                          {"row_weighting", to_string(p.curvature_options.weighting)},
                          {"min_neighbors", p.curvature_options.min_neighbors},
                          {"max_normal_angle_deg", p.curvature_options.max_normal_angle_deg},
                          {"undefined_vertices", p.curvature_undefined},
                          {"widened_to_2_ring", p.curvature_widened},
                          {"normal_rows_dropped", p.curvature_normal_rows_dropped},
                          {"quadric_fallback", p.curvature_fallback}};
    j["curvature"]["sign_convention"] = "H > 0 where convex with outward normals (unit sphere: +1)";
    j["curvature"]["units"] = "1/length on the mesh scaled to mean vertex distance 1 from the centroid";
    if (p.curvature_capped) {  // only then: reports of meshes without a capped fit are unchanged
        j["curvature"]["capped_neighbourhoods"] = p.curvature_capped;
        j["curvature"]["capped_vertices"] = p.curvature_capped_vertices;
        j["curvature"]["max_fit_neighbors"] = kMaxFitNeighbors;
    }
    level_arrays(
        j, p.levels, {"levels", "sigma", "level_details"}, [](const LevelRoughness& l) { return l.level; }, level_json);
    j["sigma_global"] = p.has_global ? sigma_json(p.global) : nlohmann::json(nullptr);
    if (p.has_global) j["global"] = level_json(p.global);
    j["neighborhood"] = "N_L(i) = vertices within L edges of i, i excluded; global: all other vertices";
    if (p.trim > 0.0)
        j["trim"] = {{"share", p.trim},
                     {"definition", "sigma without the ceil(share x count) vertices of largest |D| at each level"}};
    if (p.bootstrap > 0)
        j["bootstrap"] = {{"resamples", p.bootstrap},
                          {"seed", p.bootstrap_seed},
                          {"confidence", kBootstrapConfidence},
                          {"definition",
                           "sigma_interval of each level: the 2.5th and 97.5th percentiles of sigma over the "
                           "resamples of the vertices used, drawn with replacement (trim and area weights applied "
                           "to each)"}};
    if (!p.radii.empty()) {  // only then: reports without metric levels are unchanged
        level_arrays(
            j, p.radii, {"radii", "sigma_radii", "radius_details"}, [](const LevelRoughness& l) { return l.radius; },
            radius_json);
        j["neighborhood_radii"] =
            "N_r(i) = vertices joined to i by mesh edges inside the closed ball of radius r about i (unit-scaled "
            "mesh), i excluded; means and sigma weighted by vertex area (one third of incident face areas)";
    }
    j["warnings"] = warnings_json(warnings(f, &p));
    return j;
}

namespace {

// An H error over a set of vertices; rms and max are null when none was compared.
nlohmann::json error_json(const CurvatureError& e)
{
    return {{"rms", e.compared ? nlohmann::json(e.rms) : nlohmann::json(nullptr)},
            {"max", e.compared ? nlohmann::json(e.max) : nlohmann::json(nullptr)},
            {"vertices", e.compared}};
}

}  // namespace

nlohmann::json exact_profile_json(const RoughnessProfile& estimated, const ExactProfile& exact,
                                  const std::string& property)
{
    nlohmann::json levels = nlohmann::json::array(), sigma = nlohmann::json::array();
    for (std::size_t k = 0; k < estimated.levels.size(); ++k) {
        levels.push_back(estimated.levels[k].level);
        sigma.push_back(exact.profile.levels[k].sigma);
    }
    const auto& e = exact.h_error;
    nlohmann::json j = {{"property", property},
                        {"levels", levels},
                        {"sigma", sigma},
                        {"sigma_global", exact.profile.has_global ? nlohmann::json(exact.profile.global.sigma)
                                                                  : nlohmann::json(nullptr)},
                        {"undefined_vertices", exact.profile.curvature_undefined},
                        {"h_error",
                         {{"rms", e.rms},
                          {"max", e.max},
                          {"vertices", e.compared},
                          {"interior", error_json(exact.h_error_interior)},
                          {"boundary", error_json(exact.h_error_boundary)}}}};
    if (!exact.profile.radii.empty()) {  // only with --radii
        nlohmann::json radii = nlohmann::json::array(), sigma_r = nlohmann::json::array();
        for (const auto& l : exact.profile.radii) {
            radii.push_back(l.radius);
            sigma_r.push_back(l.sigma);
        }
        j["radii"] = radii;
        j["sigma_radii"] = sigma_r;
    }
    return j;
}

namespace {
nlohmann::json corsini_level_json(const CorsiniLevel& l)
{
    return {{"level", l.level},
            {"roughness", l.roughness},
            {"vertices_used", l.vertices_used},
            {"no_neighborhood", l.no_neighborhood},
            {"mean_edges", l.mean_edges}};
}
}  // namespace

nlohmann::json corsini_json(const CorsiniProfile& p)
{
    nlohmann::json levels = nlohmann::json::array(), r = nlohmann::json::array(), details = nlohmann::json::array();
    for (const auto& l : p.levels) {
        levels.push_back(l.level);
        r.push_back(l.roughness);
        details.push_back(corsini_level_json(l));
    }
    nlohmann::json j;
    j["levels"] = levels;
    j["roughness"] = r;
    j["roughness_global"] = p.has_global ? nlohmann::json(p.global.roughness) : nlohmann::json(nullptr);
    j["multiscale"] = p.levels.empty() ? nlohmann::json(nullptr) : nlohmann::json(p.multiscale);
    if (p.has_global) j["global"] = corsini_level_json(p.global);
    j["dihedral"] = {{"edges", p.edges},
                     {"edges_with_angle", p.dihedral_edges},
                     {"mean", p.mean_dihedral},
                     {"max", p.max_dihedral},
                     {"unit", "rad"}};
    j["variance"] = p.options.unbiased ? "sample (divisor n - 1)" : "population (divisor n)";
    j["unit"] = "rad^2";
    j["definition"] =
        "theta_e = angle between the normals of the two faces of edge e; R_L(v) = variance of theta_e over the edges "
        "with both ends within L edges of v; R_L(M) = sum A_v R_L(v) / sum A_v (A_v = a third of the incident face "
        "areas); global: variance over all edges; multiscale: mean of R_L(M) over the levels (METHOD.md 6a)";
    return j;
}

nlohmann::json corsini_profile_json(const MeshFacts& f, const CorsiniProfile& p)
{
    nlohmann::json j;
    j["schema"] = "meshdiff.corsini/1";
    j["meshdiff_version"] = MESHDIFF_VERSION;
    j["mesh"] = mesh_json(f);
    j["measure"] = "corsini";
    j["corsini"] = corsini_json(p);
    j["warnings"] = warnings_json(warnings(f));
    return j;
}

namespace {

// The mesh and defect lines that head a profile report.
}  // namespace

const char* detail::scale_meaning(NormalizeMethod method)
{
    switch (method) {
        case NormalizeMethod::Paper:
            break;
        case NormalizeMethod::Area:
            return "sqrt(area / 4 pi), about the area-weighted centroid";
        case NormalizeMethod::Original:
            return "the original's frame: its centroid and mean vertex distance";
    }
    return "mean vertex distance to centroid";
}

namespace {

std::string mesh_header(const MeshFacts& f)
{
    const auto& t = f.topology;
    std::string s;
    s += fmt::format("mesh       {}\n", f.input.path);
    s += fmt::format("           {} vertices, {} faces, {} component{}, {}\n", t.vertices, t.faces, t.components,
                     t.components == 1 ? "" : "s",
                     t.closed() ? "closed" : fmt::format("open ({} boundary loops)", t.boundary_loops));
    s += fmt::format(
        "defects    non-manifold edges {}, non-manifold vertices {}, degenerate faces {}, duplicate "
        "faces {},\n           orientation conflicts {}, unreferenced vertices removed {}\n",
        t.non_manifold_edges, t.non_manifold_vertices, t.degenerate_faces, t.duplicate_faces, t.orientation_conflicts,
        f.input.unreferenced_vertices);
    return s;
}

}  // namespace

std::string profile_text(const MeshFacts& f, const RoughnessProfile& p)
{
    std::string s = mesh_header(f);
    s += fmt::format("scale      centroid ({:.6g}, {:.6g}, {:.6g}), s = {:.6g} ({})\n", p.normalization.center.x(),
                     p.normalization.center.y(), p.normalization.center.z(), p.normalization.scale,
                     detail::scale_meaning(p.normalization.method));
    if (p.curvature_options.method == CurvatureMethod::Jet)
        s += fmt::format(
            "curvature  jet (2-ring, rows weighted 1/|d|^4); undefined {}, 3-ring {}, degree-2 fallback {}, steep {}\n",
            p.curvature_undefined, p.curvature_widened, p.curvature_fallback, p.curvature_steep);
    else
        s += fmt::format("curvature  {}{}; undefined {}, 2-ring {}, normal rows dropped {}, quadric fallback {}\n",
                         to_string(p.curvature_options.method),
                         p.curvature_options.method == CurvatureMethod::MeyerCotangent
                             ? ""
                             : fmt::format(" (row weighting {})", to_string(p.curvature_options.weighting)),
                         p.curvature_undefined, p.curvature_widened, p.curvature_normal_rows_dropped,
                         p.curvature_fallback);
    if (p.trim > 0.0)
        s += fmt::format("trim       sigma without the {:g}% of vertices with the largest |D| at each level\n",
                         100.0 * p.trim);
    if (p.bootstrap > 0)
        s += fmt::format("bootstrap  {:g}% interval of sigma over {} resamples of the vertices (seed {})\n",
                         100.0 * kBootstrapConfidence, p.bootstrap, p.bootstrap_seed);
    const std::string interval_head = p.bootstrap > 0 ? "   95% interval" : "";
    s += fmt::format("\n   level        sigma     used   no-nbhd {:>9}{}\n",
                     fmt::format("top{:g}%", 100.0 * p.outlier_fraction), interval_head);
    auto row = [&](const std::string& name, const LevelRoughness& l) {
        const std::string interval =
            p.bootstrap == 0   ? std::string()
            : l.sigma_interval ? fmt::format("   [{:.6g}, {:.6g}]", l.sigma_interval->first, l.sigma_interval->second)
                               : std::string("   -");
        s += fmt::format("{:>8} {:>12} {:>8} {:>9} {:>8.1f}%{}\n", name,
                         l.vertices_used ? fmt::format("{:.6g}", l.sigma) : std::string("-"), l.vertices_used,
                         l.no_neighborhood, 100.0 * l.top_share, interval);
    };
    for (const auto& l : p.levels) row(std::to_string(l.level), l);
    if (p.has_global) row("global", p.global);
    if (!p.radii.empty()) {
        s += fmt::format("\n  radius        sigma     used   no-nbhd {:>9}{}   (metric levels, area-weighted)\n",
                         fmt::format("top{:g}%", 100.0 * p.outlier_fraction), interval_head);
        for (const auto& l : p.radii) row(fmt::format("{:g}", l.radius), l);
    }
    const auto w = warnings(f, &p);
    if (!w.empty()) {
        s += "\nwarnings\n";
        for (const auto& line : w) s += "  - " + line.text + "\n";
    }
    return s;
}

std::string corsini_profile_text(const MeshFacts& f, const CorsiniProfile& p)
{
    std::string s = mesh_header(f);
    s += fmt::format(
        "corsini    dihedral-angle roughness (Corsini et al. 2007; METHOD.md 6a): {} of {} edges have an angle, "
        "mean {:.6g} rad, max {:.6g} rad; {} variance\n",
        p.dihedral_edges, p.edges, p.mean_dihedral, p.max_dihedral, p.options.unbiased ? "sample" : "population");
    s += fmt::format("\n   level    roughness     used   no-nbhd   edges/nbhd   (rad^2)\n");
    auto row = [&](const std::string& name, const CorsiniLevel& l) {
        s += fmt::format("{:>8} {:>12.6g} {:>8} {:>9} {:>12.1f}\n", name, l.roughness, l.vertices_used,
                         l.no_neighborhood, l.mean_edges);
    };
    for (const auto& l : p.levels) row(std::to_string(l.level), l);
    if (p.has_global) row("global", p.global);
    if (!p.levels.empty()) s += fmt::format("\nmulti-scale roughness (mean over the levels): {:.6g}\n", p.multiscale);
    const auto w = warnings(f);
    if (!w.empty()) {
        s += "\nwarnings\n";
        for (const auto& line : w) s += "  - " + line.text + "\n";
    }
    return s;
}

std::string exact_profile_text(const RoughnessProfile& profile, const ExactProfile& e, const std::string& property)
{
    const auto part = [](const CurvatureError& x) {
        return x.compared ? fmt::format("RMS {:.4g}, max {:.4g} over {}", x.rms, x.max, x.compared)
                          : std::string("no vertex");
    };
    std::string text = fmt::format(
        "\nexact profile from the vertex property '{}' (H error of the estimate on the scaled "
        "mesh: RMS {:.4g}, max {:.4g} over {} vertices)\n  interior: {}; boundary: {}\n"
        "   level  sigma estimated  sigma exact\n",
        property, e.h_error.rms, e.h_error.max, e.h_error.compared, part(e.h_error_interior), part(e.h_error_boundary));
    for (std::size_t k = 0; k < profile.levels.size(); ++k)
        text += fmt::format("{:>8} {:>16.6g} {:>12.6g}\n", profile.levels[k].level, profile.levels[k].sigma,
                            e.profile.levels[k].sigma);
    if (profile.has_global)
        text += fmt::format("{:>8} {:>16.6g} {:>12.6g}\n", "global", profile.global.sigma, e.profile.global.sigma);
    if (!profile.radii.empty() && e.profile.radii.size() == profile.radii.size()) {  // only with --radii
        text += "\n  radius  sigma estimated  sigma exact   (metric levels, area-weighted)\n";
        for (std::size_t k = 0; k < profile.radii.size(); ++k)
            text += fmt::format("{:>8} {:>16.6g} {:>12.6g}\n", fmt::format("{:g}", profile.radii[k].radius),
                                profile.radii[k].sigma, e.profile.radii[k].sigma);
    }
    return text;
}

}  // namespace meshdiff
