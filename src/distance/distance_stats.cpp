#include "meshdiff/distance/distance_stats.h"

#include "meshdiff/error.h"

#include "distance/distance_accumulators.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace meshdiff {

namespace {

std::size_t rank_of(std::size_t n, unsigned q)
{
    return std::clamp<std::size_t>((std::size_t(q) * n + 999) / 1000, 1, n);  // ceil(q n / 1000)
}

}  // namespace

double nearest_rank(std::vector<double>& v, unsigned q, unsigned below)
{
    const std::size_t n = v.size();
    const std::size_t rank = rank_of(n, q);
    const std::size_t start = below == 0 ? 0 : rank_of(n, below) - 1;
    std::nth_element(v.begin() + std::ptrdiff_t(start), v.begin() + std::ptrdiff_t(rank - 1), v.end());
    return v[rank - 1];
}

std::vector<double> nearest_ranks(const std::vector<double>& v, const std::vector<unsigned>& per_mille)
{
    return detail::nearest_ranks(v.data(), v.size(), per_mille);
}

std::vector<double> detail::nearest_ranks(const double* v, std::size_t n, const std::vector<unsigned>& per_mille)
{
    if (n == 0) throw InvalidArgumentError("nearest_ranks: no values");
    std::vector<double> out(per_mille.size());
    // A value >= 0 (not NaN) orders as its bits read as an unsigned integer:
    // the count of the values per group of their top 16 bits places each
    // rank in one group (20M distances of a comparison: the groups of the
    // ranks hold a few percent of them).
    constexpr int kShift = 48;
    constexpr std::size_t kGroups = std::size_t(1) << 16;
    const auto bits = [](double x) {
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        return b;
    };
    std::vector<std::uint64_t> count(kGroups, 0);
    bool plain = true, nan = false;
    const auto m = std::ptrdiff_t(n);
#pragma omp parallel
    {
        std::vector<std::uint64_t> local(kGroups, 0);
        bool ok = true, has_nan = false;
#pragma omp for schedule(static) nowait
        for (std::ptrdiff_t i = 0; i < m; ++i) {
            const double x = v[std::size_t(i)];
            ok &= x >= 0.0 && !std::signbit(x);  // false for NaN and -0
            has_nan |= std::isnan(x);
            ++local[bits(x) >> kShift];
        }
#pragma omp critical
        {
            for (std::size_t g = 0; g < kGroups; ++g) count[g] += local[g];
            plain = plain && ok;
            nan = nan || has_nan;
        }
    }
    if (nan) throw InvalidArgumentError("nearest_ranks: a value is NaN (it has no rank)");
    if (!plain) {
        std::vector<double> copy(v, v + n);
        for (std::size_t j = 0; j < per_mille.size(); ++j) out[j] = nearest_rank(copy, per_mille[j]);
        return out;
    }
    // Each rank's group and its rank within the group (0-based).
    std::vector<std::size_t> group(per_mille.size()), within(per_mille.size());
    std::vector<std::size_t> first(kGroups + 1, 0);  // the values below each group
    for (std::size_t g = 0; g < kGroups; ++g) first[g + 1] = first[g] + count[g];
    std::vector<std::size_t> wanted;  // the groups of the ranks, ascending, each once
    for (std::size_t j = 0; j < per_mille.size(); ++j) {
        const std::size_t r = rank_of(n, per_mille[j]) - 1;
        group[j] = std::size_t(std::upper_bound(first.begin(), first.end(), r) - first.begin()) - 1;
        within[j] = r - first[group[j]];
        wanted.push_back(group[j]);
    }
    std::sort(wanted.begin(), wanted.end());
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
    std::vector<std::vector<double>> values(wanted.size());
    for (std::size_t k = 0; k < wanted.size(); ++k) values[k].reserve(count[wanted[k]]);
    std::vector<int> slot(kGroups, -1);
    for (std::size_t k = 0; k < wanted.size(); ++k) slot[wanted[k]] = int(k);
#pragma omp parallel
    {
        std::vector<std::vector<double>> local(wanted.size());
#pragma omp for schedule(static) nowait
        for (std::ptrdiff_t i = 0; i < m; ++i) {
            const double x = v[std::size_t(i)];
            const int k = slot[bits(x) >> kShift];
            if (k >= 0) local[std::size_t(k)].push_back(x);
        }
#pragma omp critical
        for (std::size_t k = 0; k < wanted.size(); ++k)
            values[k].insert(values[k].end(), local[k].begin(), local[k].end());
    }
    // The values of a group in any order: the selection gives the same value.
    for (std::size_t j = 0; j < per_mille.size(); ++j) {
        std::vector<double>& g = values[std::size_t(slot[group[j]])];
        std::nth_element(g.begin(), g.begin() + std::ptrdiff_t(within[j]), g.end());
        out[j] = g[within[j]];
    }
    return out;
}

