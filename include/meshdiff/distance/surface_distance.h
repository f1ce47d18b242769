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

#include "meshdiff/core/mesh.h"
#include "meshdiff/distance/distance_kind.h"
#include "meshdiff/distance/hausdorff.h"
#include "meshdiff/geometry/closest_point.h"
#include "meshdiff/geometry/sampling.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace meshdiff {

//! Counts of the distances of one direction in N equal bins over [0, max]
//! (Metro's -h histogram): every sample (vertex, edge, face) counts once; a
//! distance d falls in bin min(floor(d / w), N - 1), w = max / N, so the
//! maximum is in the last bin. A direction whose maximum is 0 has all its
//! samples in bin 0 and edges 0, ..., 0.
struct Histogram
{
    std::vector<double> edges;        //!< N + 1 bin edges, edges[i] = i x max / N
    std::vector<std::size_t> counts;  //!< N counts, summing to the sample count
};

//! Area-weighted statistics of one direction, from its face samples only
//! (METHOD.md section 6): each face sample on face f stands for the area
//! A_f / n_f (n_f: the face samples of f), so that the weighted mean converges
//! to the mean of d over the surface, (1 / A) integral d dA, as the sampling
//! is refined (Metro's pooled DistanceStats::mean does not: it over-weights
//! vertices and edges). Faces without a face sample (degenerate ones, and
//! small ones a coarse budget skips) are left out of the sums and of the
//! area; area_fraction says how much of the area was covered.
struct AreaWeightedStats
{
    double mean = 0.0;           //!< sum_i w_i d_i / sum_i w_i
    double mean_square = 0.0;    //!< sum_i w_i d_i^2 / sum_i w_i (the MSE of PSNR, the L2 Chamfer term)
    double rms = 0.0;            //!< sqrt(mean_square)
    std::size_t n_face = 0;      //!< face samples used
    double area = 0.0;           //!< area of the faces holding a face sample, sum_i w_i
    double area_fraction = 0.0;  //!< area / area of the faces
};

//! Signed statistics of one direction (signed_distance.h): each sample's
//! distance with the sign of its side of the target surface, positive outside,
//! negative inside, 0 on it; over the same samples as DistanceStats, each
//! with weight 1 (mean = sum s / n, rms = sqrt(sum s^2 / n), which equals the
//! unsigned rms).
struct SignedDistanceStats
{
    double min = 0.0;
    double max = 0.0;
    double mean = 0.0;
    double rms = 0.0;
    //! The target surface was oriented inwards (negative volume) and was
    //! signed against flipped, so that positive is still outside.
    bool flipped = false;
};

//! The signed statistics of \p signed_distances (over all samples, weight 1).
//! \throw InvalidArgumentError if there are none.
SignedDistanceStats signed_distance_stats(const std::vector<double>& signed_distances);

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
    std::size_t n_point = 0;   //!< points of a point cloud (cloud_distance.h)
    //! Where the maximum lies: the first sample (in sample order) at `max`,
    //! its kind and source element (SurfaceSamples::element).
    Vec3 max_point = Vec3::Zero();
    SampleKind max_kind = SampleKind::OnVertex;
    std::uint32_t max_element = 0;
    std::size_t n_samples() const { return n_vertex + n_edge + n_face + n_point; }
    //! Face samples only, area-weighted; std::nullopt when the direction has
    //! no face sample (faces off, or a budget the vertices and edges used up).
    std::optional<AreaWeightedStats> area_weighted;
    //! Only when SummaryOptions::histogram_bins > 0; else empty.
    Histogram histogram;
    //! The signed statistics when the target surface can be signed against
    //! (signed_distance.h); else std::nullopt and signed_unavailable says why.
    std::optional<SignedDistanceStats> signed_distance;
    std::string signed_unavailable;
};

//! Options of the summary metrics of a surface distance (METHOD.md section 6).
struct SummaryOptions
{
    //! F-score thresholds, relative to the bounding-box diagonal of A (the
    //! original); each finite and > 0. Empty: no F-score.
    std::vector<double> fscore_thresholds;
    //! Bins of the per-direction histogram (Histogram); 0: none.
    std::size_t histogram_bins = 0;
};

//! The most --fscore thresholds and histogram bins accepted.
constexpr std::size_t kMaxFscoreThresholds = 64;
constexpr std::size_t kMaxHistogramBins = 100'000;
//! The largest F-score threshold (relative to the diagonal).
constexpr double kMaxFscoreThreshold = 1e6;

//! Throws OptionError naming the field if a threshold is not finite, > 0 and
//! <= kMaxFscoreThreshold, or there are more than kMaxFscoreThresholds thresholds or
//! kMaxHistogramBins bins.
void validate(const SummaryOptions& options);

//! F-score at one threshold (Knapitsch et al., "Tanks and Temples", ACM TOG
//! 36(4), 2017), over area-weighted face samples: precision = area share of
//! the processed mesh (B, backward samples) closer than the threshold to A;
//! recall = area share of the original (A, forward samples) closer than the
//! threshold to B; fscore = 2 P R / (P + R), 0 when P + R = 0.
struct FScore
{
    double threshold = 0.0;           //!< relative to the diagonal of A
    double threshold_absolute = 0.0;  //!< threshold x diagonal
    double precision = 0.0;
    double recall = 0.0;
    double fscore = 0.0;
};

