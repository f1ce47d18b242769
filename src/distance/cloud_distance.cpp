#include "meshdiff/distance/cloud_distance.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/closest_point.h"

#include "core/compensated_sum.h"
#include "distance/two_directions.h"

#include <fmt/format.h>
#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

namespace meshdiff {

DistanceKind distance_kind(bool from_cloud, bool to_cloud)
{
    if (from_cloud) return to_cloud ? DistanceKind::PointToPoint : DistanceKind::PointToSurface;
    return to_cloud ? DistanceKind::SurfaceToPoint : DistanceKind::SurfaceToSurface;
}

namespace {

// nanoflann's dataset adaptor over a vector of points.
struct PointsAdaptor
{
    std::vector<Vec3> points;
    std::size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t dim) const { return points[i][int(dim)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const
    {
        return false;
    }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointsAdaptor>, PointsAdaptor,
                                                   3, std::uint32_t>;

}  // namespace

// A cloud must have points, all finite (read_mesh_or_cloud() guarantees it
// for files; arrays and code may not).
void detail::check_cloud(const Mesh& cloud, const std::string& what)
{
    if (cloud.points.empty()) throw InvalidMeshError(fmt::format("{}: the point cloud has no points", what));
    for (std::size_t i = 0; i < cloud.points.size(); ++i)
        if (!cloud.points[i].allFinite())
            throw InvalidMeshError(fmt::format("{}: point {} has a non-finite coordinate", what, i));
}

struct PointCloudIndex::Impl
{
    PointsAdaptor data;
    KdTree tree;
    explicit Impl(const std::vector<Vec3>& points)
        : data{points}, tree(3, data, nanoflann::KDTreeSingleIndexAdaptorParams(10))
    {}
};

PointCloudIndex::PointCloudIndex(const std::vector<Vec3>& points)
{
    detail::check_cloud(Mesh{points, {}}, "PointCloudIndex");
    if (points.size() > std::size_t(UINT32_MAX))
        throw InvalidMeshError(fmt::format("PointCloudIndex: {} points, more than 2^32 - 1", points.size()));
    impl_ = std::make_unique<Impl>(points);
}

PointCloudIndex::~PointCloudIndex() = default;
PointCloudIndex::PointCloudIndex(PointCloudIndex&&) noexcept = default;
PointCloudIndex& PointCloudIndex::operator=(PointCloudIndex&&) noexcept = default;

std::size_t PointCloudIndex::size() const
{
    return impl_->data.points.size();
}

PointCloudIndex::Nearest PointCloudIndex::nearest(const Vec3& q) const
{
    std::uint32_t index = 0;
    double d2 = 0.0;
    impl_->tree.knnSearch(q.data(), 1, &index, &d2);
    // The distance from the point found, as a brute-force search computes it.
    return {index, (q - impl_->data.points[index]).norm()};
}

std::vector<double> PointCloudIndex::distances(const std::vector<Vec3>& queries) const
{
    std::vector<double> out(queries.size());
    const auto n = std::int64_t(queries.size());
#pragma omp parallel for schedule(dynamic, 1024)
    for (std::int64_t i = 0; i < n; ++i) out[std::size_t(i)] = nearest(queries[std::size_t(i)]).distance;
    return out;
}

SurfaceSamples cloud_samples(const Mesh& cloud)
{
    SurfaceSamples s;
    s.points = cloud.points;
    s.kind.assign(cloud.points.size(), SampleKind::OnPoint);
    s.element.resize(cloud.points.size());
    for (std::size_t i = 0; i < s.element.size(); ++i) s.element[i] = std::uint32_t(i);
    s.target = cloud.points.size();
    return s;
}

// The "area-weighted" statistics of a cloud direction: every point weight 1
// (see the file comment of cloud_distance.h), and the shares below the
// absolute \p thresholds.
AreaWeightedStats detail::point_weighted_stats(const std::vector<double>& distances,
                                               const std::vector<double>& thresholds, std::vector<double>& within)
{
    detail::CompensatedSum sum, sum2;
    std::vector<std::size_t> below(thresholds.size(), 0);
    for (double d : distances) {
        sum.add(d);
        sum2.add(d * d);
        for (std::size_t k = 0; k < thresholds.size(); ++k) below[k] += d < thresholds[k];
    }
    const auto n = double(distances.size());
    AreaWeightedStats s;
    s.mean = sum.value() / n;
    s.mean_square = sum2.value() / n;
    s.rms = std::sqrt(s.mean_square);
    s.n_face = 0;
    s.area = 0.0;
    s.area_fraction = 1.0;
    within.resize(thresholds.size());
    for (std::size_t k = 0; k < thresholds.size(); ++k) within[k] = double(below[k]) / n;
    return s;
}

SampledDirection detail::cloud_direction(const Mesh& from, bool from_cloud, const ClosestPointIndex* index,
                                         const PointCloudIndex* cloud, const SamplingOptions& options)
{
    SampledDirection d;
    if (from_cloud) {
        d.samples = cloud_samples(from);
    } else {
        d.samples = sample_surface(from, options);
        if (d.samples.size() == 0)
            throw InvalidArgumentError("SamplingOptions: the enabled sample kinds give no sample on this mesh");
    }
    d.distances = cloud ? cloud->distances(d.samples.points) : index->distances(d.samples.points);
    return d;
}

CertifiedHausdorff detail::exact_over_points(const Mesh& to, const ClosestPointIndex* index,
                                             const PointCloudIndex* cloud, const DistanceStats& s, std::size_t n_points)
{
    CertifiedHausdorff h;
    h.lower = h.upper = s.max;
    h.tolerance = 0.0;
    h.certified = true;
    h.location.point = s.max_point;
    h.location.face = s.max_element;
    if (cloud) {
        const auto n = cloud->nearest(s.max_point);
        h.location.closest_point = to.points[n.index];
        h.location.closest_face = n.index;
    } else {
        const ClosestPoint cp = index->closest_point(s.max_point);
        h.location.closest_point = cp.point;
        h.location.closest_face = cp.face;
    }
    h.point_evaluations = n_points;
    return h;
}

SurfaceDistance detail::deprecated_result(SurfaceDistance r, SampledDirection* forward_samples,
                                          SampledDirection* backward_samples)
{
    r.a_vertex_distance = std::exchange(r.original_vertex_distance, {});
    r.b_vertex_distance = std::exchange(r.processed_vertex_distance, {});
    r.a_vertex_signed_distance = std::exchange(r.original_vertex_signed_distance, {});
    r.b_vertex_signed_distance = std::exchange(r.processed_vertex_signed_distance, {});
    if (forward_samples) *forward_samples = std::exchange(r.forward_samples, {});
    if (backward_samples) *backward_samples = std::exchange(r.backward_samples, {});
    return r;
}

SurfaceDistance cloud_surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options)
{
    return detail::two_directions(a, b, options, options.keep_samples, options.keep_samples, true);
}

SurfaceDistance cloud_surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options,
                                       bool vertex_distances, const std::optional<HausdorffOptions>& certify,
                                       const SummaryOptions& summary, SampledDirection* forward_samples,
                                       SampledDirection* backward_samples)
{
    DistanceOptions o;
    o.sampling = options;
    o.hausdorff = certify;
    o.summary = summary;
    o.vertex_distances = vertex_distances;
    return detail::deprecated_result(
        detail::two_directions(a, b, o, forward_samples != nullptr, backward_samples != nullptr, true), forward_samples,
        backward_samples);
}

}  // namespace meshdiff
