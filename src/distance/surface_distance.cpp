#include "meshdiff/distance/surface_distance.h"

#include "meshdiff/core/progress.h"
#include "meshdiff/distance/cloud_distance.h"
#include "meshdiff/distance/signed_distance.h"
#include "meshdiff/error.h"

#include "core/release.h"
#include "core/stage_progress.h"
#include "core/unset_allocator.h"
#include "distance/direction_fold.h"
#include "distance/hausdorff_seeded.h"
#include "distance/signed_query.h"
#include "distance/surface_distance_chunks.h"
#include "distance/two_directions.h"
#include "geometry/morton_code.h"
#include "geometry/sample_plan.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
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

double detail::reference_diagonal(const MeshData& a, const char* what)
{
    const double diagonal = a.box().diagonal();
    if (!(diagonal > 0.0 && std::isfinite(diagonal)))
        throw InvalidMeshError(fmt::format(
            "surface_distance: A (the original) has no extent: its {} {} lie at one place (bounding-box diagonal "
            "{}), so the distances relative to its diagonal are undefined",
            a.mesh().n_vertices(), what, diagonal));
    return diagonal;
}

using detail::DirectionFold;

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
SampledDirection sampled_direction(const MeshData& from, const Target& to, const SamplingOptions& options,
                                   const std::vector<detail::VertexClosest>* vertex_closest,
                                   std::vector<std::int8_t>& signs)
{
    SampledDirection d;
    d.samples = sample_surface(from, options);
    if (d.samples.size() == 0)
        throw InvalidArgumentError("SamplingOptions: the enabled sample kinds give no sample on this mesh");
    const std::size_t n = d.samples.size();
    const std::size_t nv = vertex_closest ? d.samples.n_vertex : 0;  // the vertex samples come first
    d.distances.resize(n);
    signs.assign(to.normals ? n : 0, 0);
    const auto mv = std::int64_t(nv);
#pragma omp parallel for schedule(static)
    for (std::int64_t j = 0; j < mv; ++j) {
        const auto i = std::size_t(j);
        const detail::VertexClosest& c = (*vertex_closest)[d.samples.element[i]];
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

}  // namespace

void detail::chunk_query_order(const Vec3* points, const SampleKind* kind, const std::uint32_t* element, std::size_t k,
                               const BoundingBox& box, std::vector<std::uint32_t>& order)
{
    order.clear();
    auto starts_run = [&](std::size_t i) { return i == 0 || kind[i] != kind[i - 1] || element[i] != element[i - 1]; };
    std::vector<std::uint32_t> start;  // the runs' first positions, then k
    for (std::size_t i = 0; i < k; ++i)
        if (starts_run(i)) start.push_back(std::uint32_t(i));
    const std::size_t runs = start.size();
    start.push_back(std::uint32_t(k));
    if (runs < 2) return;
    // Each run's key: the top 30 bits of its first point's Morton code (10
    // per axis) above its index; sorted by the code alone, stably (three
    // passes of 10 bits, least significant first), so ties keep position
    // order.
    const Vec3 ext = morton_extent(box);
    std::vector<std::uint64_t> key(runs), sorted(runs);
    for (std::size_t r = 0; r < runs; ++r) key[r] = (morton_code(points[start[r]], box.min, ext) >> 33) << 32 | r;
    std::array<std::uint32_t, 1025> at;
    for (int pass = 0; pass < 3; ++pass) {
        const int shift = 32 + 10 * pass;
        at.fill(0);
        for (const std::uint64_t x : key) ++at[((x >> shift) & 1023u) + 1];
        for (std::size_t d = 1; d < at.size(); ++d) at[d] += at[d - 1];
        for (const std::uint64_t x : key) sorted[at[(x >> shift) & 1023u]++] = x;
        key.swap(sorted);
    }
    // Kept only where it shortens the steps between consecutive runs' first
    // points (their L1 lengths) by kOrderedStepRatio or more: an order
    // already coherent (a mesh numbered along its scan lines) gains less from
    // it than the sort costs.
    auto first = [&](std::uint64_t x) -> const Vec3& { return points[start[x & 0xffffffffu]]; };
    double given = 0.0, ordered = 0.0;
    for (std::size_t r = 1; r < runs; ++r) {
        given += (points[start[r]] - points[start[r - 1]]).lpNorm<1>();
        ordered += (first(key[r]) - first(key[r - 1])).lpNorm<1>();
    }
    if (!(given >= kOrderedStepRatio * ordered)) return;
    order.resize(k);
    std::size_t j = 0;
    for (const std::uint64_t x : key) {
        const std::size_t r = x & 0xffffffffu;
        for (std::uint32_t i = start[r]; i < start[r + 1]; ++i) order[j++] = i;
    }
}

namespace {

// One direction as sampled_direction(), distance_stats(), the signed
// statistics and summarize() give it, in bounded memory: the samples are
// made, queried and folded into the statistics \p chunk at a time (a multiple
// of kQueryBlock: the queries then start from the same triangles as in one
// batch); only their distances are kept, for the percentiles. The area shares
// below \p thresholds go to \p within. \p planned (when set) is called once
// the plan is made.
DistanceStats chunked_direction(const MeshData& from_data, const Target& to, const SamplingOptions& options,
                                const std::vector<detail::VertexClosest>* vertex_closest,
                                const std::vector<double>& thresholds, std::size_t bins, std::size_t chunk,
                                std::vector<double>& within, const std::function<void()>& planned)
{
    const Mesh& from = from_data.mesh();
    // As sample_surface() does: check, then plan in the "sampling" stage.
    validate(options);
    from_data.validate("sample_surface");
    detail::SamplePlan plan;
    {
        detail::StageProgress stage("sampling", 1);
        plan = detail::plan_samples(from_data, options);
        stage.finish();
    }
    if (planned) planned();
    const std::size_t n = plan.size();
    if (n == 0) throw InvalidArgumentError("SamplingOptions: the enabled sample kinds give no sample on this mesh");
    const std::size_t nv = vertex_closest ? plan.counts.n_vertex : 0;  // the vertex samples come first
    // Grown chunk by chunk, so that its pages become resident as the plan's
    // vertex and edge lists are freed; reserved, so never moved while a
    // chunk's distances are folded.
    // Not zeroed: the queries (in parallel) are the first to write them.
    std::vector<double, detail::UnsetAllocator<double>> distances;
    distances.reserve(n);
    const std::size_t m = std::min(chunk, n);
    // Two sets of buffers: a chunk is folded into the statistics (serially,
    // in sample order) by one thread of the team that queries the next one
    // in the other set (the others query meanwhile).
    struct Buffers
    {
        std::vector<Vec3> points;
        std::vector<SampleKind> kind;
        std::vector<std::uint32_t> element;
        std::vector<std::int8_t> signs;
    };
    Buffers buffers[2];
    for (Buffers& b : buffers) {
        b.points.resize(m);  // not zeroed (Eigen): first written in parallel below
        const auto mm = std::int64_t(m);
#pragma omp parallel for schedule(static)
        for (std::int64_t i = 0; i < mm; ++i) b.points[std::size_t(i)] = Vec3::Zero();
        b.kind.resize(m);
        b.element.resize(m);
        b.signs.assign(to.normals ? m : 0, 0);
    }
    detail::SampleMaker maker(from, plan);
    DirectionFold fold(from, plan, thresholds, to.normals != nullptr);
    // The chunk made and queried last, not folded yet: [begin, begin + k) in b.
    struct Pending
    {
        std::size_t begin = 0, k = 0;
        const Buffers* b = nullptr;
    } pending;
    auto fold_pending = [&] {
        if (!pending.b) return;
        const Buffers& b = *pending.b;
        fold.add(pending.k, b.points.data(), b.kind.data(), b.element.data(), distances.data() + pending.begin,
                 b.signs.data());
        pending.b = nullptr;
    };
    std::size_t chunks = 0;

    // The vertex samples with their distances from vertex_closest.
    for (std::size_t begin = 0; begin < nv; begin += chunk) {
        const std::size_t k = std::min(nv, begin + chunk) - begin;
        Buffers& b = buffers[chunks++ % 2];
        maker.make(begin, begin + k, b.points.data(), b.kind.data(), b.element.data());
        plan.discard_made(begin + k);
        distances.resize(begin + k);
        const auto kk = std::int64_t(k);
#pragma omp parallel for schedule(static)
        for (std::int64_t j = 0; j < kk; ++j) {
            const auto i = std::size_t(j);
            const detail::VertexClosest& c = (*vertex_closest)[b.element[i]];
            distances[begin + i] = c.distance;
            if (to.normals)
                b.signs[i] =
                    c.distance > 0.0 ? std::int8_t(distance_sign(to.mesh, *to.normals, b.points[i], c.face)) : 0;
        }
        fold_pending();
        pending = {begin, k, &b};
    }
    // The others queried, as one stage, each chunk in its query order
    // (chunk_query_order()). A mesh's vertices, edges or faces are numbered
    // coherently or not throughout: once kOrderTrials chunks in a row that
    // begin with one kind of sample kept their own order, the chunks that
    // begin with that kind are not tried again.
    std::vector<std::uint32_t> order;
    std::array<std::size_t, 4> kept_own{};  // by the SampleKind of a chunk's first sample
    Progress* progress = current_progress();
    detail::StageProgress stage("distances", n - nv);
    for (std::size_t begin = nv; begin < n; begin += chunk) {
        const std::size_t k = std::min(n, begin + chunk) - begin;
        Buffers& b = buffers[chunks++ % 2];  // not the pending chunk's
        maker.make(begin, begin + k, b.points.data(), b.kind.data(), b.element.data());
        plan.discard_made(begin + k);
        distances.resize(begin + k);
        order.clear();
        std::size_t& own = kept_own[std::size_t(b.kind[0]) % kept_own.size()];
        if (own < detail::kOrderTrials) {
            detail::chunk_query_order(b.points.data(), b.kind.data(), b.element.data(), k, from_data.box(), order);
            own = order.empty() ? own + 1 : 0;
        }
        const std::uint32_t* ordered = order.empty() ? nullptr : order.data();
        {
            PartProgress part(progress, begin - nv);
            const ProgressScope scope(progress ? &part : nullptr);
            const std::function<void()> beside = pending.b ? std::function<void()>(fold_pending) : nullptr;
            if (to.normals)
                detail::signed_query(to.mesh, to.index, *to.normals, b.points.data(), k, distances.data() + begin,
                                     b.signs.data(), beside, ordered);
            else
                detail::distances_with_regions(to.index, b.points.data(), k, distances.data() + begin, {}, beside,
                                               ordered);
        }
        fold_pending();  // a no-op: the team ran it (kept so that no chunk can be left unfolded)
        pending = {begin, k, &b};
        if (begin + k >= plan.counts.n_vertex + plan.counts.n_edge)
            plan.drop_vertices_and_edges();  // face samples left (the fold reads the face offsets only)
    }
    fold_pending();
    stage.finish();
    for (Buffers& b : buffers) b = {};
    return fold.finish(distances.data(), distances.size(), bins, within);
}

// The signed distances: sign x distance (0 where the sign is 0).
std::vector<double> apply_signs(const std::vector<double>& distances, const std::vector<std::int8_t>& signs)
{
    std::vector<double> s(distances.size());
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = signs[i] == 0 ? 0.0 : double(signs[i]) * distances[i];
    return s;
}

// What two_directions() asks of one direction: the samples of `from` (a
// mesh's samples or a cloud's points) and their distances to `to`.
struct DirectionTask
{
    const MeshData& from_data;  // the derived data of `from` and `to`
    const MeshData& to_data;
    const Mesh& from;  // from_data.mesh()
    const Mesh& to;    // to_data.mesh()
    bool from_cloud;
    bool to_cloud;
    const char* to_name;  // names `to` in the reason for no sign
    const DistanceOptions& options;
    const SamplingOptions& sampling;                        // with the default budget set
    const std::vector<double>& thresholds;                  // the F-score thresholds, absolute
    bool keep;                                              // keep the samples
    std::size_t chunk;                                      // samples made and queried at a time when not kept
    const ClosestPointIndex* index;                         // of `to`, built by the caller; null: build one
    std::vector<ClosestPoint>* vertices_closest = nullptr;  // of from's vertices on `to`, if the caller has them
    std::function<void()> planned = nullptr;                // HandedToDistance::release_incidences
};

// What one direction gives back.
struct DirectionResult
{
    DistanceStats stats;
    std::vector<double> within;                                   // area (point) shares below the thresholds
    SampledDirection samples;                                     // with DirectionTask::keep
    std::vector<double> vertex_distance, vertex_signed_distance;  // with DistanceOptions::vertex_distances
    std::optional<CertifiedHausdorff> certified;                  // with DistanceOptions::hausdorff
};

// The target of a direction: the index of a mesh, with its pseudo-normals
// when it can be signed against and the samples are a mesh's, or of a cloud.
struct DirectionTarget
{
    std::optional<ClosestPointIndex> own;      // built here
    const ClosestPointIndex* index = nullptr;  // own or the caller's
    std::optional<PointCloudIndex> cloud;
    std::optional<PseudoNormals> normals;
    std::string unsigned_reason;  // why there is no sign
    // The normals while they are made, by a task that writes unsigned_reason:
    // declared last, so destroyed (waiting for the task) first when a
    // direction ends early on an exception.
    std::future<std::optional<PseudoNormals>> pending;
    // The pseudo-normals, once made; without face normals (48 MB for 2M
    // faces): the signs make them from the index's corners (the same
    // values, signed_distance.h).
    void take_normals()
    {
        if (pending.valid()) normals = pending.get();
    }
};

// The index of the mesh t.to: the caller's (its face count checked), or built.
void build_index(const DirectionTask& t, DirectionTarget& g)
{
    if (!t.index) {
        g.index = &g.own.emplace(t.to_data);
        return;
    }
    if (t.index->n_faces() != t.to.n_faces())
        throw InvalidArgumentError(fmt::format("DistanceOptions: the index given for {} has {} faces, the mesh has {}",
                                               t.to_name, t.index->n_faces(), t.to.n_faces()));
    g.index = t.index;
}

void make_target(const DirectionTask& t, DirectionTarget& g)
{
    if (t.to_cloud) {
        g.cloud.emplace(t.to.points);
        g.unsigned_reason = "the other input is a point cloud: it has no inside";
    } else if (t.from_cloud) {
        // A cloud's points against a mesh are left unsigned (the sign needs
        // the closest feature, not computed for them).
        build_index(t, g);
        g.unsigned_reason =
            "the samples are the points of a cloud: signed distances are computed for mesh samples only";
    } else {
        // The sign (signed_distance.h): from the closest faces of the same
        // queries. The pseudo-normals (serial) are made on another thread
        // while the index is built (or, when it was given, while the
        // vertices' closest points are found): take_normals() waits for them.
        g.pending = std::async(omp_get_max_threads() > 1 ? std::launch::async : std::launch::deferred, [&t, &g] {
            return detail::pseudo_normals_without_faces(t.to_data, t.to_name, &g.unsigned_reason);
        });
        build_index(t, g);
    }
}

// The distance of every vertex of a mesh t.from to the mesh t.to, and the
// signed ones when it can be signed against; from \p vq (the closest points
// of the vertices) when given.
void mesh_vertex_distances(const DirectionTask& t, const DirectionTarget& g,
                           const std::vector<detail::VertexClosest>* vq, DirectionResult& r)
{
    const std::size_t nv = t.from.points.size();
    std::vector<std::int8_t> vsigns(g.normals ? nv : 0, 0);
    if (vq) {
        r.vertex_distance.resize(nv);
        for (std::size_t v = 0; v < nv; ++v) {
            r.vertex_distance[v] = (*vq)[v].distance;
            if (g.normals && (*vq)[v].distance > 0.0)
                vsigns[v] = std::int8_t(distance_sign(t.to, *g.normals, t.from.points[v], (*vq)[v].face));
        }
    } else if (g.normals) {
        r.vertex_distance.resize(nv);
        signed_query(t.to, *g.index, *g.normals, t.from.points.data(), nv, r.vertex_distance.data(), vsigns.data());
    } else {
        r.vertex_distance = vertex_distances(t.from, *g.index);
    }
    if (g.normals) r.vertex_signed_distance = apply_signs(r.vertex_distance, vsigns);
}

// One direction of two_directions(): the statistics of the distances of the
// samples of t.from to t.to, with the per-vertex distances, the kept samples
// and the certification asked for.
DirectionResult one_direction(const DirectionTask& t)
{
    const DistanceOptions& o = t.options;
    const std::size_t bins = o.summary.histogram_bins;
    DirectionResult r;
    DirectionTarget g;
    make_target(t, g);
    const bool meshes = !t.from_cloud && !t.to_cloud;
    // From's vertices on `to` (samples and certification, two meshes): their
    // distances and faces only, the caller's closest points freed.
    std::vector<detail::VertexClosest> vq;
    if (meshes && o.hausdorff) {
        if (t.vertices_closest && t.vertices_closest->size() == t.from.points.size()) {
            vq = detail::vertex_closest(*t.vertices_closest);
            detail::release(*t.vertices_closest);
        } else {
            vq = detail::vertex_closest(g.index->closest_points(t.from.points));
        }
    }
    g.take_normals();
    const std::vector<detail::VertexClosest>* vertex_closest = meshes && o.hausdorff ? &vq : nullptr;
    if (meshes && !t.keep) {
        // The same statistics without keeping the samples (freed before the certification).
        const Target target{t.to, *g.index, g.normals ? &*g.normals : nullptr};
        r.stats = chunked_direction(t.from_data, target, t.sampling, vertex_closest, t.thresholds, bins, t.chunk,
                                    r.within, t.planned);
    } else {
        SampledDirection d;
        if (meshes) {
            std::vector<std::int8_t> signs;
            const Target target{t.to, *g.index, g.normals ? &*g.normals : nullptr};
            d = sampled_direction(t.from_data, target, t.sampling, vertex_closest, signs);
            r.stats = distance_stats(d.samples, d.distances);
            if (g.normals) {
                d.signed_distances = apply_signs(d.distances, signs);
                r.stats.signed_distance = signed_distance_stats(d.signed_distances);
            }
        } else {
            d = detail::cloud_direction(t.from, t.from_cloud, g.index, g.cloud ? &*g.cloud : nullptr, t.sampling);
            r.stats = distance_stats(d.samples, d.distances);
        }
        if (t.from_cloud) {
            r.stats.n_point = d.samples.size();
            r.stats.area_weighted = detail::point_weighted_stats(d.distances, t.thresholds, r.within);
        } else {
            r.stats.area_weighted = area_weighted_stats(t.from, d.samples, d.distances, t.thresholds, &r.within);
        }
        if (bins > 0) r.stats.histogram = distance_histogram(d.distances, bins);
        if (t.from_cloud && o.vertex_distances) r.vertex_distance = d.distances;  // the points, in order
        if (t.keep) r.samples = std::move(d);
    }
    if (g.normals)
        r.stats.signed_distance->flipped = g.normals->flipped;
    else
        r.stats.signed_unavailable = g.unsigned_reason;
    if (o.vertex_distances && !t.from_cloud) {
        if (t.to_cloud)
            r.vertex_distance = g.cloud->distances(t.from.points);
        else
            mesh_vertex_distances(t, g, vertex_closest, r);
    }
    // The pseudo-normals freed before the certification, but for their
    // opposite half-edges: its neighbours across `to`'s edges.
    std::vector<std::uint32_t> opposite;
    if (g.normals) opposite = std::move(g.normals->opposite);
    g.normals.reset();
    if (o.hausdorff && meshes)
        r.certified =
            detail::certified_hausdorff(t.from_data, t.to_data, *g.index, *o.hausdorff,
                                        detail::seed_of(t.from, r.stats), vq, opposite.empty() ? nullptr : &opposite);
    else if (o.hausdorff && t.from_cloud)
        r.certified =
            detail::exact_over_points(t.to, g.index, g.cloud ? &*g.cloud : nullptr, r.stats, t.from.points.size());
    return r;
}

}  // namespace

DistanceStats one_sided_distance(const Mesh& from, const ClosestPointIndex& to, const SamplingOptions& options)
{
    const Mesh none;
    std::vector<std::int8_t> signs;
    const SampledDirection d = sampled_direction(MeshData(from), Target{none, to, nullptr}, options, nullptr, signs);
    return distance_stats(d.samples, d.distances);
}

namespace {

// The derived data of \p mesh ("A" or "B", \p which): \p given if set (it
// must be that very mesh's), else made in \p own.
const MeshData& data_of(const Mesh& mesh, const MeshData* given, std::optional<MeshData>& own, const char* which)
{
    if (!given) return own.emplace(mesh);
    if (&given->mesh() != &mesh)
        throw InvalidArgumentError(
            fmt::format("DistanceOptions: data_{} holds the derived data of another mesh than {}",
                        which[0] == 'A' ? "a" : "b", which));
    return *given;
}

}  // namespace

SurfaceDistance detail::two_directions(const Mesh& a, const Mesh& b, const DistanceOptions& options, bool keep_forward,
                                       bool keep_backward, bool clouds, std::size_t chunk, HandedToDistance* handed)
{
    if (chunk == 0 || chunk % kQueryBlock != 0)
        throw InvalidArgumentError(
            fmt::format("surface_distance: chunk of {} samples, not a positive multiple of {}", chunk, kQueryBlock));
    validate(options.sampling);
    validate(options.summary);
    if (options.hausdorff) validate(*options.hausdorff);
    // The derived data of A and B: the caller's, or made here.
    std::optional<MeshData> own_a, own_b;
    const MeshData& da = data_of(a, options.data_a, own_a, "A");
    const MeshData& db = data_of(b, options.data_b, own_b, "B");
    const bool cloud_a = clouds && a.faces.empty(), cloud_b = clouds && b.faces.empty();
    if (cloud_a)
        check_cloud(a, "surface_distance: A");
    else
        da.validate("surface_distance: mesh A");
    if (cloud_b)
        check_cloud(b, "surface_distance: B");
    else
        db.validate("surface_distance: mesh B");
    // An unset target is Metro's 10 x max(#faces A, #faces B), each point of
    // a cloud counted as a face, so that a mesh is sampled at least as
    // densely as the cloud it is measured against.
    SamplingOptions sampling = options.sampling;
    if (!sampling.samples && !sampling.density)
        sampling.samples =
            10 * std::max(cloud_a ? a.n_vertices() : a.n_faces(), cloud_b ? b.n_vertices() : b.n_faces());
    // A cloud of one point (or of equal points) has no diagonal: an input
    // error like a mesh without extent.
    const double diagonal = reference_diagonal(da, cloud_a ? "points" : "vertices");
    std::vector<double> thresholds;  // absolute
    for (double t : options.summary.fscore_thresholds) thresholds.push_back(t * diagonal);

    // An index of A handed over is used by the backward direction, which
    // then runs first, and freed before the forward one (the two directions
    // are independent: the order changes no bit).
    const bool handed_a = handed && handed->index_a.has_value();
    if (handed_a && (cloud_a || options.index_a))
        throw InvalidArgumentError(
            "surface_distance: an index of A handed over with DistanceOptions::index_a set "
            "or A a point cloud");
    std::function<void()> release_incidences;
    if (handed && !cloud_a && !cloud_b) release_incidences = handed->release_incidences;
    auto forward = [&] {
        return one_direction({da, db, a, b, cloud_a, cloud_b, "the processed mesh", options, sampling, thresholds,
                              keep_forward, chunk, cloud_b ? nullptr : options.index_b, nullptr, release_incidences});
    };
    auto backward = [&] {
        DirectionTask t{db,
                        da,
                        b,
                        a,
                        cloud_b,
                        cloud_a,
                        "the original mesh",
                        options,
                        sampling,
                        thresholds,
                        keep_backward,
                        chunk,
                        handed_a  ? &*handed->index_a
                        : cloud_a ? nullptr
                                  : options.index_a};
        if (handed && !cloud_a && !cloud_b) t.vertices_closest = &handed->b_vertices_on_a;
        t.planned = release_incidences;
        DirectionResult k = one_direction(t);
        if (handed) {
            handed->index_a.reset();
            detail::release(handed->b_vertices_on_a);
        }
        return k;
    };
    DirectionResult k, f;
    if (handed_a) {
        k = backward();
        f = forward();
    } else {
        f = forward();
        k = backward();
    }

    SurfaceDistance r;
    r.forward = std::move(f.stats);
    r.forward_samples = std::move(f.samples);
    r.original_vertex_distance = std::move(f.vertex_distance);
    r.original_vertex_signed_distance = std::move(f.vertex_signed_distance);
    r.forward_hausdorff = std::move(f.certified);
    r.backward = std::move(k.stats);
    r.backward_samples = std::move(k.samples);
    r.processed_vertex_distance = std::move(k.vertex_distance);
    r.processed_vertex_signed_distance = std::move(k.vertex_signed_distance);
    r.backward_hausdorff = std::move(k.certified);

    r.hausdorff = std::max(r.forward.max, r.backward.max);
    r.diagonal = diagonal;
    r.metro_diagonal = metro_diagonal(da.box(), db.box());
    r.summary = summary_metrics(r, &r.summary_unavailable);
    if (r.summary) r.fscore = fscores(options.summary.fscore_thresholds, diagonal, f.within, k.within);
    r.forward_kind = distance_kind(cloud_a, cloud_b);
    r.backward_kind = distance_kind(cloud_b, cloud_a);
    return r;
}

SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options)
{
    return detail::two_directions(a, b, options, options.keep_samples, options.keep_samples, false);
}

