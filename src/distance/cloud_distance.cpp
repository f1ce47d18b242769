#include "meshdiff/distance/cloud_distance.h"

#include "meshdiff/error.h"
#include "meshdiff/geometry/closest_point.h"

#include "core/compensated_sum.h"
#include "distance/surface_distance_chunks.h"

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

// A cloud must have points, all finite (read_mesh_or_cloud() guarantees it
// for files; arrays and code may not).
void check_cloud(const Mesh& cloud, const std::string& what)
{
    if (cloud.points.empty()) throw InvalidMeshError(fmt::format("{}: the point cloud has no points", what));
    for (std::size_t i = 0; i < cloud.points.size(); ++i)
        if (!cloud.points[i].allFinite())
            throw InvalidMeshError(fmt::format("{}: point {} has a non-finite coordinate", what, i));
}

}  // namespace

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
    check_cloud(Mesh{points, {}}, "PointCloudIndex");
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

namespace {

// The "area-weighted" statistics of a cloud direction: every point weight 1
// (see the file comment of cloud_distance.h), and the shares below the
// absolute \p thresholds.
AreaWeightedStats point_weighted_stats(const std::vector<double>& distances, const std::vector<double>& thresholds,
                                       std::vector<double>& within)
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

}  // namespace

namespace {

// cloud_surface_distance() when \p a or \p b is a cloud: both directions,
// keeping the samples of the forward (backward) direction in
// r.forward_samples (backward_samples) with \p keep_forward (\p keep_backward).
SurfaceDistance both_with_clouds(const Mesh& a, const Mesh& b, const DistanceOptions& o, bool keep_forward,
                                 bool keep_backward)
{
    const SamplingOptions& options = o.sampling;
    const std::optional<HausdorffOptions>& certify = o.hausdorff;
    const SummaryOptions& summary = o.summary;
    const bool cloud_a = a.faces.empty(), cloud_b = b.faces.empty();
    validate(options);
    validate(summary);
    if (certify) validate(*certify);
    if (cloud_a) {
        check_cloud(a, "surface_distance: A");
    } else {
        validate(a, "surface_distance: mesh A");
    }
    if (cloud_b) {
        check_cloud(b, "surface_distance: B");
    } else {
        validate(b, "surface_distance: mesh B");
    }
    SamplingOptions opt = options;
    // The default budget counts each point of a cloud as a face (Metro: 10 x
    // max(#faces A, #faces B)), so that a mesh is sampled at least as densely
    // as the cloud it is measured against.
    if (!opt.samples && !opt.density)
        opt.samples = 10 * std::max(cloud_a ? a.n_vertices() : a.n_faces(), cloud_b ? b.n_vertices() : b.n_faces());

    // A cloud of one point (or of equal points) has no diagonal: an input
    // error like a mesh without extent.
    const double diagonal = detail::reference_diagonal(a, a.faces.empty() ? "points" : "vertices");
    std::vector<double> thresholds;  // absolute
    for (double t : summary.fscore_thresholds) thresholds.push_back(t * diagonal);
    std::vector<double> recall, precision;

    auto direction = [&](const Mesh& from, const Mesh& to, DistanceStats& stats, std::vector<double>& within,
                         SampledDirection* keep, std::vector<double>* vertex_distance,
                         std::optional<CertifiedHausdorff>& certified) {
        const bool from_cloud = from.faces.empty(), to_cloud = to.faces.empty();
        SampledDirection d;
        if (from_cloud) {
            d.samples = cloud_samples(from);
        } else {
            d.samples = sample_surface(from, opt);
            if (d.samples.size() == 0)
                throw InvalidArgumentError("SamplingOptions: the enabled sample kinds give no sample on this mesh");
        }
        std::optional<ClosestPointIndex> mesh_index;
        std::optional<PointCloudIndex> cloud_index;
        if (to_cloud) {
            cloud_index.emplace(to.points);
            d.distances = cloud_index->distances(d.samples.points);
        } else {
            mesh_index.emplace(to);
            d.distances = mesh_index->distances(d.samples.points);
        }
        stats = distance_stats(d.samples, d.distances);
        // A cloud has no inside; a cloud's points against a mesh are left
        // unsigned too (the sign needs the closest feature, not computed here).
        stats.signed_unavailable =
            to_cloud ? "the other input is a point cloud: it has no inside"
                     : "the samples are the points of a cloud: signed distances are computed for mesh samples only";
        if (from_cloud) {
            stats.n_point = d.samples.size();
            stats.area_weighted = point_weighted_stats(d.distances, thresholds, within);
        } else {
            stats.area_weighted = area_weighted_stats(from, d.samples, d.distances, thresholds, &within);
        }
        if (summary.histogram_bins > 0) stats.histogram = distance_histogram(d.distances, summary.histogram_bins);
        if (vertex_distance) {
            if (from_cloud) {
                *vertex_distance = d.distances;  // the points, in order
            } else if (to_cloud) {
                *vertex_distance = cloud_index->distances(from.points);
            } else {
                *vertex_distance = meshdiff::vertex_distances(from, *mesh_index);
            }
        }
        if (certify && from_cloud) {  // exact over the points
            CertifiedHausdorff h;
            h.lower = h.upper = stats.max;
            h.tolerance = 0.0;
            h.certified = true;
            h.location.point = stats.max_point;
            h.location.face = stats.max_element;
            if (to_cloud) {
                const auto n = cloud_index->nearest(stats.max_point);
                h.location.closest_point = to.points[n.index];
                h.location.closest_face = n.index;
            } else {
                const ClosestPoint cp = mesh_index->closest_point(stats.max_point);
                h.location.closest_point = cp.point;
                h.location.closest_face = cp.face;
            }
            h.point_evaluations = d.samples.size();
            certified = h;
        }
        if (keep) *keep = std::move(d);
    };
    SurfaceDistance r;
    direction(a, b, r.forward, recall, keep_forward ? &r.forward_samples : nullptr,
              o.vertex_distances ? &r.a_vertex_distance : nullptr, r.forward_hausdorff);
    direction(b, a, r.backward, precision, keep_backward ? &r.backward_samples : nullptr,
              o.vertex_distances ? &r.b_vertex_distance : nullptr, r.backward_hausdorff);
    r.hausdorff = std::max(r.forward.max, r.backward.max);
    r.diagonal = diagonal;
    r.metro_diagonal = metro_diagonal(a, b);
    r.summary = summary_metrics(r, &r.summary_unavailable);
    if (r.summary) r.fscore = fscores(summary.fscore_thresholds, diagonal, recall, precision);
    r.forward_kind = distance_kind(cloud_a, cloud_b);
    r.backward_kind = distance_kind(cloud_b, cloud_a);
    return r;
}

}  // namespace

SurfaceDistance cloud_surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options,
                                       bool vertex_distances, const std::optional<HausdorffOptions>& certify,
                                       const SummaryOptions& summary, SampledDirection* forward_samples,
                                       SampledDirection* backward_samples)
{
    if (!a.faces.empty() && !b.faces.empty())
        return surface_distance(a, b, options, vertex_distances, certify, summary, forward_samples, backward_samples);
    const DistanceOptions o{options, certify, summary, vertex_distances, false};
    SurfaceDistance r = both_with_clouds(a, b, o, forward_samples != nullptr, backward_samples != nullptr);
    if (forward_samples) *forward_samples = std::exchange(r.forward_samples, {});
    if (backward_samples) *backward_samples = std::exchange(r.backward_samples, {});
    return r;
}

SurfaceDistance cloud_surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options)
{
    if (!a.faces.empty() && !b.faces.empty()) return surface_distance(a, b, options);
    return both_with_clouds(a, b, options, options.keep_samples, options.keep_samples);
}

}  // namespace meshdiff