void validate(const SummaryOptions& options)
{
    if (options.fscore_thresholds.size() > kMaxFscoreThresholds)
        throw OptionError("summary.fscore_thresholds",
                          fmt::format("more than the limit of {} thresholds", kMaxFscoreThresholds));
    for (double t : options.fscore_thresholds)
        if (!(std::isfinite(t) && t > 0.0 && t <= kMaxFscoreThreshold))
            throw OptionError(
                "summary.fscore_thresholds",
                fmt::format("threshold {} is not in (0, {:g}] (relative to the diagonal)", t, kMaxFscoreThreshold));
    if (options.histogram_bins > kMaxHistogramBins)
        throw OptionError("summary.histogram_bins",
                          fmt::format("{} is outside 0..{} (0: none)", options.histogram_bins, kMaxHistogramBins));
}

std::optional<AreaWeightedStats> area_weighted_stats(const Mesh& from, const SurfaceSamples& samples,
                                                     const std::vector<double>& distances,
                                                     const std::vector<double>& thresholds, std::vector<double>* within)
{
    std::vector<double> shares;
    if (within) within->assign(thresholds.size(), 0.0);
    if (samples.size() != distances.size())
        throw InvalidArgumentError(
            fmt::format("area_weighted_stats: {} samples but {} distances", samples.size(), distances.size()));
    // Face samples per face (any order of the samples).
    std::vector<std::uint32_t> per_face(from.n_faces(), 0);
    std::size_t n_face = 0;
    for (std::size_t i = 0; i < samples.kind.size() && i < samples.element.size(); ++i)
        if (samples.kind[i] == SampleKind::OnFace && samples.element[i] < per_face.size()) {
            ++per_face[samples.element[i]];
            ++n_face;
        }
    if (n_face == 0) return std::nullopt;
    std::vector<double> area(from.n_faces(), 0.0);
    detail::CompensatedSum total, sampled;
    for (std::size_t f = 0; f < from.n_faces(); ++f) {
        area[f] = 0.5 * face_cross(from, f).norm();
        total.add(area[f]);
        if (per_face[f]) sampled.add(area[f]);
    }
    detail::AreaWeightedAccumulator acc(thresholds, [&](std::uint32_t f) { return area[f] / double(per_face[f]); });
    const std::size_t n = std::min(samples.kind.size(), samples.element.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (samples.kind[i] == SampleKind::OnFace && samples.element[i] < per_face.size())
            acc.add_face_sample(samples.element[i], distances[i]);
        else
            acc.add_other_sample();
    }
    return acc.finish(n_face, sampled, total, within ? *within : shares);
}

Histogram distance_histogram(const std::vector<double>& distances, std::size_t bins)
{
    return detail::distance_histogram(distances.data(), distances.size(), bins);
}

