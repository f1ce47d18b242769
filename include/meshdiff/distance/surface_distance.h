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
//! The statistics of a direction (min, max, mean, RMS, percentiles, the
//! area-weighted and signed ones, F-scores) are defined in distance_stats.h.
//!
//! Known limits. The maximum is a lower bound of the true one-sided Hausdorff
//! distance (a sampled maximum); it converges as the sample count grows. A mesh
//! compared with itself gives 0 at vertex samples exactly; edge and face samples,
//! whose coordinates are rounded, give distances at rounding level (about 1e-16
//! of the coordinates' magnitude), not exactly 0.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/distance/distance_kind.h"
#include "meshdiff/distance/distance_stats.h"
#include "meshdiff/distance/hausdorff.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/geometry/sampling.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace meshdiff {

//! One direction of a surface distance with everything kept: the samples of
//! the source surface and the exact distance of each to the other surface.
struct SampledDirection
{
    SurfaceSamples samples;         //!< the samples (points, kinds, source elements), in sample order
    std::vector<double> distances;  //!< exact distance of each sample to the other surface, same order
    //! Signed distance of each sample (positive outside the other surface),
    //! same order; empty when the other surface cannot be signed against.
    std::vector<double> signed_distances;
};

//! The per-vertex distance maps of a comparison: every vertex (unreferenced
//! ones included, in vertex order) of the original mesh A and of the processed
//! mesh B with its exact distance to the other surface, and the signed
//! distances (signed_distance.h: positive outside) where the other surface can
//! be signed against (else empty). SurfaceDistance and Comparison (compare.h)
//! both hold them, under these names.
struct VertexDistances
{
    //! Per vertex of the processed mesh B, its distance to the original surface.
    std::vector<double> processed_vertex_distance;
    //! Per vertex of the original mesh A, its distance to the processed surface.
    std::vector<double> original_vertex_distance;
    std::vector<double> processed_vertex_signed_distance;  //!< signed processed_vertex_distance
    std::vector<double> original_vertex_signed_distance;   //!< signed original_vertex_distance
};

//! Result of surface_distance(). With DistanceOptions::vertex_distances, the
//! VertexDistances are filled, from the indexes the two directions build (of
//! B forward, of A backward).
struct SurfaceDistance : VertexDistances
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
    //! Deprecated, removed in 0.3: the 0.2 names of the VertexDistances
    //! (b_vertex_distance: processed_vertex_distance, a_vertex_distance:
    //! original_vertex_distance, and the signed pair), filled instead of them
    //! by the deprecated positional overloads of surface_distance() and
    //! cloud_surface_distance() only.
    std::vector<double> b_vertex_distance;
    std::vector<double> a_vertex_distance;
    std::vector<double> b_vertex_signed_distance;
    std::vector<double> a_vertex_signed_distance;
    //! Chamfer and PSNR; std::nullopt (with summary_unavailable saying why)
    //! when a direction has no area-weighted statistics.
    std::optional<SummaryMetrics> summary;
    std::string summary_unavailable;
    //! One per SummaryOptions::fscore_thresholds, in the order asked (empty
    //! when none was asked or the summary is unavailable).
    std::vector<FScore> fscore;
    //! Which distance each direction measures: surface-to-surface here; with
    //! a point cloud, as cloud_surface_distance() sets them (cloud_distance.h).
    DistanceKind forward_kind = DistanceKind::SurfaceToSurface;
    DistanceKind backward_kind = DistanceKind::SurfaceToSurface;
    //! With DistanceOptions::keep_samples: the samples of A (forward) and of B
    //! (backward), each with its distance to the other surface; else empty.
    SampledDirection forward_samples;
    SampledDirection backward_samples;
};

//! The options of surface_distance() and cloud_surface_distance(): what to
//! sample, certify, summarise and keep. The defaults are Metro's sampling,
//! sampled maxima only, the summary without F-scores or histograms.
struct DistanceOptions
{
    //! The sampling of both directions (sampling.h); an unset target means
    //! 10 x max(#faces A, #faces B).
    SamplingOptions sampling{};
    //! Certify both one-sided Hausdorff distances (hausdorff.h) with these
    //! options, the lower bounds seeded with the sampled maxima and reusing
    //! the indexes of the sampling; std::nullopt keeps the sampled maxima only.
    std::optional<HausdorffOptions> hausdorff;
    //! F-score thresholds and histogram bins (the area-weighted statistics,
    //! Chamfer and PSNR are always computed).
    SummaryOptions summary{};
    //! Also the exact distance of every vertex of each mesh to the other
    //! surface, and the signed ones where the other can be signed against
    //! (the VertexDistances of the result), from the indexes the directions
    //! build.
    bool vertex_distances = false;
    //! Keep the samples of both directions and their distances
    //! (SurfaceDistance::forward_samples, backward_samples; about 50 bytes per
    //! sample and direction). Without it, each direction makes, queries and
    //! sums its samples a chunk at a time and keeps only their distances
    //! (8 bytes per sample, for the percentiles); the statistics are the same
    //! bit for bit.
    bool keep_samples = false;
    //! Indexes of A and of B that the caller built (ClosestPointIndex(a),
    //! ClosestPointIndex(b)) and keeps, e.g. to measure one mesh against
    //! several others: the backward direction measures to A, the forward one
    //! to B; nullptr (the default): the direction builds the index of its
    //! mesh and drops it at its end. Each must index that very mesh (its face
    //! count is checked) and outlive the call; the results are the same bit
    //! for bit. Not used for a point cloud (cloud_distance.h), which gets its
    //! own k-d tree.
    const ClosestPointIndex* index_a = nullptr;
    const ClosestPointIndex* index_b = nullptr;
    //! The derived data (mesh_data.h) of A and of B that the caller keeps,
    //! e.g. from the topology report of the same meshes: each datum is then
    //! derived once for all of them; nullptr (the default): made for the
    //! call. Each must be that very mesh's (MeshData::mesh() is A, B) and
    //! outlive the call; the results are the same bit for bit.
    const MeshData* data_a = nullptr;
    const MeshData* data_b = nullptr;
};

