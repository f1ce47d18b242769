//! \file geometry/vertex_areas.h
//! \brief The barycentric area share of each vertex, the weight of the
//! area-weighted roughness levels (metric_levels.h) and of Corsini's measure
//! (corsini.h).
#pragma once

#include "meshdiff/core/mesh.h"

#include <vector>

namespace meshdiff {

//! The area share of each vertex: one third of the area of each incident
//! face (a face with a repeated corner, or of zero area, contributes 0).
//! Sums to surface_area() over the faces without a repeated corner.
std::vector<double> vertex_areas(const Mesh& mesh);

}  // namespace meshdiff