SurfaceDistance surface_distance(const Mesh& a, const Mesh& b, const SamplingOptions& options, bool b_vertex_distances,
                                 const std::optional<HausdorffOptions>& certify, const SummaryOptions& summary,
                                 SampledDirection* forward_samples, SampledDirection* backward_samples)
{
    DistanceOptions o;
    o.sampling = options;
    o.hausdorff = certify;
    o.summary = summary;
    o.vertex_distances = b_vertex_distances;
    return detail::deprecated_result(
        detail::two_directions(a, b, o, forward_samples != nullptr, backward_samples != nullptr, false),
        forward_samples, backward_samples);
}

SurfaceDistance detail::surface_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options,
                                         std::size_t chunk)
{
    return two_directions(a, b, options, options.keep_samples, options.keep_samples, false, chunk);
}

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
    return metro_diagonal(bounding_box(a), bounding_box(b));
}

double metro_diagonal(const BoundingBox& ba, const BoundingBox& bb)
{
    BoundingBox u;
    u.min = ba.min.cwiseMin(bb.min);
    u.max = ba.max.cwiseMax(bb.max);
    const double widen = 0.02 * u.diagonal();
    u.min.array() -= widen;
    u.max.array() += widen;
    return u.diagonal();
}

}  // namespace meshdiff
