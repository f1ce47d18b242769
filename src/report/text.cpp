#include "meshdiff/report/text.h"

#include "meshdiff/version.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace meshdiff {

namespace {

// The mesh and defect lines that head a profile report.
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
    s += fmt::format("scale      centroid ({:.6g}, {:.6g}, {:.6g}), s = {:.6g} (mean vertex distance to centroid)\n",
                     p.normalization.center.x(), p.normalization.center.y(), p.normalization.center.z(),
                     p.normalization.scale);
    s += fmt::format("curvature  {}{}; undefined {}, 2-ring {}, normal rows dropped {}, quadric fallback {}\n",
                     to_string(p.curvature_options.method),
                     p.curvature_options.method == CurvatureMethod::MeyerCotangent
                         ? ""
                         : fmt::format(" (row weighting {})", to_string(p.curvature_options.weighting)),
                     p.curvature_undefined, p.curvature_widened, p.curvature_normal_rows_dropped, p.curvature_fallback);
    s += fmt::format("\n   level        sigma     used   no-nbhd {:>9}\n",
                     fmt::format("top{:g}%", 100.0 * p.outlier_fraction));
    auto row = [&](const std::string& name, const LevelRoughness& l) {
        s += fmt::format("{:>8} {:>12.6g} {:>8} {:>9} {:>8.1f}%\n", name, l.sigma, l.vertices_used, l.no_neighborhood,
                         100.0 * l.top_share);
    };
    for (const auto& l : p.levels) row(std::to_string(l.level), l);
    if (p.has_global) row("global", p.global);
    if (!p.radii.empty()) {
        s += fmt::format("\n  radius        sigma     used   no-nbhd {:>9}   (metric levels, area-weighted)\n",
                         fmt::format("top{:g}%", 100.0 * p.outlier_fraction));
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
    std::string text = fmt::format(
        "\nexact profile from the vertex property '{}' (H error of the estimate on the scaled "
        "mesh: RMS {:.4g}, max {:.4g} over {} vertices)\n   level  sigma estimated  sigma exact\n",
        property, e.h_error.rms, e.h_error.max, e.h_error.compared);
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
    if (c.distance && (c.original.input.point_cloud || c.processed.input.point_cloud)) {
        s += cloud_distance_text(c);
    } else if (c.distance) {
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
    }
    s += same_connectivity_text(c);
    return s;
}

std::string smoothing_text(const std::string& output, const SmoothingOptions& options, std::size_t vertices,
                           const SmoothingReport& report)
{
    std::string s = fmt::format("{}: {} {}-updating, {} iterations, {} vertices\n", output, to_string(options.method),
                                to_string(options.update), options.iterations, vertices);
    if (!report.steps.empty())
        s += fmt::format("flow time {:.6g} e^2 (e = {:.6g}, the initial mean edge length)\n", report.time,
                         report.mean_edge);
    return s;
}

std::optional<std::string> smoothing_warning(const std::string& input, const SmoothingOptions& options,
                                             const SmoothingReport& report)
{
    if (report.unstable_iterations == 0) return std::nullopt;
    return fmt::format(
        "warning: {}: {} of {} explicit steps exceeded the stability bound (up to {:.3g} times); the flow "
        "may diverge: use a smaller --step, --step-control adaptive or --implicit (mcf)\n",
        input, report.unstable_iterations, options.iterations, report.max_stability_ratio());
}

std::string noise_description(const NoiseOptions& o, const NoiseReport& r)
{
    const std::string law = o.distribution == NoiseDistribution::Uniform
                                ? fmt::format("uniform [-{}, {})", o.amplitude, o.amplitude)
                                : fmt::format("gaussian sigma {}", o.amplitude);
    switch (o.unit) {
        case NoiseUnit::MeanEdge:
            return fmt::format("{} x mean edge length {:.6g}", law, r.unit_length);
        case NoiseUnit::BBoxDiagonal:
            return fmt::format("{} x bbox diagonal {:.6g}", law, r.unit_length);
        case NoiseUnit::Absolute:
            break;
    }
    return law + " in mesh units";
}

namespace {
std::string noise_along(const NoiseOptions& o)
{
    return o.direction == NoiseDirection::Normal ? "along vertex normals" : "along random directions";
}
}  // namespace

std::string noise_comment(const std::string& input, const NoiseOptions& options, const NoiseReport& r)
{
    std::string comment = fmt::format("meshdiff noise: {} moved {} by {} = amplitude {:.6g}, seed {}, boundary {}",
                                      input, noise_along(options), noise_description(options, r), r.amplitude,
                                      options.seed, options.move_boundary ? "moved" : "fixed");
    std::replace_if(
        comment.begin(), comment.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    return comment;
}

std::string noise_text(const std::string& output, const NoiseOptions& options, const NoiseReport& r)
{
    return fmt::format(
        "{}: {} vertices moved, {} skipped ({} boundary, {} without direction, {} isolated); amplitude {:.6g} ({}) "
        "{}, seed {}\n",
        output, r.moved, r.skipped(), r.skipped_boundary, r.skipped_no_direction, r.skipped_isolated, r.amplitude,
        noise_description(options, r), noise_along(options), options.seed);
}

std::string shape_text(const std::string& output, const Shape& shape, const std::string& description)
{
    const auto [lo, hi] = std::minmax_element(shape.exact_H.begin(), shape.exact_H.end());
    return fmt::format("{}: {} vertices, {} faces, exact H in [{:.6g}, {:.6g}] ({})\n", output, shape.mesh.n_vertices(),
                       shape.mesh.n_faces(), *lo, *hi, description);
}

}  // namespace meshdiff
