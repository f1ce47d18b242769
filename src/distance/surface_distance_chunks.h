// surface_distance() with the size of the sample chunks as a parameter (for
// the tests of the chunk boundaries).
#pragma once

#include "meshdiff/distance/surface_distance.h"

#include "geometry/query_block.h"

#include <cstddef>

namespace meshdiff::detail {

//! The bounding-box diagonal of \p a (the original), which every relative
//! distance divides by; throws InvalidMeshError when it is not positive: all
//! of A's vertices (or points) at one place, or so close that the diagonal
//! underflows. \p what names A's elements ("vertices", "points").
double reference_diagonal(const MeshData& a, const char* what);

//! The samples a direction makes and queries at a time when they are not kept
//! (64 query blocks, about 4 MB of points, kinds, elements and signs; two
//! such sets, one queried while the other is folded).
constexpr std::size_t kSampleChunk = 64 * kQueryBlock;

//! surface_distance() (same options and results, bit for bit), the
//! directions whose samples are not kept made and queried \p chunk samples at
//! a time; \p chunk > 0, a multiple of kQueryBlock so that the queries start
//! from the same triangles as in one batch.
SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options, std::size_t chunk);

}  // namespace meshdiff::detail