Histogram detail::distance_histogram(const double* distances, std::size_t n, std::size_t bins)
{
    if (bins == 0) throw InvalidArgumentError("distance_histogram: bins must be positive");
    if (n == 0) throw InvalidArgumentError("distance_histogram: no distances");
    // The largest and the counts in parallel (exact: a maximum and integer
    // counts do not depend on the order); with a NaN or a -0 (whose place
    // among equal values would matter), serially as before.
    const auto m = std::ptrdiff_t(n);
    double max = distances[0];
    bool nan = false;
#pragma omp parallel for schedule(static) reduction(max : max) reduction(|| : nan)
    for (std::ptrdiff_t i = 0; i < m; ++i) {
        const double d = distances[std::size_t(i)];
        nan = nan || std::isnan(d) || (d == 0.0 && std::signbit(d));
        max = std::max(max, d);
    }
    if (nan) max = *std::max_element(distances, distances + n);
    Histogram h;
    h.edges.resize(bins + 1);
    for (std::size_t i = 0; i <= bins; ++i) h.edges[i] = max * double(i) / double(bins);
    h.counts.assign(bins, 0);
    const double width = max / double(bins);
    const auto bin = [&](double d) {
        std::size_t k = 0;
        if (width > 0.0) k = std::min(bins - 1, std::size_t(d / width));
        return k;
    };
    if (nan) {
        for (std::size_t i = 0; i < n; ++i) ++h.counts[bin(distances[i])];
        return h;
    }
#pragma omp parallel
    {
        std::vector<std::size_t> local(bins, 0);
#pragma omp for schedule(static) nowait
        for (std::ptrdiff_t i = 0; i < m; ++i) ++local[bin(distances[std::size_t(i)])];
#pragma omp critical
        for (std::size_t k = 0; k < bins; ++k) h.counts[k] += local[k];
    }
    return h;
}

std::vector<FScore> fscores(const std::vector<double>& relative_thresholds, double diagonal,
                            const std::vector<double>& recall_shares, const std::vector<double>& precision_shares)
{
    if (recall_shares.size() != relative_thresholds.size() || precision_shares.size() != relative_thresholds.size())
        throw InvalidArgumentError(fmt::format("fscores: {} thresholds but {} and {} shares",
                                               relative_thresholds.size(), recall_shares.size(),
                                               precision_shares.size()));
    std::vector<FScore> r;
    for (std::size_t k = 0; k < relative_thresholds.size(); ++k) {
        FScore s;
        s.threshold = relative_thresholds[k];
        s.threshold_absolute = relative_thresholds[k] * diagonal;
        s.precision = precision_shares[k];
        s.recall = recall_shares[k];
        s.fscore = s.precision + s.recall > 0.0 ? 2.0 * s.precision * s.recall / (s.precision + s.recall) : 0.0;
        r.push_back(s);
    }
    return r;
}

DistanceStats relative_to(const DistanceStats& stats, double diagonal)
{
    if (!(std::isfinite(diagonal) && diagonal > 0.0))
        throw InvalidArgumentError(fmt::format("relative_to: diagonal must be finite and positive, got {}", diagonal));
    DistanceStats r = stats;
    for (const StatField& f : kStatFields) r.*f.field /= diagonal;
    return r;
}

DistanceStats distance_stats(const SurfaceSamples& samples, const std::vector<double>& distances)
{
    if (samples.size() != distances.size())
        throw InvalidArgumentError(
            fmt::format("distance_stats: {} samples but {} distances", samples.size(), distances.size()));
    if (distances.empty()) throw InvalidArgumentError("distance_stats: no samples");
    detail::DistanceAccumulator acc;
    for (std::size_t i = 0; i < distances.size(); ++i)  // hand-made samples may lack kinds and elements
        acc.add(distances[i], samples.points[i], i < samples.kind.size() ? samples.kind[i] : SampleKind::OnVertex,
                i < samples.element.size() ? samples.element[i] : 0);
    std::vector<double> sorted = distances;
    DistanceStats s = acc.finish(sorted.data(), sorted.size());
    s.n_vertex = samples.n_vertex;
    s.n_edge = samples.n_edge;
    s.n_face = samples.n_face;
    return s;
}

SignedDistanceStats signed_distance_stats(const std::vector<double>& s)
{
    if (s.empty()) throw InvalidArgumentError("signed_distance_stats: no samples");
    detail::SignedAccumulator acc;
    for (double x : s) acc.add(x);
    return acc.finish(s.size());
}

}  // namespace meshdiff
