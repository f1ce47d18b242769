#include "meshdiff/vertex_maps.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <algorithm>

namespace meshdiff {

VertexMap distance_map(const Comparison& c, std::optional<std::pair<double, double>> color_range)
{
    const std::vector<double>& d = c.processed_vertex_distance;
    if (d.size() != c.processed.topology.vertices)
        throw InvalidArgumentError("distance_map: the comparison was made without vertex distances");
    double lo = 0.0, hi = 0.0;
    if (color_range) {
        if (!(color_range->first < color_range->second))
            throw InvalidArgumentError("distance_map: the colour range needs MIN < MAX");
        lo = color_range->first;
        hi = color_range->second;
    } else {
        for (double x : d) hi = std::max(hi, x);
    }
    VertexMap m;
    m.scalars.push_back({"distance", d});
    m.colors = sequential_colors(d, lo, hi);
    m.comments = {
        fmt::format("per-vertex distance of {} to the surface of {}", c.processed.input.path, c.original.input.path),
        fmt::format("colour: blue (low) to red (high) over [{:.9g}, {:.9g}]", lo, hi)};
    // Where the certified one-sided Hausdorff distances are attained on this
    // (the processed) mesh: the backward one at a point of it, the forward one
    // at the closest point of it to a point of the original.
    if (c.distance && c.distance->backward_hausdorff && c.distance->forward_hausdorff) {
        const HausdorffLocation& b = c.distance->backward_hausdorff->location;
        const HausdorffLocation& f = c.distance->forward_hausdorff->location;
        m.comments.push_back(
            fmt::format("hausdorff processed->original in [{:.9g}, {:.9g}] attained at {:.9g} {:.9g} {:.9g} on face {}",
                        c.distance->backward_hausdorff->lower, c.distance->backward_hausdorff->upper, b.point.x(),
                        b.point.y(), b.point.z(), b.face));
        m.comments.push_back(fmt::format(
            "hausdorff original->processed in [{:.9g}, {:.9g}] attained nearest to {:.9g} {:.9g} {:.9g} on face {}",
            c.distance->forward_hausdorff->lower, c.distance->forward_hausdorff->upper, f.closest_point.x(),
            f.closest_point.y(), f.closest_point.z(), f.closest_face));
    }
    return m;
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