//! PSNR of the surface distance as in MPEG's point-cloud and mesh metrics
//! (mpeg-pcc-dmetric pc_error, mpeg-pcc-mmetric; METHOD.md section 6):
//! PSNR = 10 log10(factor x peak^2 / e), factor 3, peak = bounding-box
//! diagonal of A, e = a squared distance. The symmetric values take the larger
//! error of the two directions. Infinite (e = 0) is +inf here; reports write null.
struct Psnr
{
    double peak = 0.0;    //!< the diagonal of A
    double factor = 3.0;  //!< pc_error's factor for geometry
    double mse = 0.0;     //!< max(forward, backward) area-weighted mean squared distance
    double mse_db = 0.0;  //!< 10 log10(3 peak^2 / mse)
    double forward_mse_db = 0.0, backward_mse_db = 0.0;
    double hausdorff = 0.0;     //!< the sampled symmetric Hausdorff distance h
    double hausdorff_db = 0.0;  //!< 10 log10(3 peak^2 / h^2)
    double forward_hausdorff_db = 0.0, backward_hausdorff_db = 0.0;
};

//! Summary metrics from both directions' area-weighted statistics.
struct SummaryMetrics
{
    //! Chamfer distance, L1 convention: mean forward + mean backward (area-weighted).
    double chamfer_l1 = 0.0;
    //! Chamfer distance, L2 convention: mean squared forward + mean squared backward.
    double chamfer_l2 = 0.0;
    Psnr psnr;
};

//! The statistics with every distance field divided by \p diagonal (counts
//! unchanged; the area-weighted and histogram parts are left absolute). \throw InvalidArgumentError unless \p diagonal
//! is finite and > 0.
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
    //! Asked for with b_vertex_distance: the same for every vertex of A to the
    //! surface of B, from the forward direction's index of B.
    std::vector<double> a_vertex_distance;
    //! With them, the signed distances (signed_distance.h: positive outside)
    //! where the other mesh can be signed against; else empty.
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
};

//! The area-weighted statistics of \p distances, the distances of \p samples
//! of \p from (same order); std::nullopt if there is no face sample. With
//! \p within, also the area share of the face samples with d < t for each
//! absolute threshold t of \p thresholds (in that order; all 0 without face samples).
//! \throw InvalidArgumentError if the sizes differ.
std::optional<AreaWeightedStats> area_weighted_stats(const Mesh& from, const SurfaceSamples& samples,
                                                     const std::vector<double>& distances,
                                                     const std::vector<double>& thresholds = {},
                                                     std::vector<double>* within = nullptr);

//! The histogram of \p distances in \p bins bins over [0, max].
//! \throw InvalidArgumentError if \p bins is 0 or \p distances is empty.
Histogram distance_histogram(const std::vector<double>& distances, std::size_t bins);

//! The Chamfer distances and PSNR of \p d from its directions'
//! area_weighted, its diagonal and sampled maxima; std::nullopt and the
//! \p reason if a direction has no area-weighted statistics.
std::optional<SummaryMetrics> summary_metrics(const SurfaceDistance& d, std::string* reason = nullptr);

//! The F-scores at \p relative_thresholds (x \p diagonal) from the area shares
//! below them: \p recall_shares of the original's face samples (forward),
//! \p precision_shares of the processed mesh's (backward).
//! \throw InvalidArgumentError if the sizes differ.
std::vector<FScore> fscores(const std::vector<double>& relative_thresholds, double diagonal,
                            const std::vector<double>& recall_shares, const std::vector<double>& precision_shares);

//! The statistics of \p distances, the distances of \p samples (same order).
//! \throw InvalidArgumentError if the sizes differ or there are no samples.
DistanceStats distance_stats(const SurfaceSamples& samples, const std::vector<double>& distances);

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

//! One direction: samples \p from with \p options (an unset target means
//! 10 x #faces of \p from) and returns the statistics of the exact distances
//! to \p to.
//! \throw InvalidArgumentError for invalid options or if the options give no sample.
//! \throw InvalidMeshError if \p from is invalid.
DistanceStats one_sided_distance(const Mesh& from, const ClosestPointIndex& to, const SamplingOptions& options = {});

//! Both directions, the symmetric Hausdorff distance and the diagonals.
//! \p a is the original, \p b the processed mesh; \p options apply to both
//! directions (an unset target means 10 x max(#faces A, #faces B)). With
//! \p b_vertex_distances, SurfaceDistance::b_vertex_distance and a_vertex_distance are filled too.
//! With \p certify, both one-sided Hausdorff distances are also certified
//! (hausdorff.h), reusing the indexes of the sampling.
//! \throw InvalidArgumentError for invalid options or if they give no sample.
//! \throw InvalidMeshError if a mesh is invalid (meshdiff::validate()).
//! The area-weighted statistics, the summary metrics and, when asked for in
//! \p summary, the histograms are filled too (sums over the samples). With
//! \p forward_samples (\p backward_samples), the samples of that direction and
//! their distances are kept there (as surface_distance_samples() keeps them).
//! A direction whose samples are not kept makes, queries and sums them a
//! chunk at a time and keeps only their distances (8 bytes per sample, for
//! the percentiles); the results are the same bit for bit.
SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options = {},
                                 bool b_vertex_distances = false,
                                 const std::optional<HausdorffOptions>& certify = std::nullopt,
                                 const SummaryOptions& summary = {}, SampledDirection* forward_samples = nullptr,
                                 SampledDirection* backward_samples = nullptr);

//! Result of surface_distance_samples(): the statistics, bit for bit those of
//! surface_distance() with the same arguments, and the samples behind them
//! (for histograms, per-kind statistics or plots of one's own).
struct SampledSurfaceDistance
{
    SurfaceDistance distance;   //!< as surface_distance() returns it (no b_vertex_distance)
    SampledDirection forward;   //!< samples on A, distances to B
    SampledDirection backward;  //!< samples on B, distances to A
};

//! surface_distance() keeping every sample and its distance (about 50 bytes
//! per sample and direction). Same arguments, conventions and exceptions.
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

}  // namespace meshdiff
