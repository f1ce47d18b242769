//! \file distance_accumulators.h (private)
//! \brief The per-direction statistics of distance_stats.h folded over the
//! samples one at a time, in sample order: the one implementation behind
//! distance_stats(), signed_distance_stats() and area_weighted_stats() (all
//! samples at once) and behind the surface distance's chunked directions
//! (samples made, queried and folded a chunk at a time). Every sum is
//! sequential (a compensated sum in sample order), so the results are the same
//! to the last bit whichever way the samples arrive.
#pragma once

#include "meshdiff/distance/distance_stats.h"

#include "core/compensated_sum.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace meshdiff::detail {

//! nearest_ranks() and distance_histogram() (distance_stats.h) of the \p n
//! values at \p v (the surface distance's chunks keep theirs in an array that
//! is not zeroed before the queries write it).
std::vector<double> nearest_ranks(const double* v, std::size_t n, const std::vector<unsigned>& per_mille);
Histogram distance_histogram(const double* distances, std::size_t n, std::size_t bins);

//! min, max (with where it lies), mean, RMS, standard deviation and the
//! percentiles of kPercentiles.
class DistanceAccumulator
{
public:
    //! The next sample: its distance \p d, point \p p, kind and source element.
    void add(double d, const Vec3& p, SampleKind kind, std::uint32_t element)
    {
        if (n_ == 0) {
            s_.min = s_.max = d;
            locate_max(p, kind, element);
        }
        s_.min = std::min(s_.min, d);
        if (d > s_.max) {
            s_.max = d;
            locate_max(p, kind, element);
        }
        sum_.add(d);
        sum2_.add(d * d);
        ++n_;
    }

    //! The statistics of the samples added, whose distances are \p distances
    //! (the same, in sample order). The sample counts and the other parts are
    //! left to the caller.
    DistanceStats finish(const double* distances, std::size_t count) const
    {
        DistanceStats s = s_;
        const auto n = double(count);
        s.mean = sum_.value() / n;
        s.rms = std::sqrt(sum2_.value() / n);
        CompensatedSum dev;
        for (std::size_t i = 0; i < count; ++i) dev.add((distances[i] - s.mean) * (distances[i] - s.mean));
        s.stddev = std::sqrt(dev.value() / n);
        std::vector<unsigned> per_mille;
        for (const PercentileField& q : kPercentiles) per_mille.push_back(q.per_mille);
        const std::vector<double> p = nearest_ranks(distances, count, per_mille);
        for (std::size_t j = 0; j < per_mille.size(); ++j) s.*kPercentiles[j].field = p[j];
        return s;
    }

private:
    void locate_max(const Vec3& p, SampleKind kind, std::uint32_t element)
    {
        s_.max_point = p;
        s_.max_kind = kind;
        s_.max_element = element;
    }

    DistanceStats s_;
    CompensatedSum sum_, sum2_;
    std::size_t n_ = 0;
};

//! The signed statistics: min, max, mean and RMS of the signed distances.
class SignedAccumulator
{
public:
    //! The next sample's signed distance.
    void add(double x)
    {
        if (n_ == 0) r_.min = r_.max = x;
        r_.min = std::min(r_.min, x);
        r_.max = std::max(r_.max, x);
        sum_.add(x);
        sum2_.add(x * x);
        ++n_;
    }
    //! The statistics of the \p n samples added (n > 0).
    SignedDistanceStats finish(std::size_t n) const
    {
        SignedDistanceStats r = r_;
        r.mean = sum_.value() / double(n);
        r.rms = std::sqrt(sum2_.value() / double(n));
        return r;
    }

private:
    SignedDistanceStats r_;
    CompensatedSum sum_, sum2_;
    std::size_t n_ = 0;
};

//! The area-weighted statistics of the face samples (AreaWeightedStats) and
//! the area shares below the F-score thresholds. A run of consecutive samples
//! on one face is summed plainly, then added with the face's weight, its area
//! per face sample; any other sample ends the run.
class AreaWeightedAccumulator
{
public:
    //! \p thresholds: absolute; \p weight(f): the area of face f divided by
    //! its number of face samples (called once a run).
    AreaWeightedAccumulator(const std::vector<double>& thresholds, std::function<double(std::uint32_t)> weight)
        : thresholds_(thresholds), weight_(std::move(weight)), below_(thresholds.size()), run_below_(thresholds.size())
    {}

    //! The next sample, a face sample on face \p f at distance \p d.
    void add_face_sample(std::uint32_t f, double d)
    {
        if (!in_run_ || f != run_face_) {
            end_run();
            in_run_ = true;
            run_face_ = f;
        }
        s1_ += d;
        s2_ += d * d;
        for (std::size_t k = 0; k < thresholds_.size(); ++k) run_below_[k] += d < thresholds_[k];
    }
    //! The next sample is not a face sample: the run ends.
    void add_other_sample() { end_run(); }

    //! The statistics of the \p n_face face samples added; \p sampled_area:
    //! the area of the faces holding a face sample, \p total_area that of all
    //! faces (each a sum over the faces in index order). The area shares below
    //! the thresholds go to \p within. std::nullopt if the sampled area is 0.
    std::optional<AreaWeightedStats> finish(std::size_t n_face, const CompensatedSum& sampled_area,
                                            const CompensatedSum& total_area, std::vector<double>& within)
    {
        end_run();
        within.assign(thresholds_.size(), 0.0);
        AreaWeightedStats s;
        s.n_face = n_face;
        s.area = sampled_area.value();
        if (!(s.area > 0.0)) return std::nullopt;  // only zero-area faces were sampled
        s.area_fraction = s.area / total_area.value();
        s.mean = sum_.value() / s.area;
        s.mean_square = sum2_.value() / s.area;
        s.rms = std::sqrt(s.mean_square);
        for (std::size_t k = 0; k < below_.size(); ++k) within[k] = std::min(1.0, below_[k].value() / s.area);
        return s;
    }

private:
    void end_run()
    {
        if (!in_run_) return;
        const double w = weight_(run_face_);
        sum_.add(w * s1_);
        sum2_.add(w * s2_);
        for (std::size_t k = 0; k < thresholds_.size(); ++k)
            if (run_below_[k]) below_[k].add(w * double(run_below_[k]));
        in_run_ = false;
        s1_ = s2_ = 0.0;
        std::fill(run_below_.begin(), run_below_.end(), 0);
    }

    const std::vector<double>& thresholds_;
    std::function<double(std::uint32_t)> weight_;
    CompensatedSum sum_, sum2_;
    std::vector<CompensatedSum> below_;
    bool in_run_ = false;
    std::uint32_t run_face_ = 0;
    double s1_ = 0.0, s2_ = 0.0;
    std::vector<std::size_t> run_below_;
};

}  // namespace meshdiff::detail
