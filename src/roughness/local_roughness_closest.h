//! \file local_roughness_closest.h (detail)
//! \brief The local roughness difference handing over the closest points it
//! finds: what compare_meshes() passes on to the surface distance, whose
//! backward direction needs the same ones.
#pragma once

#include "meshdiff/roughness/local_roughness.h"

#include <vector>

namespace meshdiff::detail {

//! local_roughness_distance(), and, when \p closest is given, the closest
//! points of mesh's vertices on other (other_index.closest_points(mesh.points))
//! moved into it.
LocalRoughnessDistance local_roughness_distance(const Mesh& mesh, const RoughnessProfile& profile, const Mesh& other,
                                                const RoughnessProfile& other_profile,
                                                const ClosestPointIndex& other_index, double trim,
                                                bool keep_vertex_data, LocalRoughnessParts parts,
                                                std::vector<ClosestPoint>* closest);

}  // namespace meshdiff::detail
