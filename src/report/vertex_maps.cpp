#include "meshdiff/report/vertex_maps.h"

#include "meshdiff/error.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace meshdiff {

std::pair<double, double> distance_map_range(const Comparison& c)
{
    if (c.processed_vertex_distance.size() != c.processed.topology.vertices ||
        c.original_vertex_distance.size() != c.original.topology.vertices)
        throw InvalidArgumentError("distance_map_range: the comparison was made without vertex distances");
    double hi = 0.0;
    for (double x : c.processed_vertex_distance) hi = std::max(hi, x);
    for (double x : c.original_vertex_distance) hi = std::max(hi, x);
    return {0.0, hi};
}

std::pair<double, double> distance_color_range(const Comparison& c, double percentile)
{
    if (!(percentile > 0.0 && percentile <= 100.0))
        throw InvalidArgumentError(fmt::format("distance_color_range: percentile {} is not in (0, 100]", percentile));
    if (percentile == 100.0) return distance_map_range(c);
    distance_map_range(c);  // the same refusal without vertex distances
    std::vector<double> all;
    all.reserve(c.original_vertex_distance.size() + c.processed_vertex_distance.size());
    for (const auto* d : {&c.original_vertex_distance, &c.processed_vertex_distance})
        for (double x : *d)
            if (std::isfinite(x)) all.push_back(x);
    if (all.empty()) return {0.0, 1.0};
    const auto k = std::size_t(std::llround(percentile / 100.0 * double(all.size() - 1)));
    std::nth_element(all.begin(), all.begin() + std::ptrdiff_t(k), all.end());
    return {0.0, all[k] > 0.0 ? all[k] : 1.0};
}

VertexMap distance_map(const Comparison& c, MapSide side, std::optional<std::pair<double, double>> color_range)
{
    const bool processed = side == MapSide::Processed;
    const std::vector<double>& d = processed ? c.processed_vertex_distance : c.original_vertex_distance;
    const MeshFacts& self = processed ? c.processed : c.original;
    const MeshFacts& other = processed ? c.original : c.processed;
    if (d.size() != self.topology.vertices)
        throw InvalidArgumentError("distance_map: the comparison was made without vertex distances");
    double lo = 0.0, hi = 0.0;
    if (color_range) {
        // A degenerate range (a mesh compared with itself: [0, 0]) is a valid range: every colour its low end.
        if (!(std::isfinite(color_range->first) && std::isfinite(color_range->second) &&
              color_range->first <= color_range->second))
            throw InvalidArgumentError("distance_map: the colour range needs finite MIN <= MAX");
        lo = color_range->first;
        hi = color_range->second;
    } else {
        for (double x : d) hi = std::max(hi, x);
    }
    const std::vector<double>& sd = processed ? c.processed_vertex_signed_distance : c.original_vertex_signed_distance;
    VertexMap m;
    m.scalars.push_back({"distance", d});
    if (sd.size() == d.size()) m.scalars.push_back({"signed_distance", sd});
    // The distance again as "quality", the property MeshLab reads (its colourize, histogram and clamp filters).
    m.scalars.push_back({"quality", d});
    // On the processed mesh: the local roughness difference per ring level (local_roughness.h), where it was kept.
    std::vector<int> local_levels;
    if (processed && c.local_roughness) {
        const LocalRoughnessDistance& l = *c.local_roughness;
        for (std::size_t k = 0; k < l.vertex.size() && k < l.levels.size(); ++k)
            if (l.vertex[k].size() == d.size()) {
                m.scalars.push_back({fmt::format("local_{}", l.levels[k]), l.vertex[k]});
                local_levels.push_back(l.levels[k]);
            }
    }
    m.colors = sequential_colors(d, lo, hi);
    m.comments = {fmt::format("per-vertex distance of {} to the surface of {}", self.input.path, other.input.path),
                  fmt::format("colour: blue (low) to red (high) over [{:.9g}, {:.9g}]", lo, hi)};
    // Where the certified one-sided Hausdorff distances are attained on this
    // mesh: the one whose samples lie on it at a point of it, the other at the
    // closest point of it to a point of the other mesh.
    if (c.distance && c.distance->backward_hausdorff && c.distance->forward_hausdorff) {
        const CertifiedHausdorff& from_self =
            processed ? *c.distance->backward_hausdorff : *c.distance->forward_hausdorff;
        const CertifiedHausdorff& to_self =
            processed ? *c.distance->forward_hausdorff : *c.distance->backward_hausdorff;
        const char* self_name = processed ? "processed" : "original";
        const char* other_name = processed ? "original" : "processed";
        const HausdorffLocation& a = from_self.location;
        const HausdorffLocation& b = to_self.location;
        m.comments.push_back(
            fmt::format("hausdorff {}->{} in [{:.9g}, {:.9g}] attained at {:.9g} {:.9g} {:.9g} on face {}", self_name,
                        other_name, from_self.lower, from_self.upper, a.point.x(), a.point.y(), a.point.z(), a.face));
        m.comments.push_back(
            fmt::format("hausdorff {}->{} in [{:.9g}, {:.9g}] attained nearest to {:.9g} {:.9g} {:.9g} on face {}",
                        other_name, self_name, to_self.lower, to_self.upper, b.closest_point.x(), b.closest_point.y(),
                        b.closest_point.z(), b.closest_face));
    }
    if (sd.size() == d.size())
        m.comments.push_back(
            "signed_distance: positive outside the surface of the other mesh, negative inside "
            "(angle-weighted pseudo-normals)");
    else
        m.comments.push_back("no signed_distance: the other mesh cannot be signed against (see the report)");
    if (!local_levels.empty())
        m.comments.push_back(fmt::format(
            "local_L (L = {}): F minus its mean over the vertex's L-ring, F = H minus the original's H at the "
            "closest point (roughness added > 0, lost < 0; NaN where undefined); their trimmed RMS is "
            "roughness_distance.local",
            fmt::join(local_levels, ", ")));
    return m;
}