//! The Chamfer distances and PSNR of \p d from its directions'
//! area_weighted, its diagonal and sampled maxima; std::nullopt and the
//! \p reason if a direction has no area-weighted statistics.
std::optional<SummaryMetrics> summary_metrics(const SurfaceDistance& d, std::string* reason = nullptr);

//! One direction: samples \p from with \p options (an unset target means
//! 10 x #faces of \p from) and returns the statistics of the exact distances
//! to \p to.
//! \throw InvalidArgumentError for invalid options or if the options give no sample.
//! \throw InvalidMeshError if \p from is invalid.
DistanceStats one_sided_distance(const Mesh& from, const ClosestPointIndex& to, const SamplingOptions& options = {});

//! Both directions, the symmetric Hausdorff distance and the diagonals.
//! \p a is the original, \p b the processed mesh; \p options (DistanceOptions)
//! say how to sample both directions, whether to certify the one-sided
//! Hausdorff distances, what to summarise and what to keep. The area-weighted
//! statistics, the summary metrics and, when asked for in options.summary,
//! the F-scores and histograms are filled too (sums over the samples).
//! \throw InvalidArgumentError for invalid options or if they give no sample.
//! \throw InvalidMeshError if a mesh is invalid (meshdiff::validate()).
SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options = {});

//! Deprecated, removed in 0.3: surface_distance(a, b, DistanceOptions), with
//! \p options, \p certify, \p summary and \p b_vertex_distances as the
//! fields sampling, hausdorff, summary and vertex_distances. The per-vertex
//! distances are returned under their 0.2 names (SurfaceDistance::
//! a_vertex_distance, b_vertex_distance and the signed pair). With
//! \p forward_samples (\p backward_samples), the samples of that direction
//! and their distances are kept there (SurfaceDistance::forward_samples and
//! backward_samples stay empty). The results are the same bit for bit.
SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options,
                                 bool b_vertex_distances = false,
                                 const std::optional<HausdorffOptions>& certify = std::nullopt,
                                 const SummaryOptions& summary = {}, SampledDirection* forward_samples = nullptr,
                                 SampledDirection* backward_samples = nullptr);

//! Result of surface_distance_samples(): the statistics, bit for bit those of
//! surface_distance() with the same options, and the samples behind them
//! (for histograms, per-kind statistics or plots of one's own).
struct SampledSurfaceDistance
{
    SurfaceDistance distance;   //!< as surface_distance() returns it (no vertex distances)
    SampledDirection forward;   //!< samples on A, distances to B
    SampledDirection backward;  //!< samples on B, distances to A
};

//! surface_distance() keeping every sample and its distance (about 50 bytes
//! per sample and direction): DistanceOptions::keep_samples with the samples
//! moved out of the result. Same conventions and exceptions.
SampledSurfaceDistance surface_distance_samples(const Mesh& a, const Mesh& b, const SamplingOptions& options = {},
                                                const SummaryOptions& summary = {});

//! Exact distance of every vertex of \p from (unreferenced ones included) to
//! the surface indexed by \p to, in vertex order; for per-vertex distance maps.
std::vector<double> vertex_distances(const Mesh& from, const ClosestPointIndex& to);

//! vertex_distances() of \p from to \p to (indexed by \p index), and in
//! \p signed_out the signed ones when \p to can be signed against (else
//! \p signed_out is emptied); \p to_name names \p to in the reason.
std::vector<double> vertex_distances(const Mesh& from, const Mesh& to, const ClosestPointIndex& index,
                                     std::vector<double>& signed_out, const std::string& to_name = "the mesh");

//! Diagonal of the union of the boxes of \p a and \p b widened by 2% of its
//! diagonal on every side (Metro's reference diagonal).
double metro_diagonal(const Mesh& a, const Mesh& b);
//! The same from the two meshes' bounding boxes.
double metro_diagonal(const BoundingBox& a, const BoundingBox& b);

}  // namespace meshdiff
