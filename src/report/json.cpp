#include "meshdiff/report/json.h"

#include "meshdiff/version.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

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
nlohmann::json level_json(const LevelRoughness& l)
{
    return {{"level", l.level},
            {"sigma", number_or_null(l.sigma)},
            {"vertices_used", l.vertices_used},
            {"no_neighborhood", l.no_neighborhood},
            {"top_share", number_or_null(l.top_share)},
            {"worst_vertices", l.worst_vertices}};
}
nlohmann::json radius_json(const LevelRoughness& l)
{
    nlohmann::json j = level_json(l);
    j.erase("level");
    j["radius"] = l.radius;
    return j;
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
                      {"normal_rows_dropped", p.curvature_normal_rows_dropped},
                      {"quadric_fallback", p.curvature_fallback},
                      {"sign_convention", "H > 0 where convex with outward normals (unit sphere: +1)"},
                      {"units", "1/length on the mesh scaled to mean vertex distance 1 from the centroid"}};
    if (p.curvature_capped) {  // only then: reports of meshes without a capped fit are unchanged
        j["curvature"]["capped_neighbourhoods"] = p.curvature_capped;
        j["curvature"]["capped_vertices"] = p.curvature_capped_vertices;
        j["curvature"]["max_fit_neighbors"] = kMaxFitNeighbors;
    }
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
    if (!p.radii.empty()) {  // only then: reports without metric levels are unchanged
        nlohmann::json radii = nlohmann::json::array(), sigma_r = nlohmann::json::array(),
                       details_r = nlohmann::json::array();
        for (const auto& l : p.radii) {
            radii.push_back(l.radius);
            sigma_r.push_back(number_or_null(l.sigma));
            details_r.push_back(radius_json(l));
        }
        j["radii"] = radii;
        j["sigma_radii"] = sigma_r;
        j["radius_details"] = details_r;
        j["neighborhood_radii"] =
            "N_r(i) = vertices joined to i by mesh edges inside the closed ball of radius r about i (unit-scaled "
            "mesh), i excluded; means and sigma weighted by vertex area (one third of incident face areas)";
    }
    j["warnings"] = warnings_json(warnings(f, &p));
    return j;
}

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
                        {"h_error", {{"rms", e.rms}, {"max", e.max}, {"vertices", e.compared}}}};
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
    j["level_details"] = details;
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

