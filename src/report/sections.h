//! \file sections.h (private)
//! \brief Parts of one report made in the file of another subject: the
//! comparison report (compare.cpp) takes its surface distance section from
//! distance.cpp.
#pragma once

#include "meshdiff/compare.h"

#include <string>

namespace meshdiff::detail {

//! The surface distance section of comparison_text() (\p c has a distance):
//! Metro's statistics of both directions, the Hausdorff distance (certified
//! interval or sampled) and the summary metrics; with a point cloud among the
//! inputs, the distances of clouds (cloud_distance.h).
std::string surface_distance_text(const Comparison& c);

//! What the scale s of a normalisation is, for the text reports (profile.cpp).
const char* scale_meaning(NormalizeMethod method);

}  // namespace meshdiff::detail
