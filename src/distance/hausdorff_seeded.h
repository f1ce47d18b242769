//! \file hausdorff.h (detail)
//! \brief certified_hausdorff() with the closest points of A's vertices
//! already known (surface_distance() has them from its vertex samples).
#pragma once

#include "meshdiff/distance/hausdorff.h"

#include <vector>

namespace meshdiff::detail {

//! certified_hausdorff(a, b, b_index, options, seed), \p vertex_closest being
//! b_index.closest_points(a.points) (the closest point of every vertex of A).
CertifiedHausdorff certified_hausdorff(const Mesh& a, const Mesh& b, const ClosestPointIndex& b_index,
                                       const HausdorffOptions& options, const std::optional<HausdorffSeed>& seed,
                                       const std::vector<ClosestPoint>& vertex_closest);

}  // namespace meshdiff::detail
