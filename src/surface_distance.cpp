#include "meshdiff/surface_distance.h"

#include "meshdiff/error.h"

#include "detail/hausdorff.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace meshdiff {

namespace {

// Neumaier's compensated sum, sequential in index order.
struct Sum
{
    double s = 0.0, c = 0.0;
    void add(double x)
    {
        const double t = s + x;
        c += std::abs(s) >= std::abs(x) ? (s - t) + x : (x - t) + s;
        s = t;
    }
    double value() const { return s + c; }
};

std::size_t rank_of(std::size_t n, unsigned q)
{
    return std::clamp<std::size_t>((std::size_t(q) * n + 99) / 100, 1, n);  // ceil(q n / 100)
}

// The nearest-rank q-th percentile of v: its ceil(q n / 100)-th smallest
// element. v is partially sorted in place; if it already is partitioned at the
// rank of percentile `below` (an earlier call with q = below), only the part
// above that rank is searched.
double nearest_rank(std::vector<double>& v, unsigned q, unsigned below)
{
    const std::size_t n = v.size();
    const std::size_t rank = rank_of(n, q);
    const std::size_t start = below == 0 ? 0 : rank_of(n, below) - 1;
    std::nth_element(v.begin() + std::ptrdiff_t(start), v.begin() + std::ptrdiff_t(rank - 1), v.end());
    return v[rank - 1];
}

}  // namespace

DistanceStats relative_to(const DistanceStats& stats, double diagonal)
{
    if (!(std::isfinite(diagonal) && diagonal > 0.0))
        throw InvalidArgumentError(fmt::format("relative_to: diagonal must be finite and positive, got {}", diagonal));
    DistanceStats r = stats;
    for (double* x : {&r.min, &r.max, &r.mean, &r.rms, &r.stddev, &r.p50, &r.p95, &r.p99}) *x /= diagonal;
    return r;
}

DistanceStats distance_stats(const SurfaceSamples& samples, const std::vector<double>& distances)
{
    if (samples.size() != distances.size())
        throw InvalidArgumentError(
            fmt::format("distance_stats: {} samples but {} distances", samples.size(), distances.size()));
    if (distances.empty()) throw InvalidArgumentError("distance_stats: no samples");
    DistanceStats s;
    s.n_vertex = samples.n_vertex;
    s.n_edge = samples.n_edge;
    s.n_face = samples.n_face;
    const auto n = double(distances.size());
    Sum sum, sum2;
    s.min = distances[0];
    s.max = distances[0];
    std::size_t at_max = 0;
    for (std::size_t i = 0; i < distances.size(); ++i) {
        const double d = distances[i];
        s.min = std::min(s.min, d);
        if (d > s.max) {
            s.max = d;
            at_max = i;
        }
        sum.add(d);
        sum2.add(d * d);
    }
    s.max_point = samples.points[at_max];
    if (at_max < samples.kind.size()) s.max_kind = samples.kind[at_max];  // hand-made samples may lack them
    if (at_max < samples.element.size()) s.max_element = samples.element[at_max];
    s.mean = sum.value() / n;
    s.rms = std::sqrt(sum2.value() / n);
    Sum dev;
    for (double d : distances) dev.add((d - s.mean) * (d - s.mean));
    s.stddev = std::sqrt(dev.value() / n);
    std::vector<double> sorted = distances;
    s.p50 = nearest_rank(sorted, 50, 0);
    s.p95 = nearest_rank(sorted, 95, 50);
    s.p99 = nearest_rank(sorted, 99, 95);
    return s;
}

