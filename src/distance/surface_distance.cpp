#include "meshdiff/distance/surface_distance.h"

#include "meshdiff/core/progress.h"
#include "meshdiff/distance/signed_distance.h"
#include "meshdiff/error.h"

#include "core/compensated_sum.h"
#include "core/stage_progress.h"
#include "distance/distance_accumulators.h"
#include "distance/hausdorff_seeded.h"
#include "distance/surface_distance_chunks.h"
#include "geometry/sample_plan.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <string_view>
#include <utility>

namespace meshdiff {

namespace {

// 10 log10(factor peak^2 / e); +inf for e = 0.
double psnr_db(double peak, double factor, double e)
{
    return e > 0.0 ? 10.0 * std::log10(factor * peak * peak / e) : std::numeric_limits<double>::infinity();
}

}  // namespace

std::optional<SummaryMetrics> summary_metrics(const SurfaceDistance& d, std::string* reason)
{
    const auto& f = d.forward.area_weighted;
    const auto& b = d.backward.area_weighted;
    if (!f || !b) {
        if (reason)
            *reason = fmt::format(
                "no face sample in the {} direction (face samples off, or the vertex and edge samples "
                "used the whole budget)",
                !f && !b ? "forward and backward" : (!f ? "forward" : "backward"));
        return std::nullopt;
    }
    SummaryMetrics m;
    m.chamfer_l1 = f->mean + b->mean;
    m.chamfer_l2 = f->mean_square + b->mean_square;
    Psnr& p = m.psnr;
    p.peak = d.diagonal;
    p.mse = std::max(f->mean_square, b->mean_square);
    p.mse_db = psnr_db(p.peak, p.factor, p.mse);
    p.forward_mse_db = psnr_db(p.peak, p.factor, f->mean_square);
    p.backward_mse_db = psnr_db(p.peak, p.factor, b->mean_square);
    p.hausdorff = d.hausdorff;
    p.hausdorff_db = psnr_db(p.peak, p.factor, d.hausdorff * d.hausdorff);
    p.forward_hausdorff_db = psnr_db(p.peak, p.factor, d.forward.max * d.forward.max);
    p.backward_hausdorff_db = psnr_db(p.peak, p.factor, d.backward.max * d.backward.max);
    return m;
}

double detail::reference_diagonal(const Mesh& a, const char* what)
{
    const double diagonal = bounding_box(a).diagonal();
    if (!(diagonal > 0.0 && std::isfinite(diagonal)))
        throw InvalidMeshError(fmt::format(
            "surface_distance: A (the original) has no extent: its {} {} lie at one place (bounding-box diagonal "
            "{}), so the distances relative to its diagonal are undefined",
            a.n_vertices(), what, diagonal));
    return diagonal;
}

namespace {

// The surface a direction measures to, with its pseudo-normals when it can be
// signed against.
struct Target
{
    const Mesh& mesh;
    const ClosestPointIndex& index;
    const PseudoNormals* normals;  // null: no sign
};

// The samples of \p from and their distances to \p to, and when to.normals is
// set the signs of the distances in \p signs (-1, 0, +1; one byte a sample).
// With \p vertex_closest (the closest points of all vertices of \p from), the
// vertex samples take their distances from it instead of new queries (the
// same values: the queries are exact).
SampledDirection sampled_direction(const Mesh& from, const Target& to, const SamplingOptions& options,
                                   const std::vector<ClosestPoint>* vertex_closest, std::vector<std::int8_t>& signs)
{
    SampledDirection d;
    d.samples = sample_surface(from, options);
    if (d.samples.size() == 0)
        throw InvalidArgumentError("SamplingOptions: the enabled sample kinds give no sample on this mesh");
    const std::size_t n = d.samples.size();
    const std::size_t nv = vertex_closest ? d.samples.n_vertex : 0;  // the vertex samples come first
    d.distances.resize(n);
    signs.assign(to.normals ? n : 0, 0);
    for (std::size_t i = 0; i < nv; ++i) {
        const ClosestPoint& c = (*vertex_closest)[d.samples.element[i]];
        d.distances[i] = c.distance;
        if (to.normals && c.distance > 0.0)
            signs[i] = std::int8_t(distance_sign(to.mesh, *to.normals, d.samples.points[i], c.face));
    }
    const Vec3* rest = d.samples.points.data() + nv;
    if (to.normals)
        signed_query(to.mesh, to.index, *to.normals, rest, n - nv, d.distances.data() + nv, signs.data() + nv);
    else
        to.index.distances(rest, n - nv, d.distances.data() + nv);
    return d;
}

// The Progress of one part of a stage run as a batch of its own (a chunk of
// the samples' queries): the part's stage is not announced, its work is
// reported as done in the whole stage from `offset` on, and it stops when the
// whole run is cancelled.
class PartProgress : public Progress
{
public:
    PartProgress(Progress* whole, std::size_t offset) : whole_(whole), offset_(offset) {}
    void stage(std::string_view, std::size_t) override {}
    void advance(std::size_t done) override { whole_->advance(offset_ + done); }
    bool cancelled() const override { return whole_->cancelled(); }

private:
    Progress* whole_;
    std::size_t offset_;
};

// The statistics of one direction folded over its samples a range at a time,
// in sample order, by the accumulators of distance_stats(),
// signed_distance_stats() and area_weighted_stats() (distance_accumulators.h).
class DirectionFold
{
public:
    DirectionFold(const Mesh& from, const detail::SamplePlan& plan, const std::vector<double>& thresholds,
                  bool is_signed)
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
    // sample order; partially sorted here), the histogram in \p bins bins
    // (none for 0), the area shares below the thresholds in \p within.
    DistanceStats finish(std::vector<double>& distances, std::size_t bins, std::vector<double>& within)
    {
        // The histogram first: the percentiles sort the distances in place.
        Histogram histogram;
        if (bins > 0) histogram = distance_histogram(distances, bins);
        DistanceStats s = stats_.finish(distances);
        s.n_vertex = plan_.counts.n_vertex;
        s.n_edge = plan_.counts.n_edge;
        s.n_face = plan_.counts.n_face;
        if (signed_) s.signed_distance = signed_stats_.finish(distances.size());
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
        detail::CompensatedSum total, sampled;
        for (std::size_t f = 0; f < from_.n_faces(); ++f) {
            const double area = face_area(f);
            total.add(area);
            if (face_samples(f)) sampled.add(area);
        }
        return area_.finish(plan_.counts.n_face, sampled, total, within);
    }

