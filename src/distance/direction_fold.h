//! \file direction_fold.h (detail)
//! \brief The statistics of one direction of the surface distance folded over
//! its samples a range at a time (surface_distance.cpp's chunked directions,
//! its only user).
#pragma once

#include "meshdiff/distance/distance_stats.h"
#include "meshdiff/geometry/sampling.h"

#include "core/compensated_sum.h"
#include "distance/distance_accumulators.h"
#include "geometry/sample_plan.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace meshdiff::detail {

// The statistics of one direction folded over its samples a range at a time,
// in sample order, by the accumulators of distance_stats(),
// signed_distance_stats() and area_weighted_stats() (distance_accumulators.h).
class DirectionFold
{
public:
    DirectionFold(const Mesh& from, const SamplePlan& plan, const std::vector<double>& thresholds, bool is_signed)
        : from_(from),
          plan_(plan),
          thresholds_(thresholds),
          signed_(is_signed),
          area_(thresholds, [this](std::uint32_t f) { return face_area(f) / double(face_samples(f)); })
    {}

    // Samples [begin, begin + n) (points p, kinds, elements, distances d and
    // signs, those without a sign when the direction has none).
    void add(std::size_t n, const Vec3* p, const SampleKind* kind, const std::uint32_t* element, const double* d,
             const std::int8_t* sign)
    {
        for (std::size_t i = 0; i < n; ++i) {
            const double x = d[i];
            stats_.add(x, p[i], kind[i], element[i]);
            if (signed_) signed_stats_.add(sign[i] == 0 ? 0.0 : double(sign[i]) * x);
            if (kind[i] == SampleKind::OnFace)
                area_.add_face_sample(element[i], x);
            else
                area_.add_other_sample();
        }
    }

    // The statistics of the n samples whose distances are \p distances (in
    // sample order), the histogram in \p bins bins
    // (none for 0), the area shares below the thresholds in \p within.
    DistanceStats finish(const double* distances, std::size_t n, std::size_t bins, std::vector<double>& within)
    {
        Histogram histogram;
        if (bins > 0) histogram = distance_histogram(distances, n, bins);
        DistanceStats s = stats_.finish(distances, n);
        s.n_vertex = plan_.counts.n_vertex;
        s.n_edge = plan_.counts.n_edge;
        s.n_face = plan_.counts.n_face;
        if (signed_) s.signed_distance = signed_stats_.finish(n);
        s.area_weighted = area_weighted(within);
        s.histogram = std::move(histogram);
        return s;
    }

private:
    std::size_t face_samples(std::size_t f) const { return plan_.face_offset[f + 1] - plan_.face_offset[f]; }
    double face_area(std::size_t f) const { return 0.5 * face_cross(from_, f).norm(); }

    std::optional<AreaWeightedStats> area_weighted(std::vector<double>& within)
    {
        if (plan_.counts.n_face == 0) {
            within.assign(thresholds_.size(), 0.0);
            return std::nullopt;
        }
        CompensatedSum total, sampled;
        for (std::size_t f = 0; f < from_.n_faces(); ++f) {
            const double area = face_area(f);
            total.add(area);
            if (face_samples(f)) sampled.add(area);
        }
        return area_.finish(plan_.counts.n_face, sampled, total, within);
    }

    const Mesh& from_;
    const SamplePlan& plan_;
    const std::vector<double>& thresholds_;
    bool signed_;
    DistanceAccumulator stats_;
    SignedAccumulator signed_stats_;
    AreaWeightedAccumulator area_;
};

}  // namespace meshdiff::detail
