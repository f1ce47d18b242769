#include "meshdiff/report.h"
#include "meshdiff/version.h"

#include <fmt/format.h>

#include <cmath>

namespace meshdiff {

MeshFacts mesh_facts(const LoadedMesh& loaded)
{
    MeshFacts f;
    f.input = loaded.input;
    f.topology = topology_report(loaded.mesh);
    f.box = bounding_box(loaded.mesh);
    f.area = surface_area(loaded.mesh);
    return f;
}

nlohmann::json number_or_null(double x)
{
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

std::vector<std::string> profile_warnings(const MeshFacts& f, const RoughnessProfile* p)
{
    std::vector<std::string> w;
    const auto& t = f.topology;
    if (f.input.unreferenced_vertices)
        w.push_back(fmt::format("{} unreferenced vertices were dropped", f.input.unreferenced_vertices));
    if (f.input.repeated_index_faces)
        w.push_back(fmt::format("{} faces with a repeated corner were dropped", f.input.repeated_index_faces));
    if (t.non_manifold_edges || t.non_manifold_vertices)
        w.push_back(fmt::format("non-manifold: {} edges, {} vertices", t.non_manifold_edges, t.non_manifold_vertices));
    if (t.orientation_conflicts)
        w.push_back(fmt::format("inconsistent orientation on {} edges: curvature signs near them cannot be trusted",
                                t.orientation_conflicts));
    if (t.degenerate_faces) w.push_back(fmt::format("{} zero-area faces (no normal, no samples)", t.degenerate_faces));
    if (t.duplicate_faces) w.push_back(fmt::format("{} duplicate faces", t.duplicate_faces));
    if (t.boundary_edges)
        w.push_back(fmt::format("open surface: {} boundary edges in {} loops", t.boundary_edges, t.boundary_loops));
    if (t.components > 1)
        w.push_back(
            fmt::format("{} connected components: ring levels stay inside a component, the global level "
                        "spans all",
                        t.components));
    if (p) {
        if (p->curvature_undefined)
            w.push_back(fmt::format("{} vertices have undefined curvature and are left out", p->curvature_undefined));
        auto check = [&](const LevelRoughness& l, const std::string& name) {
            if (l.top_share > 0.5)
                w.push_back(
                    fmt::format("{}: the worst {:.1f}% of vertices make {:.0f}% of sigma^2 (outliers "
                                "dominate; see worst_vertices)",
                                name, 100.0 * 0.001, 100.0 * l.top_share));
            if (l.vertices_used == 0) w.push_back(fmt::format("{}: no vertex has a defined D (sigma set to 0)", name));
        };
        for (const auto& l : p->levels) check(l, fmt::format("level {}", l.level));
        if (p->has_global) check(p->global, "global level");
    }
    return w;
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
    j["bbox"] = {{"min", {f.box.min.x(), f.box.min.y(), f.box.min.z()}},
                 {"max", {f.box.max.x(), f.box.max.y(), f.box.max.z()}},
                 {"diagonal", f.box.diagonal()}};
    return j;
}

namespace {
nlohmann::json level_json(const LevelRoughness& l)
{
    return {{"level", l.level},
            {"sigma", number_or_null(l.sigma)},
            {"vertices_used", l.vertices_used},
            {"no_neighborhood", l.no_neighborhood},
            {"top_share", number_or_null(l.top_share)},
            {"worst_vertices", l.worst_vertices}};
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
        {"scale", p.normalization.scale}};
    j["mesh"]["scale_factor"] = p.normalization.scale;
    j["curvature"] = {{"method", to_string(p.curvature_options.method)},
                      {"row_weighting", to_string(p.curvature_options.weighting)},
                      {"min_neighbors", p.curvature_options.min_neighbors},
                      {"max_normal_angle_deg", p.curvature_options.max_normal_angle_deg},
                      {"undefined_vertices", p.curvature_undefined},
                      {"widened_to_2_ring", p.curvature_widened},
                      {"quadric_fallback", p.curvature_fallback},
                      {"sign_convention", "H > 0 where convex with outward normals (unit sphere: +1)"},
                      {"units", "1/length on the mesh scaled to mean vertex distance 1 from the centroid"}};
    nlohmann::json levels = nlohmann::json::array(), sigma = nlohmann::json::array(), details = nlohmann::json::array();
    for (const auto& l : p.levels) {
        levels.push_back(l.level);
        sigma.push_back(number_or_null(l.sigma));
        details.push_back(level_json(l));
    }
    j["levels"] = levels;
    j["sigma"] = sigma;
    j["sigma_global"] = p.has_global ? number_or_null(p.global.sigma) : nlohmann::json(nullptr);
    j["level_details"] = details;
    if (p.has_global) j["global"] = level_json(p.global);
    j["neighborhood"] = "N_L(i) = vertices within L edges of i, i excluded; global: all other vertices";
    j["warnings"] = profile_warnings(f, &p);
    return j;
}

std::string profile_text(const MeshFacts& f, const RoughnessProfile& p)
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
    s += fmt::format("scale      centroid ({:.6g}, {:.6g}, {:.6g}), s = {:.6g} (mean vertex distance to centroid)\n",
                     p.normalization.center.x(), p.normalization.center.y(), p.normalization.center.z(),
                     p.normalization.scale);
    s += fmt::format("curvature  {}{}; undefined {}, 2-ring {}, quadric fallback {}\n",
                     to_string(p.curvature_options.method),
                     p.curvature_options.method == CurvatureMethod::MeyerCotangent
                         ? ""
                         : fmt::format(" (row weighting {})", to_string(p.curvature_options.weighting)),
                     p.curvature_undefined, p.curvature_widened, p.curvature_fallback);
    s += "\n   level        sigma     used   no-nbhd   top0.1%\n";
    auto row = [&](const std::string& name, const LevelRoughness& l) {
        s += fmt::format("{:>8} {:>12.6g} {:>8} {:>9} {:>8.1f}%\n", name, l.sigma, l.vertices_used, l.no_neighborhood,
                         100.0 * l.top_share);
    };
    for (const auto& l : p.levels) row(std::to_string(l.level), l);
    if (p.has_global) row("global", p.global);
    const auto w = profile_warnings(f, &p);
    if (!w.empty()) {
        s += "\nwarnings\n";
        for (const auto& line : w) s += "  - " + line + "\n";
    }
    return s;
}

nlohmann::json roughness_distance_json(const RoughnessDistance& d)
{
    nlohmann::json j;
    j["k"] = d.k;
    j["formula"] = "d = ln(|s' - s| / s + k) - ln(k); relative_change = (s' - s) / s";
    nlohmann::json levels = nlohmann::json::array(), dist = nlohmann::json::array(), rel = nlohmann::json::array();
    nlohmann::json undefined = nlohmann::json::array();
    for (const auto& l : d.levels) {
        levels.push_back(l.level);
        dist.push_back(l.distance);
        rel.push_back(l.relative_change_defined ? nlohmann::json(l.relative_change) : nlohmann::json(nullptr));
        if (l.reference_zero) undefined.push_back(l.level);
    }
    j["levels"] = levels;
    j["distance"] = dist;
    j["relative_change"] = rel;
    j["reference_zero_levels"] = undefined;
    if (d.has_global)
        j["global"] = {{"distance", d.global.distance},
                       {"relative_change", d.global.relative_change_defined ? nlohmann::json(d.global.relative_change)
                                                                            : nlohmann::json(nullptr)},
                       {"reference_zero", d.global.reference_zero}};
    return j;
}

}  // namespace meshdiff