    const Mesh& from_;
    const detail::SamplePlan& plan_;
    const std::vector<double>& thresholds_;
    bool signed_;
    detail::DistanceAccumulator stats_;
    detail::SignedAccumulator signed_stats_;
    detail::AreaWeightedAccumulator area_;
};

// One direction as sampled_direction(), distance_stats(), the signed
// statistics and summarize() give it, in bounded memory: the samples are
// made, queried and folded into the statistics \p chunk at a time (a multiple
// of kQueryBlock: the queries then start from the same triangles as in one
// batch); only their distances are kept, for the percentiles. The area shares
// below \p thresholds go to \p within.
DistanceStats chunked_direction(const Mesh& from, const Target& to, const SamplingOptions& options,
                                const std::vector<ClosestPoint>* vertex_closest, const std::vector<double>& thresholds,
                                std::size_t bins, std::size_t chunk, std::vector<double>& within)
{
    // As sample_surface() does: check, then plan in the "sampling" stage.
    validate(options);
    validate(from, "sample_surface");
    detail::SamplePlan plan;
    {
        detail::StageProgress stage("sampling", 1);
        plan = detail::plan_samples(from, options);
        stage.finish();
    }
    const std::size_t n = plan.size();
    if (n == 0) throw InvalidArgumentError("SamplingOptions: the enabled sample kinds give no sample on this mesh");
    const std::size_t nv = vertex_closest ? plan.counts.n_vertex : 0;  // the vertex samples come first
    // Grown chunk by chunk, so that its pages become resident as the plan's
    // vertex and edge lists are freed.
    std::vector<double> distances;
    distances.reserve(n);
    const std::size_t m = std::min(chunk, n);
    std::vector<Vec3> points(m);
    std::vector<SampleKind> kind(m);
    std::vector<std::uint32_t> element(m);
    std::vector<std::int8_t> signs(to.normals ? m : 0, 0);
    detail::SampleMaker maker(from, plan);
    DirectionFold fold(from, plan, thresholds, to.normals != nullptr);

    // The vertex samples with their distances from vertex_closest.
    for (std::size_t begin = 0; begin < nv; begin += chunk) {
        const std::size_t k = std::min(nv, begin + chunk) - begin;
        maker.make(begin, begin + k, points.data(), kind.data(), element.data());
        distances.resize(begin + k);
        for (std::size_t i = 0; i < k; ++i) {
            const ClosestPoint& c = (*vertex_closest)[element[i]];
            distances[begin + i] = c.distance;
            if (to.normals)
                signs[i] = c.distance > 0.0 ? std::int8_t(distance_sign(to.mesh, *to.normals, points[i], c.face)) : 0;
        }
        fold.add(k, points.data(), kind.data(), element.data(), distances.data() + begin, signs.data());
    }
    // The others queried, as one stage.
    Progress* progress = current_progress();
    detail::StageProgress stage("distances", n - nv);
    for (std::size_t begin = nv; begin < n; begin += chunk) {
        const std::size_t k = std::min(n, begin + chunk) - begin;
        maker.make(begin, begin + k, points.data(), kind.data(), element.data());
        distances.resize(begin + k);
        {
            PartProgress part(progress, begin - nv);
            const ProgressScope scope(progress ? &part : nullptr);
            if (to.normals)
                signed_query(to.mesh, to.index, *to.normals, points.data(), k, distances.data() + begin, signs.data());
            else
                to.index.distances(points.data(), k, distances.data() + begin);
        }
        fold.add(k, points.data(), kind.data(), element.data(), distances.data() + begin, signs.data());
        if (begin + k >= plan.counts.n_vertex + plan.counts.n_edge)
            plan.drop_vertices_and_edges();  // face samples left
    }
    stage.finish();
    points = {};
    kind = {};
    element = {};
    signs = {};
    return fold.finish(distances, bins, within);
}

// The signed distances: sign x distance (0 where the sign is 0).
std::vector<double> apply_signs(const std::vector<double>& distances, const std::vector<std::int8_t>& signs)
{
    std::vector<double> s(distances.size());
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = signs[i] == 0 ? 0.0 : double(signs[i]) * distances[i];
    return s;
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
// the samples of the forward (backward) direction in r.forward_samples
// (backward_samples) with \p keep_forward (\p keep_backward). Without it, the
// samples are made and queried \p chunk at a time (chunked_direction()).
SurfaceDistance both_directions(const Mesh& a, const Mesh& b, const DistanceOptions& o, bool keep_forward,
                                bool keep_backward, std::size_t chunk = detail::kSampleChunk)
{
    if (chunk == 0 || chunk % detail::kQueryBlock != 0)
        throw InvalidArgumentError(fmt::format("surface_distance: chunk of {} samples, not a positive multiple of {}",
                                               chunk, detail::kQueryBlock));
    const SamplingOptions& options = o.sampling;
    const std::optional<HausdorffOptions>& certify = o.hausdorff;
    const SummaryOptions& summary = o.summary;
    validate(options);
    validate(summary);
    if (certify) validate(*certify);
    validate(a, "surface_distance: mesh A");
    validate(b, "surface_distance: mesh B");
    SamplingOptions opt = options;
    if (!opt.samples && !opt.density) opt.samples = 10 * std::max(a.n_faces(), b.n_faces());

    const double diagonal = detail::reference_diagonal(a, "vertices");
    std::vector<double> thresholds;  // absolute
    for (double t : summary.fscore_thresholds) thresholds.push_back(t * diagonal);
    // The sums over the samples beside the statistics of one direction.
    std::vector<double> recall, precision;  // area shares below the thresholds, forward and backward
    auto summarize = [&](DistanceStats& s, const Mesh& from, const SampledDirection& d, std::vector<double>& within) {
        s.area_weighted = area_weighted_stats(from, d.samples, d.distances, thresholds, &within);
        if (summary.histogram_bins > 0) s.histogram = distance_histogram(d.distances, summary.histogram_bins);
    };

    // One direction: samples on `from`, exact distances to `to`.
    auto direction = [&](const Mesh& from, const Mesh& to, const char* to_name, DistanceStats& stats,
                         std::vector<double>& within, SampledDirection* keep, std::vector<double>* vertex_distance,
                         std::vector<double>* vertex_signed, std::optional<CertifiedHausdorff>& certified) {
        // The sign (signed_distance.h): from the closest faces of the same
        // queries. The pseudo-normals (serial) are made on another thread
        // while the index is built.
        std::string unavailable;
        auto made_normals = std::async(omp_get_max_threads() > 1 ? std::launch::async : std::launch::deferred,
                                       [&] { return pseudo_normals(to, to_name, &unavailable); });
        const ClosestPointIndex index(to);
        std::optional<PseudoNormals> normals = made_normals.get();
        const Target target{to, index, normals ? &*normals : nullptr};
        std::vector<ClosestPoint> vq;  // from's vertices: samples and certification
        if (certify) vq = index.closest_points(from.points);
        if (keep) {
            std::vector<std::int8_t> signs;
            SampledDirection d = sampled_direction(from, target, opt, certify ? &vq : nullptr, signs);
            stats = distance_stats(d.samples, d.distances);
            if (normals) {
                d.signed_distances = apply_signs(d.distances, signs);
                stats.signed_distance = signed_distance_stats(d.signed_distances);
            }
            summarize(stats, from, d, within);
            *keep = std::move(d);
        } else {
            // The same statistics without keeping the samples (freed before the certification).
            stats = chunked_direction(from, target, opt, certify ? &vq : nullptr, thresholds, summary.histogram_bins,
                                      chunk, within);
        }
        if (normals)
            stats.signed_distance->flipped = normals->flipped;
        else
            stats.signed_unavailable = unavailable;
        if (vertex_distance) {
            const std::size_t nv = from.points.size();
            std::vector<std::int8_t> vsigns(normals ? nv : 0, 0);
            if (certify) {
                vertex_distance->resize(nv);
                for (std::size_t v = 0; v < nv; ++v) {
                    (*vertex_distance)[v] = vq[v].distance;
                    if (normals && vq[v].distance > 0.0)
                        vsigns[v] = std::int8_t(distance_sign(to, *normals, from.points[v], vq[v].face));
                }
            } else if (normals) {
                vertex_distance->resize(nv);
                signed_query(to, index, *normals, from.points.data(), nv, vertex_distance->data(), vsigns.data());
            } else {
                *vertex_distance = vertex_distances(from, index);
            }
            if (normals) *vertex_signed = apply_signs(*vertex_distance, vsigns);
        }
        normals.reset();  // free the pseudo-normals before the certification
        if (certify) certified = detail::certified_hausdorff(from, to, index, *certify, seed_of(from, stats), vq);
    };
    SurfaceDistance r;
    direction(a, b, "the processed mesh", r.forward, recall, keep_forward ? &r.forward_samples : nullptr,
              o.vertex_distances ? &r.a_vertex_distance : nullptr, &r.a_vertex_signed_distance, r.forward_hausdorff);
    direction(b, a, "the original mesh", r.backward, precision, keep_backward ? &r.backward_samples : nullptr,
              o.vertex_distances ? &r.b_vertex_distance : nullptr, &r.b_vertex_signed_distance, r.backward_hausdorff);
    r.hausdorff = std::max(r.forward.max, r.backward.max);
    r.diagonal = diagonal;
    r.metro_diagonal = metro_diagonal(a, b);
    r.summary = summary_metrics(r, &r.summary_unavailable);
    if (r.summary) r.fscore = fscores(summary.fscore_thresholds, diagonal, recall, precision);
    return r;
}

}  // namespace

DistanceStats one_sided_distance(const Mesh& from, const ClosestPointIndex& to, const SamplingOptions& options)
{
    const Mesh none;
    std::vector<std::int8_t> signs;
    const SampledDirection d = sampled_direction(from, Target{none, to, nullptr}, options, nullptr, signs);
    return distance_stats(d.samples, d.distances);
}

SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options)
{
    return both_directions(a, b, options, options.keep_samples, options.keep_samples);
}

SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options, bool b_vertex_distances,
                                 const std::optional<HausdorffOptions>& certify, const SummaryOptions& summary,
                                 SampledDirection* forward_samples, SampledDirection* backward_samples)
{
    const DistanceOptions o{options, certify, summary, b_vertex_distances, false};
    SurfaceDistance r = both_directions(a, b, o, forward_samples != nullptr, backward_samples != nullptr);
    if (forward_samples) *forward_samples = std::exchange(r.forward_samples, {});
    if (backward_samples) *backward_samples = std::exchange(r.backward_samples, {});
    return r;
}

