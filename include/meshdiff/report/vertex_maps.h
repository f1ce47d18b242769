//! \file vertex_maps.h
//! \brief Per-vertex maps to write as PLY (io.h write_ply): named scalar
//! properties, a colour per vertex and header comments that say what the
//! colours mean. For viewing results in MeshLab, CloudCompare or ParaView.
#pragma once

#include "meshdiff/compare.h"
#include "meshdiff/io/io.h"
#include "meshdiff/report/colormap.h"
#include "meshdiff/roughness/roughness.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace meshdiff {

//! What write_ply() writes beside the positions and faces.
struct VertexMap
{
    std::vector<VertexScalar> scalars;
    std::vector<Rgb> colors;
    std::vector<std::string> comments;
};

//! The distance map of a comparison made with CompareOptions::vertex_distances:
//! per vertex of the processed mesh its exact distance to the original surface
//! (property "distance"; and "signed_distance", positive outside, when the
//! original can be signed against: signed_distance.h; then "quality", the
//! distance again, which MeshLab reads as its per-vertex quality), coloured by sequential_colors() over
//! \p color_range, by default [0, largest distance]. With certified Hausdorff
//! distances, two comments mark where they are attained on the processed
//! mesh (point and face).
//! \throw InvalidArgumentError if the comparison has no vertex distances or
//!        the range is not finite MIN <= MAX (a degenerate range is valid).
VertexMap distance_map(const Comparison& comparison, std::optional<std::pair<double, double>> color_range = {});

//! Which mesh of a comparison a distance map shows.
enum class MapSide
{
    Original,   //!< the original's vertices, distances to the processed surface
    Processed,  //!< the processed mesh's vertices, distances to the original surface
};

//! The distance map of either mesh (distance_map(c, range) is the processed
//! one): property "distance", colours as above; comments name the side, the
//! range and where the certified Hausdorff distances are attained on that
//! mesh. Give both maps of one comparison the same range (e.g.
//! distance_map_range()) so that one colour means one distance on both.
VertexMap distance_map(const Comparison& comparison, MapSide side,
                       std::optional<std::pair<double, double>> color_range = {});

//! [0, the largest vertex distance of both meshes]: one colour scale for the
//! two maps of a comparison.
//! \throw InvalidArgumentError if the comparison has no vertex distances.
std::pair<double, double> distance_map_range(const Comparison& comparison);

//! The default colour range of the distance maps and the HTML report: [0, this
//! percentile of both meshes' vertex distances], MeshLab's percentile clamp,
//! so that one worst point does not turn every other vertex blue
//! (`--color-range max` is [0, the largest]).
constexpr double kDefaultColorPercentile = 99.0;

//! [0, the \p percentile th percentile (nearest rank) of the vertex distances
//! of both meshes]: a colour scale robust to a few worst vertices (100: the
//! largest, as distance_map_range()); [0, 1] if that is 0.
//! \throw InvalidArgumentError if the comparison has no vertex distances or
//!        \p percentile is not in (0, 100].
std::pair<double, double> distance_color_range(const Comparison& comparison, double percentile);

//! The per-vertex data of a profile made with keep_vertex_data: H, D_<level>
//! per level, D_global, D_r<radius> per metric level (the radius's decimal
//! point written p: D_r0p05), and `worst` (1 at the worst |D| vertices of some
//! level or radius); H coloured by diverging_colors() over [-R, R], R = \p color_range
//! if > 0, else robust_symmetric_range(H). \p source names the input in the
//! comments. Write it with the normalised mesh (apply_normalization()).
//! \throw InvalidArgumentError if the profile has no vertex data.
VertexMap profile_map(const RoughnessProfile& profile, const std::string& source, double color_range = 0.0);

//! write_ply() of \p mesh with the map's properties, colours and comments.
void write_ply(const std::filesystem::path& path, const Mesh& mesh, const VertexMap& map);

}  // namespace meshdiff