nlohmann::json distance_stats_json(const DistanceStats& s, double diagonal)
{
    auto block = [](const DistanceStats& d) {
        nlohmann::json b = nlohmann::json::object();
        for (const StatField& f : kStatFields) b[f.key] = d.*f.field;
        return b;
    };
    nlohmann::json j = block(s);
    j["samples"] = s.n_samples();
    j["samples_by_kind"] = {{"vertex", s.n_vertex}, {"edge", s.n_edge}, {"face", s.n_face}, {"point", s.n_point}};
    j["relative"] = block(relative_to(s, diagonal));
    if (s.area_weighted) {
        const AreaWeightedStats& a = *s.area_weighted;
        j["area_weighted"] = {{"mean", a.mean},
                              {"rms", a.rms},
                              {"mean_square", a.mean_square},
                              {"face_samples", a.n_face},
                              {"area", a.area},
                              {"area_fraction", a.area_fraction},
                              {"relative", {{"mean", a.mean / diagonal}, {"rms", a.rms / diagonal}}}};
    } else {
        j["area_weighted"] = nullptr;
    }
    if (!s.histogram.counts.empty())  // only when asked for (--histogram)
        j["histogram"] = {{"edges", s.histogram.edges}, {"counts", s.histogram.counts}};
    if (s.signed_distance) {
        const SignedDistanceStats& g = *s.signed_distance;
        j["signed"] = {{"min", g.min},
                       {"max", g.max},
                       {"mean", g.mean},
                       {"rms", g.rms},
                       {"relative",
                        {{"min", g.min / diagonal},
                         {"max", g.max / diagonal},
                         {"mean", g.mean / diagonal},
                         {"rms", g.rms / diagonal}}},
                       {"orientation", g.flipped ? "flipped to outward" : "outward as given"}};
        j["signed_unavailable"] = nullptr;
    } else {
        j["signed"] = nullptr;
        j["signed_unavailable"] = s.signed_unavailable;
    }
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

namespace {

nlohmann::json point_json(const Vec3& p)
{
    return {p.x(), p.y(), p.z()};
}

// One direction's certified Hausdorff distance, or null (sampled only).
nlohmann::json certified_json(const std::optional<CertifiedHausdorff>& h, double diagonal)
{
    if (!h) return nullptr;
    return {{"lower", h->lower},
            {"upper", number_or_null(h->upper)},
            {"tolerance", h->tolerance},
            {"certified", h->certified},
            {"budget_exhausted", h->budget_exhausted},
            {"relative", {{"lower", h->lower / diagonal}, {"upper", number_or_null(h->upper / diagonal)}}},
            {"location",
             {{"point", point_json(h->location.point)},
              {"face", h->location.face},
              {"closest_point", point_json(h->location.closest_point)},
              {"closest_face", h->location.closest_face}}},
            {"bound_evaluations", h->bound_evaluations},
            {"point_evaluations", h->point_evaluations},
            {"rounds", h->rounds},
            {"chunks", h->chunks}};
}

// surface_distance_json() without the notes of point clouds.
nlohmann::json mesh_surface_distance_json(const SurfaceDistance& d, const SamplingOptions& so)
{
    nlohmann::json forward = distance_stats_json(d.forward, d.diagonal);
    nlohmann::json backward = distance_stats_json(d.backward, d.diagonal);
    forward["hausdorff"] = certified_json(d.forward_hausdorff, d.diagonal);
    backward["hausdorff"] = certified_json(d.backward_hausdorff, d.diagonal);
    // The symmetric distance: max of the one-sided ones, so its interval is
    // [max of the lowers, max of the uppers].
    nlohmann::json hausdorff;
    if (d.forward_hausdorff && d.backward_hausdorff) {
        const CertifiedHausdorff& f = *d.forward_hausdorff;
        const CertifiedHausdorff& b = *d.backward_hausdorff;
        const double lower = std::max(f.lower, b.lower);
        const double upper = std::max(f.upper, b.upper);
        hausdorff = {{"method", "certified"},
                     {"lower", lower},
                     {"upper", number_or_null(upper)},
                     {"certified", f.certified && b.certified},
                     {"attained", f.lower >= b.lower ? "forward" : "backward"},
                     {"relative", {{"lower", lower / d.diagonal}, {"upper", number_or_null(upper / d.diagonal)}}},
                     {"relative_metro",
                      {{"lower", lower / d.metro_diagonal}, {"upper", number_or_null(upper / d.metro_diagonal)}}}};
    } else {
        hausdorff = {{"method", "sampled"},
                     {"lower", d.hausdorff},
                     {"upper", nullptr},
                     {"certified", false},
                     {"attained", d.forward.max >= d.backward.max ? "forward" : "backward"},
                     {"relative", {{"lower", d.hausdorff / d.diagonal}, {"upper", nullptr}}},
                     {"relative_metro", {{"lower", d.hausdorff / d.metro_diagonal}, {"upper", nullptr}}}};
    }
    nlohmann::json chamfer = nullptr, fscore = nullptr, psnr = nullptr;
    if (d.summary) {
        const SummaryMetrics& m = *d.summary;
        chamfer = {{"l1", m.chamfer_l1},
                   {"l2", m.chamfer_l2},
                   {"l1_relative", m.chamfer_l1 / d.diagonal},
                   {"l2_relative", m.chamfer_l2 / (d.diagonal * d.diagonal)},
                   {"convention",
                    "area-weighted face samples; l1 = mean forward + mean backward distance; l2 = mean squared forward "
                    "+ mean squared backward distance (sums, not halves); l1_relative = l1 / diagonal, l2_relative = "
                    "l2 / diagonal^2"}};
        fscore = nlohmann::json::array();
        for (const FScore& f : d.fscore)
            fscore.push_back({{"threshold", f.threshold},
                              {"threshold_absolute", f.threshold_absolute},
                              {"precision", f.precision},
                              {"recall", f.recall},
                              {"fscore", f.fscore}});
        const Psnr& p = m.psnr;
        psnr = {{"peak", p.peak},
                {"peak_is", "bounding-box diagonal of the original mesh"},
                {"factor", p.factor},
                {"formula", "10 log10(factor peak^2 / e), e = mse or hausdorff^2 (MPEG pc_error); null when e = 0"},
                {"mse", p.mse},
                {"mse_is", "max of the area-weighted mean squared distances of both directions"},
                {"mse_db", number_or_null(p.mse_db)},
                {"forward_mse_db", number_or_null(p.forward_mse_db)},
                {"backward_mse_db", number_or_null(p.backward_mse_db)},
                {"hausdorff", p.hausdorff},
                {"hausdorff_is", "the sampled symmetric Hausdorff distance"},
                {"hausdorff_db", number_or_null(p.hausdorff_db)},
                {"forward_hausdorff_db", number_or_null(p.forward_hausdorff_db)},
                {"backward_hausdorff_db", number_or_null(p.backward_hausdorff_db)}};
    }
    return {{"forward", forward},
            {"backward", backward},
            {"chamfer", chamfer},
            {"fscore", fscore},
            {"fscore_samples",
             "precision: area share of the processed mesh's face samples closer than the threshold to the original; "
             "recall: area share of the original's face samples closer than the threshold to the processed mesh"},
            {"psnr", psnr},
            {"summary_unavailable", d.summary ? nlohmann::json(nullptr) : nlohmann::json(d.summary_unavailable)},
            {"sign", "positive outside"},
            {"sign_is",
             "signed distance: positive outside the other surface, negative inside, by the angle-weighted "
             "pseudo-normal of the closest feature (Baerentzen and Aanaes 2005); only against a closed, manifold, "
             "consistently oriented mesh without degenerate faces"},
            {"hausdorff", hausdorff},
            {"sampled_hausdorff", d.hausdorff},
            {"sampled_hausdorff_relative", d.hausdorff / d.diagonal},
            {"diagonal", d.diagonal},
            {"diagonal_of", "bounding box of the original mesh"},
            {"metro_diagonal", d.metro_diagonal},
            {"sampled_hausdorff_relative_metro", d.hausdorff / d.metro_diagonal},
            {"metro_diagonal_of", "union bounding box of both meshes widened by 2% of its diagonal on every side"},
            {"sampling",
             {{"face_scheme", to_string(so.face_scheme)},
              {"vertices", so.vertices},
              {"edges", so.edges},
              {"faces", so.faces},
              {"samples_requested", so.samples ? nlohmann::json(*so.samples) : nlohmann::json(nullptr)},
              {"density_requested", so.density ? nlohmann::json(*so.density) : nlohmann::json(nullptr)},
              {"seed", so.seed}}},
            {"forward_is", "samples on the original, distances to the processed surface"},
            {"cutoff", nullptr}};
}

// The distance kind of each direction and, for a point cloud side, what its
// weights and its Hausdorff value are (cloud_distance.h).
void cloud_notes_json(nlohmann::json& sd, const SurfaceDistance& dist)
{
    for (const auto& [key, kind] : {std::pair{"forward", dist.forward_kind}, {"backward", dist.backward_kind}}) {
        nlohmann::json& d = sd[key];
        d["distance_kind"] = to_string(kind);
        if (from_cloud(kind) && d["area_weighted"].is_object()) {
            d["area_weighted"]["area"] = nullptr;
            d["area_weighted"]["area_fraction"] = nullptr;
            d["area_weighted"]["points"] = d["samples"];
            d["area_weighted"]["weights"] = "uniform: every point of the cloud weight 1 (a point cloud has no areas)";
        }
        if (from_cloud(kind) && d["hausdorff"].is_object()) {
            d["hausdorff"]["exact_over_points"] = true;
            d["hausdorff"]["location"]["point_index"] = d["hausdorff"]["location"]["face"];
            d["hausdorff"]["location"]["face"] = nullptr;
            if (to_cloud(kind)) {
                d["hausdorff"]["location"]["closest_point_index"] = d["hausdorff"]["location"]["closest_face"];
                d["hausdorff"]["location"]["closest_face"] = nullptr;
            }
        } else if (kind == DistanceKind::SurfaceToPoint) {
            d["hausdorff_unavailable"] =
                "the target is a point cloud: the maximum over the mesh samples is sampled, not certified";
        }
    }
    if (dist.forward_kind != DistanceKind::SurfaceToSurface) {
        sd["distance_kinds"] =
            "point-to-surface: every point of a cloud, exact distance to the mesh; surface-to-point: samples of a "
            "mesh, distance to the nearest point of the cloud; point-to-point: every point of a cloud, distance to "
            "the nearest point of the other cloud; a cloud's Hausdorff value is exact over its points";
        sd["forward_is"] = "samples (a cloud: its points) of the original, distances to the processed input";
        sd["diagonal_of"] = from_cloud(dist.forward_kind) ? "bounding box of the original point cloud"
                                                          : "bounding box of the original mesh";
    }
}

}  // namespace

nlohmann::json surface_distance_json(const SurfaceDistance& d, const SamplingOptions& so)
{
    nlohmann::json j = mesh_surface_distance_json(d, so);
    cloud_notes_json(j, d);
    return j;
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

}  // namespace meshdiff
