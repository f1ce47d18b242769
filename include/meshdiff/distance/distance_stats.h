//! \file distance_stats.h
//! \brief The statistics of one direction of a surface distance, over its
//! samples' distances: min, max, mean, RMS, standard deviation and nearest-rank
//! percentiles (kStatFields lists them in report order), the area-weighted
//! statistics of the face samples, the signed statistics, the histogram, and
//! the summary metrics made from both directions (F-score, PSNR). One home for
//! every per-direction statistic: the surface and the point-cloud distances
//! compute them through the same accumulators (src/distance/distance_accumulators.h),
//! whether the samples are kept or folded a chunk at a time.
//!
//! Statistics over the n samples of a direction, each with weight 1 (as in
//! Metro; face samples are area-uniform, but vertex and edge samples are not):
//! mean = sum d / n; rms = sqrt(sum d^2 / n); stddev = population standard
//! deviation sqrt(sum (d - mean)^2 / n). Percentiles by nearest rank: p_q is the
//! ceil(q/100 x n)-th smallest distance (1-based), so p50, p95, p99 and p99.9
//! (p999) are sample distances. All sums run sequentially in sample order, so the results are
//! bit-identical for any number of OpenMP threads.
#pragma once

#include "meshdiff/core/mesh.h"
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
    double p50 = 0.0;     //!< nearest-rank percentiles (see the file comment; kPercentiles)
    double p95 = 0.0;
    double p99 = 0.0;
    double p999 = 0.0;         //!< the 99.9th percentile
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

//! One statistic of DistanceStats as the reports show it: its JSON key (and
//! Python dict key, and CSV column suffix), its label in the text report, and
//! its field. The JSON, text and CSV reports, the Python dict and relative_to()
//! walk kStatFields, so a statistic added to DistanceStats and to this list
//! (and, if it is a percentile, to kPercentiles) appears in all of them.
struct StatField
{
    const char* key;
    const char* label;
    double DistanceStats::*field;
};

//! The per-sample statistics of a direction, in report order.
inline constexpr StatField kStatFields[] = {{"min", "min", &DistanceStats::min},    {"max", "max", &DistanceStats::max},
                                            {"mean", "mean", &DistanceStats::mean}, {"rms", "RMS", &DistanceStats::rms},
                                            {"std", "std", &DistanceStats::stddev}, {"p50", "p50", &DistanceStats::p50},
                                            {"p95", "p95", &DistanceStats::p95},    {"p99", "p99", &DistanceStats::p99},
                                            {"p999", "p99.9", &DistanceStats::p999}};

//! A nearest-rank percentile of DistanceStats: q per mille (q = 500 is the
//! median) and its field. Ascending in q: each is searched above the one
//! before it.
struct PercentileField
{
    unsigned per_mille;
    double DistanceStats::*field;
};

//! The percentiles of a direction, ascending.
inline constexpr PercentileField kPercentiles[] = {
    {500, &DistanceStats::p50}, {950, &DistanceStats::p95}, {990, &DistanceStats::p99}, {999, &DistanceStats::p999}};

//! The nearest-rank percentile of \p q per mille of \p v: its
//! ceil(q n / 1000)-th smallest element (1-based). \p v is partially sorted in
//! place; if it already is partitioned at the rank of \p below per mille (an
//! earlier call with q = below), only the part above that rank is searched.
//! \p v must not be empty.
double nearest_rank(std::vector<double>& v, unsigned q, unsigned below = 0);

//! The nearest-rank percentiles of \p per_mille of \p v (the same values as
//! nearest_rank()), \p v unchanged. Values that are neither negative nor NaN
//! (distances) are counted by the top 16 bits of their binary form, in
//! parallel, and only the few values in the groups of the ranks are then
//! selected from; otherwise a copy of \p v is partially sorted. Throws
//! InvalidArgumentError when \p v is empty or holds a NaN.
std::vector<double> nearest_ranks(const std::vector<double>& v, const std::vector<unsigned>& per_mille);

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

//! The F-scores at \p relative_thresholds (x \p diagonal) from the area shares
//! below them: \p recall_shares of the original's face samples (forward),
//! \p precision_shares of the processed mesh's (backward).
//! \throw InvalidArgumentError if the sizes differ.
std::vector<FScore> fscores(const std::vector<double>& relative_thresholds, double diagonal,
                            const std::vector<double>& recall_shares, const std::vector<double>& precision_shares);

//! The statistics of \p distances, the distances of \p samples (same order).
//! \throw InvalidArgumentError if the sizes differ or there are no samples.
DistanceStats distance_stats(const SurfaceSamples& samples, const std::vector<double>& distances);

}  // namespace meshdiff
