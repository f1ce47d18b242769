//! \file hausdorff.h (detail)
//! \brief certified_hausdorff() with the closest points of A's vertices
//! already known (surface_distance() has them from its vertex samples).
#pragma once

#include "meshdiff/distance/distance_stats.h"
#include "meshdiff/distance/hausdorff.h"

#include <cstdint>
#include <vector>

namespace meshdiff::detail {

//! The closest point of a vertex of A on B as the surface distance keeps it
//! for its vertex samples and the certification: its distance and face (16
//! bytes; the point, 24 more, is found again for the one vertex that needs
//! it). 1M vertices: 16 MB, not 40.
struct VertexClosest
{
    double distance;
    std::uint32_t face;
};

//! The distances and faces of \p c, in parallel.
std::vector<VertexClosest> vertex_closest(const std::vector<ClosestPoint>& c);

//! certified_hausdorff(a, b, b_index, options, seed) from the derived data
//! of A and B (mesh_data.h), \p vertex_closest being
//! vertex_closest(b_index.closest_points(a.points)) (of every vertex of A).
//! With \p b_opposite (B's PseudoNormals::opposite, B signable), the descents'
//! neighbours are read from it (neighbours_across()) instead of an edge map
//! of B: the same table, the same result.
CertifiedHausdorff certified_hausdorff(const MeshData& a, const MeshData& b, const ClosestPointIndex& b_index,
                                       const HausdorffOptions& options, const std::optional<HausdorffSeed>& seed,
                                       const std::vector<VertexClosest>& vertex_closest,
                                       const std::vector<std::uint32_t>* b_opposite = nullptr);

//! The seed of a certified Hausdorff distance of \p from: the sampled
//! maximum of \p s, on a face of \p from (for a vertex sample, the
//! lowest-index face using it).
HausdorffSeed seed_of(const Mesh& from, const DistanceStats& s);

}  // namespace meshdiff::detail
