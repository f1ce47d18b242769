#include "meshdiff/report/json.h"
#include "meshdiff/report/text.h"

#include "sections.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace meshdiff {

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

namespace {

std::string stats_text(const std::string& title, const DistanceStats& s, double diag, const char* target)
{
    std::string out = fmt::format("{}\n", title);
    if (s.n_point > 0)
        out += fmt::format("  samples: {} (every point of the cloud)\n", s.n_samples());
    else
        out +=
            fmt::format("  samples: {} ({} vertex, {} edge, {} face)\n", s.n_samples(), s.n_vertex, s.n_edge, s.n_face);
    out += fmt::format("  {:>5} {:>14} {:>14}\n", "", "absolute", "wrt diagonal");
    for (const StatField& f : kStatFields)
        out += fmt::format("  {:>5} {:>14.6g} {:>14.6g}\n", f.label, s.*f.field, s.*f.field / diag);
    if (s.signed_distance) {
        const SignedDistanceStats& g = *s.signed_distance;
        out +=
            fmt::format("  signed (positive outside {}{}): min {:.6g}, max {:.6g}, mean {:.6g}, RMS {:.6g}\n", target,
                        g.flipped ? ", its orientation flipped to outward" : "", g.min, g.max, g.mean, g.rms);
    } else {
        out += fmt::format("  signed: unavailable, {}\n", s.signed_unavailable);
    }
    return out;
}

// The summary metrics of a surface distance (METHOD.md section 6).
// With a point cloud on the forward (\p cloud_a) or backward (\p cloud_b)
// sampled side, that direction weights its points equally (cloud_distance.h).
std::string summary_text(const SurfaceDistance& d, bool cloud_a = false, bool cloud_b = false)
{
    if (!d.summary) return fmt::format("Summary metrics unavailable: {}\n", d.summary_unavailable);
    const SummaryMetrics& m = *d.summary;
    const AreaWeightedStats& f = *d.forward.area_weighted;
    const AreaWeightedStats& b = *d.backward.area_weighted;
    std::string s = cloud_a || cloud_b ? fmt::format("Summary metrics ({}):\n",
                                                     cloud_a && cloud_b ? "every point of each cloud weighted equally"
                                                                        : "a mesh's face samples weighted by the area "
                                                                          "each stands for, a cloud's points equally")
                                       : "Summary metrics (face samples, each weighted by the area it stands for):\n";
    s += fmt::format("  area-weighted mean   forward {:.6g} ({:.6g} wrt diagonal), backward {:.6g} ({:.6g})\n", f.mean,
                     f.mean / d.diagonal, b.mean, b.mean / d.diagonal);
    s += fmt::format("  area-weighted RMS    forward {:.6g} ({:.6g} wrt diagonal), backward {:.6g} ({:.6g})\n", f.rms,
                     f.rms / d.diagonal, b.rms, b.rms / d.diagonal);
    if (!(cloud_a || cloud_b) && (f.area_fraction < 1.0 || b.area_fraction < 1.0))
        s += fmt::format("  area with face samples: {:.4g}% and {:.4g}% of the surfaces\n", 100.0 * f.area_fraction,
                         100.0 * b.area_fraction);
    s += fmt::format("  Chamfer L1 (mean forward + mean backward)        {:.6g} ({:.6g} wrt diagonal)\n", m.chamfer_l1,
                     m.chamfer_l1 / d.diagonal);
    s += fmt::format("  Chamfer L2 (mean squared forward + backward)     {:.6g} ({:.6g} wrt diagonal^2)\n",
                     m.chamfer_l2, m.chamfer_l2 / (d.diagonal * d.diagonal));
    auto db = [](double x) { return std::isfinite(x) ? fmt::format("{:.4f} dB", x) : std::string("inf"); };
    s += fmt::format("  PSNR (MPEG: 10 log10(3 peak^2 / e), peak = diagonal {:.6g}): mean squared {}, Hausdorff {}\n",
                     m.psnr.peak, db(m.psnr.mse_db), db(m.psnr.hausdorff_db));
    for (const FScore& x : d.fscore)
        s += fmt::format("  F-score at {:g} x diagonal ({:.6g}): {:.6f} (precision {:.6f}, recall {:.6f})\n",
                         x.threshold, x.threshold_absolute, x.fscore, x.precision, x.recall);
    return s;
}

// The surface distance when an input is a point cloud (cloud_distance.h).
std::string cloud_distance_text(const Comparison& c)
{
    const auto& d = *c.distance;
    const auto& so = c.options.sampling;
    const bool cloud_a = c.original.input.point_cloud, cloud_b = c.processed.input.point_cloud;
    std::string s = fmt::format("\nSurface distance with a point cloud ({}; {} face sampling of a mesh side{})\n",
                                cloud_a && cloud_b ? "both inputs are point clouds"
                                : cloud_a          ? "M1 is a point cloud"
                                                   : "M2 is a point cloud",
                                to_string(so.face_scheme),
                                so.face_scheme == FaceSampling::MonteCarlo ? fmt::format(", seed {}", so.seed) : "");
    s += "  point-to-surface: every point of a cloud, exact distance to the mesh; surface-to-point: samples of a "
         "mesh,\n  distance to the nearest point of the cloud; point-to-point: nearest point of the other cloud\n";
    s += fmt::format("  diagonal = bounding-box diagonal of the original = {:.6g}\n", d.diagonal);
    s += stats_text(fmt::format("Forward distance (M1 -> M2, {}):", to_string(d.forward_kind)), d.forward, d.diagonal,
                    "M2");
    s += stats_text(fmt::format("Backward distance (M2 -> M1, {}):", to_string(d.backward_kind)), d.backward,
                    d.diagonal, "M1");
    auto side = [&](const char* name, bool from_cloud, bool to_cloud, const std::optional<CertifiedHausdorff>& h,
                    const DistanceStats& st) {
        if (from_cloud && h)
            return fmt::format("  {} {:.8g}, exact over the points (at point {} ({:.9g}, {:.9g}, {:.9g}))\n", name,
                               h->lower, h->location.face, h->location.point.x(), h->location.point.y(),
                               h->location.point.z());
        if (!from_cloud && to_cloud && c.options.hausdorff)
            return fmt::format("  {} {:.8g}, sampled (not certified: the target is a point cloud)\n", name, st.max);
        return fmt::format("  {} {:.8g}, sampled\n", name, st.max);
    };
    s += fmt::format(
        "Hausdorff distance: {:.8g} ({:.6g} wrt bounding box diagonal; {:.6g} wrt Metro's widened union box, "
        "diagonal {:.6g}), {}\n",
        d.hausdorff, d.hausdorff / d.diagonal, d.hausdorff / d.metro_diagonal, d.metro_diagonal,
        d.forward_hausdorff && d.backward_hausdorff ? "exact" : "a sampled lower bound");
    s += side("forward  (M1 -> M2):", cloud_a, cloud_b, d.forward_hausdorff, d.forward);
    s += side("backward (M2 -> M1):", cloud_b, cloud_a, d.backward_hausdorff, d.backward);
    s += summary_text(d, cloud_a, cloud_b);
    if (d.summary && !(cloud_a && cloud_b)) {
        const AreaWeightedStats& m = cloud_a ? *d.backward.area_weighted : *d.forward.area_weighted;
        if (m.area_fraction < 1.0)
            s += fmt::format("  area with face samples: {:.4g}% of the mesh\n", 100.0 * m.area_fraction);
    }
    return s;
}

// The surface distance between two meshes, with the certified Hausdorff
// interval when computed.
std::string mesh_distance_text(const Comparison& c)
{
    std::string s;
    const auto& d = *c.distance;
    const auto& so = c.options.sampling;
    s += fmt::format("\nSurface distance (Metro-style: exact point-to-triangle distances, {} face sampling{})\n",
                     to_string(so.face_scheme),
                     so.face_scheme == FaceSampling::MonteCarlo ? fmt::format(", seed {}", so.seed) : "");
    s += fmt::format("  diagonal = bounding-box diagonal of the original = {:.6g}\n", d.diagonal);
    s += stats_text("Forward distance (M1 -> M2):", d.forward, d.diagonal, "M2");
    s += stats_text("Backward distance (M2 -> M1):", d.backward, d.diagonal, "M1");
    if (d.forward_hausdorff && d.backward_hausdorff) {
        const CertifiedHausdorff& f = *d.forward_hausdorff;
        const CertifiedHausdorff& b = *d.backward_hausdorff;
        const double lower = std::max(f.lower, b.lower), upper = std::max(f.upper, b.upper);
        const bool certified = f.certified && b.certified;
        s += fmt::format("Hausdorff distance: {:.8g} .. {:.8g} ({:.8g} .. {:.8g} wrt bounding box diagonal), {}\n",
                         lower, upper, lower / d.diagonal, upper / d.diagonal,
                         certified ? "certified" : "NOT certified: the evaluation budget ran out");
        auto side = [&](const char* name, const CertifiedHausdorff& h, const char* from, const char* to) {
            s += fmt::format(
                "  {} {:.8g} .. {:.8g}{}, at ({:.9g}, {:.9g}, {:.9g}) on face {} of {}, closest point "
                "({:.9g}, {:.9g}, {:.9g}) on face {} of {}\n",
                name, h.lower, h.upper, h.certified ? "" : " (not certified)", h.location.point.x(),
                h.location.point.y(), h.location.point.z(), h.location.face, from, h.location.closest_point.x(),
                h.location.closest_point.y(), h.location.closest_point.z(), h.location.closest_face, to);
        };
        side("forward  (M1 -> M2):", f, "M1", "M2");
        side("backward (M2 -> M1):", b, "M2", "M1");
        s += fmt::format("  widths asked: {:.3g} and {:.3g}; triangle bounds evaluated: {} and {}\n", f.tolerance,
                         b.tolerance, f.bound_evaluations, b.bound_evaluations);
        s += fmt::format(
            "Sampled maximum: {:.6g} ({:.6g} wrt bounding box diagonal; {:.6g} wrt Metro's "
            "widened union box, diagonal {:.6g})\n",
            d.hausdorff, d.hausdorff / d.diagonal, d.hausdorff / d.metro_diagonal, d.metro_diagonal);
    } else {
        s += fmt::format(
            "Hausdorff distance: {:.6g} ({:.6g} wrt bounding box diagonal; {:.6g} wrt Metro's "
            "widened union box, diagonal {:.6g})\n",
            d.hausdorff, d.hausdorff / d.diagonal, d.hausdorff / d.metro_diagonal, d.metro_diagonal);
    }
    s += summary_text(d);
    return s;
}

}  // namespace

namespace detail {

std::string surface_distance_text(const Comparison& c)
{
    return c.original.input.point_cloud || c.processed.input.point_cloud ? cloud_distance_text(c)
                                                                         : mesh_distance_text(c);
}

}  // namespace detail

}  // namespace meshdiff