namespace {

// The samples of \p from and their distances to \p to.
// With \p vertex_closest (the closest points of all vertices of \p from), the
// vertex samples take their distances from it instead of new queries (the
// same values: the queries are exact).
SampledDirection sampled_direction(const Mesh& from, const ClosestPointIndex& to, const SamplingOptions& options,
                                   const std::vector<ClosestPoint>* vertex_closest = nullptr)
{
    SampledDirection d;
    d.samples = sample_surface(from, options);
    if (d.samples.size() == 0)
        throw InvalidArgumentError("SamplingOptions: the enabled sample kinds give no sample on this mesh");
    if (!vertex_closest) {
        d.distances = to.distances(d.samples.points);
        return d;
    }
    const std::size_t nv = d.samples.n_vertex;  // the vertex samples come first
    d.distances.resize(d.samples.size());
    for (std::size_t i = 0; i < nv; ++i) d.distances[i] = (*vertex_closest)[d.samples.element[i]].distance;
    to.distances(d.samples.points.data() + nv, d.samples.size() - nv, d.distances.data() + nv);
    return d;
}

// The seed of a certified Hausdorff distance: the sampled maximum of \p s,
// on a face of \p from (for a vertex sample, the lowest-index face using it).
HausdorffSeed seed_of(const Mesh& from, const DistanceStats& s)
{
    HausdorffSeed seed{s.max_point, s.max_element, s.max};
    if (s.max_kind == SampleKind::OnVertex) {
        for (std::size_t f = 0; f < from.n_faces(); ++f) {
            const Face& t = from.faces[f];
            if (std::find(t.begin(), t.end(), int(s.max_element)) != t.end()) {
                seed.face = std::uint32_t(f);
                break;
            }
        }
    }
    return seed;
}

// surface_distance() and surface_distance_samples(): both directions, keeping
// the samples in \p forward and \p backward when they are given.
SurfaceDistance both_directions(const Mesh& a, const Mesh& b, const SamplingOptions& options, bool b_vertex_distances,
                                SampledDirection* forward, SampledDirection* backward,
                                const std::optional<HausdorffOptions>& certify = std::nullopt)
{
    validate(options);
    if (certify) validate(*certify);
    validate(a, "surface_distance: mesh A");
    validate(b, "surface_distance: mesh B");
    SamplingOptions opt = options;
    if (!opt.samples && !opt.density) opt.samples = 10 * std::max(a.n_faces(), b.n_faces());

    SurfaceDistance r;
    {
        const ClosestPointIndex index_b(b);
        std::vector<ClosestPoint> vq;  // A's vertices: samples and certification
        if (certify) vq = index_b.closest_points(a.points);
        SampledDirection d = sampled_direction(a, index_b, opt, certify ? &vq : nullptr);
        r.forward = distance_stats(d.samples, d.distances);
        if (forward) *forward = std::move(d);
        d = SampledDirection{};  // free the samples before the certification
        if (certify)
            r.forward_hausdorff = detail::certified_hausdorff(a, b, index_b, *certify, seed_of(a, r.forward), vq);
    }
    {
        const ClosestPointIndex index_a(a);
        std::vector<ClosestPoint> vq;
        if (certify) vq = index_a.closest_points(b.points);
        SampledDirection d = sampled_direction(b, index_a, opt, certify ? &vq : nullptr);
        r.backward = distance_stats(d.samples, d.distances);
        if (backward) *backward = std::move(d);
        d = SampledDirection{};
        if (b_vertex_distances) {
            if (certify) {
                r.b_vertex_distance.resize(vq.size());
                for (std::size_t v = 0; v < vq.size(); ++v) r.b_vertex_distance[v] = vq[v].distance;
            } else {
                r.b_vertex_distance = vertex_distances(b, index_a);
            }
        }
        if (certify)
            r.backward_hausdorff = detail::certified_hausdorff(b, a, index_a, *certify, seed_of(b, r.backward), vq);
    }
    r.hausdorff = std::max(r.forward.max, r.backward.max);
    r.diagonal = bounding_box(a).diagonal();
    r.metro_diagonal = metro_diagonal(a, b);
    return r;
}

}  // namespace

DistanceStats one_sided_distance(const Mesh& from, const ClosestPointIndex& to, const SamplingOptions& options)
{
    const SampledDirection d = sampled_direction(from, to, options);
    return distance_stats(d.samples, d.distances);
}

SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options, bool b_vertex_distances,
                                 const std::optional<HausdorffOptions>& certify)
{
    return both_directions(a, b, options, b_vertex_distances, nullptr, nullptr, certify);
}

SampledSurfaceDistance surface_distance_samples(const Mesh& a, const Mesh& b, const SamplingOptions& options)
{
    SampledSurfaceDistance r;
    r.distance = both_directions(a, b, options, false, &r.forward, &r.backward);
    return r;
}

std::vector<double> vertex_distances(const Mesh& from, const ClosestPointIndex& to)
{
    return to.distances(from.points);
}

double metro_diagonal(const Mesh& a, const Mesh& b)
{
    const BoundingBox ba = bounding_box(a);
    const BoundingBox bb = bounding_box(b);
    BoundingBox u;
    u.min = ba.min.cwiseMin(bb.min);
    u.max = ba.max.cwiseMax(bb.max);
    const double widen = 0.02 * u.diagonal();
    u.min.array() -= widen;
    u.max.array() += widen;
    return u.diagonal();
}

}  // namespace meshdiff