VertexMap distance_map(const Comparison& c, std::optional<std::pair<double, double>> color_range)
{
    return distance_map(c, MapSide::Processed, color_range);
}

VertexMap profile_map(const RoughnessProfile& profile, const std::string& source, double color_range)
{
    const std::size_t n = profile.vertices;
    if (profile.H.size() != n) throw InvalidArgumentError("profile_map: the profile was made without vertex data");
    VertexMap m;
    m.scalars.push_back({"H", profile.H});
    for (std::size_t k = 0; k < profile.levels.size(); ++k)
        m.scalars.push_back({fmt::format("D_{}", profile.levels[k].level), profile.D[k]});
    if (profile.has_global) m.scalars.push_back({"D_global", profile.D_global});
    // Metric levels: D_r<radius> with the decimal point written p (D_r0p05), as PLY readers split names on dots.
    auto radius_name = [](double r) {
        std::string t = fmt::format("{:g}", r);
        for (char& ch : t)
            if (ch == '.') ch = 'p';
        return "D_r" + t;
    };
    for (std::size_t k = 0; k < profile.radii.size() && k < profile.D_radii.size(); ++k)
        m.scalars.push_back({radius_name(profile.radii[k].radius), profile.D_radii[k]});
    std::vector<double> worst(n, 0.0);
    std::vector<std::string> marks;
    auto mark = [&](const LevelRoughness& l, const std::string& name) {
        std::string ids;
        for (auto v : l.worst_vertices) {
            worst[v] = 1.0;
            ids += fmt::format(" {}", v);
        }
        marks.push_back(fmt::format("worst |D| vertices at {}:{}", name, ids));
    };
    for (const auto& l : profile.levels) mark(l, fmt::format("level {}", l.level));
    if (profile.has_global) mark(profile.global, "global");
    for (const auto& l : profile.radii) mark(l, fmt::format("radius {:g}", l.radius));
    m.scalars.push_back({"worst", worst});
    const double range = color_range > 0.0 ? color_range : robust_symmetric_range(profile.H);
    m.colors = diverging_colors(profile.H, range);
    m.comments.push_back(
        fmt::format("source: {} scaled by 1/{:.9g} about its centroid", source, profile.normalization.scale));
    m.comments.push_back(fmt::format("colour: H on a blue-white-red map over [-{:.6g}, {:.6g}]", range, range));
    m.comments.insert(m.comments.end(), marks.begin(), marks.end());
    return m;
}

void write_ply(const std::filesystem::path& path, const Mesh& mesh, const VertexMap& map)
{
    write_ply(path, mesh, map.scalars, map.colors, map.comments);
}

}  // namespace meshdiff
