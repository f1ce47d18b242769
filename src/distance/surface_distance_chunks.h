// surface_distance() with the size of the sample chunks as a parameter (for
// the tests of the chunk boundaries).
#pragma once

#include "meshdiff/distance/surface_distance.h"

#include "meshdiff/geometry/sampling.h"

#include "geometry/query_block.h"

#include <cstddef>
#include <cstdint>
#include <vector>

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

//! How much shorter, on average, chunk_query_order()'s steps between the
//! runs must be than the samples' own for it to order a chunk.
constexpr double kOrderedStepRatio = 2.5;
//! After how many chunks in a row that begin with one kind of sample and keep
//! their own order the surface distance stops trying to order such chunks.
constexpr std::size_t kOrderTrials = 2;

//! The order in which the surface distance queries a chunk of \p k samples
//! (points, kinds, elements; k < 2^32): its runs (consecutive samples of one
//! element, the same kind and element) sorted by the Morton code of their
//! first point over \p box (its top 10 bits per axis; ties by position), each
//! run's samples in their own order, as positions 0 .. k - 1 in \p order.
//! Queries close in space then run one after another: each starts from the
//! last one's triangle and finds the index's nodes in cache; their answers do
//! not change. \p order is left empty (the samples' own order) where that
//! order is already as coherent: unless the mean distance between
//! consecutive runs' first points is kOrderedStepRatio times the sorted
//! order's or more.
void chunk_query_order(const Vec3* points, const SampleKind* kind, const std::uint32_t* element, std::size_t k,
                       const BoundingBox& box, std::vector<std::uint32_t>& order);

//! surface_distance() (same options and results, bit for bit), the
//! directions whose samples are not kept made and queried \p chunk samples at
//! a time; \p chunk > 0, a multiple of kQueryBlock so that the queries start
//! from the same triangles as in one batch.
SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options, std::size_t chunk);

}  // namespace meshdiff::detail