namespace detail {

SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options, std::size_t chunk)
{
    return both_directions(a, b, options, options.keep_samples, options.keep_samples, chunk);
}

}  // namespace detail

SampledSurfaceDistance surface_distance_samples(const Mesh& a, const Mesh& b, const SamplingOptions& options,
                                                const SummaryOptions& summary)
{
    DistanceOptions o;
    o.sampling = options;
    o.summary = summary;
    o.keep_samples = true;
    SampledSurfaceDistance r;
    r.distance = surface_distance(a, b, o);
    r.forward = std::exchange(r.distance.forward_samples, {});
    r.backward = std::exchange(r.distance.backward_samples, {});
    return r;
}

std::vector<double> vertex_distances(const Mesh& from, const ClosestPointIndex& to)
{
    return to.distances(from.points);
}

std::vector<double> vertex_distances(const Mesh& from, const Mesh& to, const ClosestPointIndex& index,
                                     std::vector<double>& signed_out, const std::string& to_name)
{
    signed_out.clear();
    const std::optional<PseudoNormals> normals = pseudo_normals(to, to_name);
    if (!normals) return index.distances(from.points);
    std::vector<double> d(from.points.size());
    std::vector<std::int8_t> signs(d.size());
    signed_query(to, index, *normals, from.points.data(), d.size(), d.data(), signs.data());
    signed_out = apply_signs(d, signs);
    return d;
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
