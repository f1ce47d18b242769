//! \file surface_distance.h
//! \brief Metro-style surface distance between two triangle meshes: one-sided
//! distances by sampling one surface and measuring the exact distance of each
//! sample to the other surface, and the symmetric Hausdorff distance
//! (Cignoni, Rocchini, Scopigno, "Metro", CGF 17(2), 1998; METHOD.md section 6).
//!
//! Conventions. Forward is A -> B: samples on A (sampling.h), exact distance to
//! the closest point of B (closest_point.h). Backward is B -> A. Both directions
//! use the same target sample count, by default 10 x max(#faces A, #faces B)
//! (Metro's default). Distances are in the meshes' own length unit, in the
//! original coordinates (never normalised). Every sample counts: there is no
//! distance cut-off (MeshLab's Hausdorff filter drops samples farther than its
//! MaxDist, 5% of the diagonal by default; Metro drops those beyond the
//! diagonal of B's box). Divide by `diagonal` (or `metro_diagonal`, to compare
//! with Metro's "wrt bounding box diagonal" figures) for relative values.
//!
//! Statistics over the n samples of a direction, each with weight 1 (as in
//! Metro; face samples are area-uniform, but vertex and edge samples are not):
//! mean = sum d / n; rms = sqrt(sum d^2 / n); stddev = population standard
//! deviation sqrt(sum (d - mean)^2 / n). Percentiles by nearest rank: p_q is the
//! ceil(q/100 x n)-th smallest distance (1-based), so p50, p95, p99 are sample
//! distances. All sums run sequentially in sample order, so the results are
//! bit-identical for any number of OpenMP threads.
//!
//! Known limits. The maximum is a lower bound of the true one-sided Hausdorff
//! distance (a sampled maximum); it converges as the sample count grows. A mesh
//! compared with itself gives 0 at vertex samples exactly; edge and face samples,
//! whose coordinates are rounded, give distances at rounding level (about 1e-16
//! of the coordinates' magnitude), not exactly 0.
#pragma once

#include "meshdiff/closest_point.h"
#include "meshdiff/hausdorff.h"
#include "meshdiff/mesh.h"
#include "meshdiff/sampling.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace meshdiff {

//! Statistics of one direction, in the meshes' length unit.
struct DistanceStats
{
    double min = 0.0;
    double max = 0.0;
    double mean = 0.0;
    double rms = 0.0;
    double stddev = 0.0;  //!< population standard deviation
    double p50 = 0.0;     //!< nearest-rank percentiles (see the file comment)
    double p95 = 0.0;
    double p99 = 0.0;
    std::size_t n_vertex = 0;  //!< vertex samples
    std::size_t n_edge = 0;    //!< edge samples
    std::size_t n_face = 0;    //!< face samples
    //! Where the maximum lies: the first sample (in sample order) at `max`,
    //! its kind and source element (SurfaceSamples::element).
    Vec3 max_point = Vec3::Zero();
    SampleKind max_kind = SampleKind::OnVertex;
    std::uint32_t max_element = 0;
    std::size_t n_samples() const { return n_vertex + n_edge + n_face; }
};

//! The statistics with every distance field divided by \p diagonal (counts
//! unchanged). \throw InvalidArgumentError unless \p diagonal is finite and > 0.
DistanceStats relative_to(const DistanceStats& stats, double diagonal);

//! Result of surface_distance().
struct SurfaceDistance
{
    DistanceStats forward;   //!< A -> B: samples on A
    DistanceStats backward;  //!< B -> A: samples on B
    double hausdorff = 0.0;  //!< max(forward.max, backward.max)
    double diagonal = 0.0;   //!< bounding-box diagonal of A (the original mesh)
    //! Metro's reference: diagonal of the union box of A and B widened by 2% of
    //! its own diagonal on every side of every axis.
    double metro_diagonal = 0.0;
    double relative_hausdorff() const { return hausdorff / diagonal; }  //!< hausdorff / diagonal
    //! Only when asked for: the certified one-sided Hausdorff distances
    //! (hausdorff.h), their lower bounds seeded with the sampled maxima, so
    //! that lower >= forward.max (backward.max).
    std::optional<CertifiedHausdorff> forward_hausdorff;
    std::optional<CertifiedHausdorff> backward_hausdorff;
    //! Only when asked for: the exact distance of every vertex of B (unreferenced
    //! ones included) to the surface of A, in vertex order, from the index of A
    //! that the backward direction built (a per-vertex distance map of B).
    std::vector<double> b_vertex_distance;
};

//! The statistics of \p distances, the distances of \p samples (same order).
//! \throw InvalidArgumentError if the sizes differ or there are no samples.
DistanceStats distance_stats(const SurfaceSamples& samples, const std::vector<double>& distances);

//! One direction: samples \p from with \p options (an unset target means
//! 10 x #faces of \p from) and returns the statistics of the exact distances
//! to \p to.
//! \throw InvalidArgumentError for invalid options or if the options give no sample.
//! \throw InvalidMeshError if \p from is invalid.
DistanceStats one_sided_distance(const Mesh& from, const ClosestPointIndex& to, const SamplingOptions& options = {});

//! Both directions, the symmetric Hausdorff distance and the diagonals.
//! \p a is the original, \p b the processed mesh; \p options apply to both
//! directions (an unset target means 10 x max(#faces A, #faces B)). With
//! \p b_vertex_distances, SurfaceDistance::b_vertex_distance is filled too.
//! With \p certify, both one-sided Hausdorff distances are also certified
//! (hausdorff.h), reusing the indexes of the sampling.
//! \throw InvalidArgumentError for invalid options or if they give no sample.
//! \throw InvalidMeshError if a mesh is invalid (meshdiff::validate()).
SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options = {},
                                 bool b_vertex_distances = false,
                                 const std::optional<HausdorffOptions>& certify = std::nullopt);

//! One direction of a surface distance with everything kept: the samples of
//! the source surface and the exact distance of each to the other surface.
struct SampledDirection
{
    SurfaceSamples samples;         //!< the samples (points, kinds, source elements), in sample order
    std::vector<double> distances;  //!< exact distance of each sample to the other surface, same order
};

//! Result of surface_distance_samples(): the statistics, bit for bit those of
//! surface_distance() with the same arguments, and the samples behind them
//! (for histograms, per-kind statistics or plots of one's own).
struct SampledSurfaceDistance
{
    SurfaceDistance distance;   //!< as surface_distance() returns it (no b_vertex_distance)
    SampledDirection forward;   //!< samples on A, distances to B
    SampledDirection backward;  //!< samples on B, distances to A
};

//! surface_distance() keeping every sample and its distance (about 40 bytes
//! per sample and direction). Same arguments, conventions and exceptions.
SampledSurfaceDistance surface_distance_samples(const Mesh& a, const Mesh& b, const SamplingOptions& options = {});

//! Exact distance of every vertex of \p from (unreferenced ones included) to
//! the surface indexed by \p to, in vertex order; for per-vertex distance maps.
std::vector<double> vertex_distances(const Mesh& from, const ClosestPointIndex& to);

//! Diagonal of the union of the boxes of \p a and \p b widened by 2% of its
//! diagonal on every side (Metro's reference diagonal).
double metro_diagonal(const Mesh& a, const Mesh& b);

}  // namespace meshdiff
