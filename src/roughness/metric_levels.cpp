#include "meshdiff/roughness/metric_levels.h"

#include "meshdiff/error.h"

#include "core/stage_progress.h"
#include "roughness/morton.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace meshdiff {

std::vector<double> default_radii()
{
    std::vector<double> r;
    for (int k = 0; k <= 8; ++k) r.push_back(0.0125 * std::pow(2.0, 0.5 * k));
    return r;
}

void check_radii(const std::vector<double>& radii)
{
    if (radii.size() > kMaxRadii)
        throw OptionError("profile.radii", fmt::format("more than the limit of {} radii", kMaxRadii));
    for (double r : radii)
        if (!(r > 0.0 && r <= kMaxRadius))
            throw OptionError("profile.radii", fmt::format("radius {} is not in (0, {}]", r, kMaxRadius));
}

namespace {

// One centre's patch, for ball_patch(): a breadth-first search that enters
// only vertices inside the ball.
std::vector<std::uint32_t> bfs_patch(const Mesh& mesh, const Adjacency& adj, std::uint32_t v, double r2)
{
    std::vector<char> seen(mesh.n_vertices(), 0);
    std::vector<std::uint32_t> found{v};
    seen[v] = 1;
    const Vec3& c = mesh.points[v];
    for (std::size_t q = 0; q < found.size(); ++q)
        for (const std::uint32_t* it = adj.begin(found[q]); it != adj.end(found[q]); ++it)
            if (!seen[*it]) {
                seen[*it] = 1;
                if ((mesh.points[*it] - c).squaredNorm() <= r2) found.push_back(*it);
            }
    return found;
}

// Bit-parallel ball search from W * 64 centres at a time (the ring search of
// neighborhood.cpp, with the ball as a filter). Bit k of a vertex's masks
// stands for centre k of the batch. The radii are taken in increasing order;
// at radius index b, centre k's bit enters vertex u only from a neighbour that
// has it, and only if u is inside the ball B(p_k, r_b), tested when the bit
// arrives: so the vertices holding bit k are then N_{r_b}(k) plus k. A bit
// refused at radius b stays on the vertex (refused) and is tested again at
// the next radius, where the vertex enters if it is inside the larger ball
// (its neighbour inside the smaller one joins it to k), and the search goes on
// from there. A vertex first reached by centre k at radius index b adds its
// value to centre k's sums of b (then cumulated over b).
template <int W>
class BatchBall
{
public:
    static constexpr std::size_t kBatch = 64 * W;

    // \p r2: distinct squared radii, ascending.
    BatchBall(const Mesh& mesh, const Adjacency& adj, const std::vector<double>& values,
              const std::vector<double>& weights, const std::vector<double>& r2, bool with_sizes)
        : mesh_(mesh),
          adj_(adj),
          values_(values),
          weights_(weights),
          r2_(r2),
          nr_(r2.size()),
          sizes_(with_sizes),
          where_(mesh.n_vertices())
    {
        sum.resize(nr_ * kBatch);
        wsum.resize(nr_ * kBatch);
        count.resize(nr_ * kBatch);
    }

    // Fills sum, wsum and, if asked for, count ([radius index][centre],
    // cumulative over radii) for centres[0..nb). wsum > 0 only if a vertex
    // with a defined value was found (only those add to it).
    void run(const std::uint32_t* centres, std::size_t nb)
    {
        std::fill(sum.begin(), sum.end(), 0.0);
        std::fill(wsum.begin(), wsum.end(), 0.0);
        std::fill(count.begin(), count.end(), 0u);
        if (++stamp_ == 0) {
            std::fill(where_.begin(), where_.end(), Where{});
            stamp_ = 1;
        }
        n_slots_ = 0;
        // A sphere around the batch's centres: a vertex farther than (its
        // radius + the largest r) from its middle is in no ball.
        Vec3 mid = Vec3::Zero();
        for (std::size_t k = 0; k < nb; ++k) {
            const Vec3& p = mesh_.points[centres[k]];
            mid += p;
            cx_[k] = p.x();
            cy_[k] = p.y();
            cz_[k] = p.z();
        }
        mid /= double(nb);
        double spread = 0.0;
        for (std::size_t k = 0; k < nb; ++k) spread = std::max(spread, (mesh_.points[centres[k]] - mid).norm());
        mid_ = mid;
        const double reach = (spread + std::sqrt(r2_.back())) * (1.0 + 1e-9) + 1e-300;
        reach2_ = reach * reach;

        flist_.clear();
        for (std::size_t k = 0; k < nb; ++k) {
            const std::uint32_t s = slot(centres[k]);
            marks_[s].seen[k / 64] |= std::uint64_t(1) << (k % 64);
            marks_[s].frontier[k / 64] |= std::uint64_t(1) << (k % 64);
            flist_.push_back(s);
        }
        for (std::size_t b = 0; b < nr_; ++b) {
            if (b > 0) {
                // The bits refused at the radius before, tested again.
                flist_.clear();
                for (std::uint32_t s = 0; s < n_slots_; ++s) {
                    Marks& m = marks_[s];
                    std::uint64_t any = 0;
                    for (int w = 0; w < W; ++w) {
                        m.next[w] = m.refused[w];
                        m.refused[w] = 0;
                        any |= m.next[w];
                    }
                    if (any && enter(s, b)) flist_.push_back(s);
                }
            }
            expand(b);
        }
        for (std::size_t b = 1; b < nr_; ++b)
            for (std::size_t k = 0; k < kBatch; ++k) {
                const std::size_t i = b * kBatch + k, j = (b - 1) * kBatch + k;
                sum[i] += sum[j];
                wsum[i] += wsum[j];
                count[i] += count[j];
            }
    }

    std::vector<double> sum, wsum;
    std::vector<std::uint32_t> count;

private:
    static constexpr std::uint32_t kOut = std::numeric_limits<std::uint32_t>::max();
    struct Where
    {
        std::uint32_t stamp = 0;
        std::uint32_t slot = 0;
    };
    struct Marks
    {
        std::uint64_t seen[W];      // centres that reached the vertex
        std::uint64_t next[W];      // offered by a neighbour, to be tested
        std::uint64_t frontier[W];  // entered at the last round
        std::uint64_t refused[W];   // offered but outside the ball at this radius
    };

    // The slot of vertex v in this batch, kOut if it is in no ball.
    std::uint32_t slot(std::uint32_t v)
    {
        Where& at = where_[v];
        if (at.stamp == stamp_) return at.slot;
        at.stamp = stamp_;
        if ((mesh_.points[v] - mid_).squaredNorm() > reach2_) return at.slot = kOut;
        const std::uint32_t s = n_slots_++;
        if (s >= vertex_.size()) {
            const std::size_t cap = std::max<std::size_t>(1024, 2 * vertex_.size());
            vertex_.resize(cap);
            marks_.resize(cap);
            nlist_.resize(cap + 1);  // expand() lists each slot at most once per round
        }
        vertex_[s] = v;
        marks_[s] = Marks{};
        return at.slot = s;
    }

    // Tests the bits offered to slot s (next) against the balls of radius
    // index b: those inside enter (seen, frontier, the sums of b), the others
    // are refused. True if any entered.
    bool enter(std::uint32_t s, std::size_t b)
    {
        Marks& m = marks_[s];
        const std::uint32_t v = vertex_[s];
        const Vec3& p = mesh_.points[v];
        const double px = p.x(), py = p.y(), pz = p.z(), r2 = r2_[b];
        const double x = values_[v];
        const bool has = !std::isnan(x);
        const double wt = weights_[v], wx = wt * x;
        double* bsum = &sum[b * kBatch];
        double* bwsum = &wsum[b * kBatch];
        std::uint32_t* bcount = &count[b * kBatch];
        std::uint64_t any = 0;
        for (int w = 0; w < W; ++w) {
            const std::uint64_t offered = m.next[w];
            std::uint64_t bits = offered, in = 0;
            m.next[w] = 0;
            const std::size_t base = 64 * std::size_t(w);
            while (bits) {
                const int i = __builtin_ctzll(bits);
                bits &= bits - 1;
                const std::size_t k = base + std::size_t(i);
                // The expression of ball_patch() and of the tests' brute force.
                const double dx = px - cx_[k], dy = py - cy_[k], dz = pz - cz_[k];
                if (dx * dx + dy * dy + dz * dz > r2) continue;
                in |= std::uint64_t(1) << i;
                if (sizes_) ++bcount[k];
                if (has) {
                    bsum[k] += wx;
                    bwsum[k] += wt;
                }
            }
            m.refused[w] |= offered & ~in;
            m.seen[w] |= in;
            m.frontier[w] = in;
            any |= in;
        }
        return any != 0;
    }

    // Breadth-first rounds at radius index b from flist_ (slots with their
    // frontier bits) until no bit moves.
    void expand(std::size_t b)
    {
        while (!flist_.empty()) {
            std::size_t n_new = 0;
            for (const std::uint32_t s : flist_) {
                std::uint64_t f[W];
                for (int w = 0; w < W; ++w) {
                    f[w] = marks_[s].frontier[w];
                    marks_[s].frontier[w] = 0;
                }
                const std::uint32_t v = vertex_[s];
                for (const std::uint32_t* it = adj_.begin(v); it != adj_.end(v); ++it) {
                    const std::uint32_t t = slot(*it);
                    if (t == kOut) continue;  // in no ball of any radius
                    Marks& m = marks_[t];
                    // Branch-free: the list grows by one exactly when the
                    // slot gets its first offer of this round.
                    bool first;
#if defined(__SSE2__)
                    if constexpr (W == 2) {
                        const __m128i fv = _mm_loadu_si128(reinterpret_cast<const __m128i*>(f));
                        const __m128i old = _mm_loadu_si128(reinterpret_cast<const __m128i*>(m.next));
                        const __m128i closed =
                            _mm_or_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(m.seen)),
                                         _mm_loadu_si128(reinterpret_cast<const __m128i*>(m.refused)));
                        const __m128i now = _mm_or_si128(old, _mm_andnot_si128(closed, fv));
                        _mm_storeu_si128(reinterpret_cast<__m128i*>(m.next), now);
                        const __m128i zero = _mm_setzero_si128();
                        const auto zold = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(old, zero)));
                        const auto znow = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(now, zero)));
                        // Without a branch (as in the ring search): zold == 0xFFFF and znow != 0xFFFF.
                        first = (((zold + 1) & (0x1FFFEu - znow)) >> 16) != 0;
                    } else
#endif
                    {
                        std::uint64_t old_any = 0, add_any = 0;
                        for (int w = 0; w < W; ++w) {
                            const std::uint64_t add = f[w] & ~m.seen[w] & ~m.refused[w];
                            old_any |= m.next[w];
                            add_any |= add;
                            m.next[w] |= add;
                        }
                        first = (old_any == 0) & (add_any != 0);
                    }
                    nlist_[n_new] = t;
                    n_new += first;
                }
            }
            flist_.clear();
            for (std::size_t q = 0; q < n_new; ++q)
                if (enter(nlist_[q], b)) flist_.push_back(nlist_[q]);
        }
    }

    const Mesh& mesh_;
    const Adjacency& adj_;
    const std::vector<double>& values_;
    const std::vector<double>& weights_;
    const std::vector<double>& r2_;
    const std::size_t nr_;
    const bool sizes_;
    std::vector<Where> where_;
    std::uint32_t stamp_ = 0;
    std::uint32_t n_slots_ = 0;
    Vec3 mid_ = Vec3::Zero();
    double reach2_ = 0.0;
    double cx_[kBatch] = {}, cy_[kBatch] = {}, cz_[kBatch] = {};
    std::vector<std::uint32_t> vertex_;
    std::vector<Marks> marks_;
    std::vector<std::uint32_t> flist_, nlist_;
};

constexpr int kBallWords = 2;

using detail::clustered_order;
using detail::morton_order;

void check_sizes(const Mesh& mesh, const Adjacency& adj)
{
    if (adj.size() != mesh.n_vertices())
        throw InvalidArgumentError(
            fmt::format("ball search: adjacency of {} vertices for a mesh of {}", adj.size(), mesh.n_vertices()));
}

}  // namespace

void check_ball_work(const Mesh& mesh, const Adjacency& adj, const std::vector<double>& radii)
{
    if (radii.empty() || mesh.n_vertices() <= kMaxMeanBallVertices) return;  // no ball can hold more
    const double r = *std::max_element(radii.begin(), radii.end());
    const std::size_t n = mesh.n_vertices(), centres = 64;
    double total = 0.0;
    for (std::size_t i = 0; i < centres; ++i) {
        check_cancelled(current_progress());
        total += double(ball_patch(mesh, adj, i * n / centres, r).size());
    }
    const double mean = total / double(centres);
    if (mean > double(kMaxMeanBallVertices))
        throw OptionError(
            "profile.radii",
            fmt::format(
                "radius {} holds about {:.0f} of the {} vertices per ball, above the limit of {} (the work grows "
                "as vertices x ball size): give a smaller radius",
                r, mean, n, kMaxMeanBallVertices));
}

std::vector<std::uint32_t> ball_patch(const Mesh& mesh, const Adjacency& adj, std::size_t centre, double radius)
{
    check_radii({radius});
    check_sizes(mesh, adj);
    if (centre >= mesh.n_vertices())
        throw InvalidArgumentError(fmt::format("ball_patch: centre {} of {} vertices", centre, mesh.n_vertices()));
    const auto found = bfs_patch(mesh, adj, std::uint32_t(centre), radius * radius);
    std::vector<std::uint32_t> ids(found.begin() + 1, found.end());
    std::sort(ids.begin(), ids.end());
    return ids;
}

BallMeans ball_means(const Mesh& mesh, const Adjacency& adj, const std::vector<double>& values,
                     const std::vector<double>& weights, const std::vector<double>& radii, bool with_sizes)
{
    return ball_means(MeshData(mesh), adj, values, weights, radii, with_sizes);
}

BallMeans ball_means(const MeshData& data, const Adjacency& adj, const std::vector<double>& values,
                     const std::vector<double>& weights, const std::vector<double>& radii, bool with_sizes)
{
    const Mesh& mesh = data.mesh();
    check_radii(radii);
    check_sizes(mesh, adj);
    const std::size_t n = mesh.n_vertices();
    if (values.size() != n || weights.size() != n)
        throw InvalidArgumentError(
            fmt::format("ball_means: {} values and {} weights for {} vertices", values.size(), weights.size(), n));
    BallMeans m;
    m.radii = radii;
    const std::size_t nr = radii.size();
    m.mean.assign(nr, std::vector<double>(n, std::numeric_limits<double>::quiet_NaN()));
    if (with_sizes) m.size.assign(nr, std::vector<std::uint32_t>(n, 0));
    if (nr == 0 || n == 0) return m;

    // Distinct squared radii, ascending; each requested radius maps to one.
    std::vector<double> r2;
    for (double r : radii) r2.push_back(r * r);
    std::sort(r2.begin(), r2.end());
    r2.erase(std::unique(r2.begin(), r2.end()), r2.end());
    std::vector<std::size_t> slot(nr);
    for (std::size_t k = 0; k < nr; ++k)
        slot[k] = std::size_t(std::lower_bound(r2.begin(), r2.end(), radii[k] * radii[k]) - r2.begin());

    // A copy of the mesh renumbered in Morton order, so that nearby vertices
    // share cache lines.
    const std::vector<std::uint32_t> order = morton_order(mesh, data.box());
    std::vector<std::uint32_t> rank(n);
    for (std::size_t i = 0; i < n; ++i) rank[order[i]] = std::uint32_t(i);
    Mesh pm;
    pm.points.resize(n);
    Adjacency padj;
    padj.offset.resize(n + 1, 0);
    padj.index.resize(adj.index.size());
    std::vector<double> pvalues(n), pweights(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t o = order[i];
        pm.points[i] = mesh.points[o];
        pvalues[i] = values[o];
        pweights[i] = weights[o];
        padj.offset[i + 1] = padj.offset[i] + std::uint32_t(adj.degree(o));
        std::uint32_t* out = padj.index.data() + padj.offset[i];
        for (const std::uint32_t* it = adj.begin(o); it != adj.end(o); ++it) *out++ = rank[*it];
    }

    // Centres with a defined value in compact batches (as for rings).
    constexpr std::size_t kBatch = BatchBall<kBallWords>::kBatch;
    // pm's points are mesh's, permuted: the same bounding box.
    const std::vector<std::uint32_t> centres = clustered_order(morton_order(pm, data.box()), padj, pvalues, kBatch);
    const std::size_t n_batches = (centres.size() + kBatch - 1) / kBatch;

    detail::StageProgress stage("metric levels", n_batches);
#pragma omp parallel
    {
        BatchBall<kBallWords> search(pm, padj, pvalues, pweights, r2, with_sizes);
#pragma omp for schedule(dynamic, 1)
        for (std::ptrdiff_t ib = 0; ib < std::ptrdiff_t(n_batches); ++ib) {
            if (!stage.tick()) continue;
            const std::size_t first = std::size_t(ib) * kBatch;
            const std::size_t nb = std::min(kBatch, centres.size() - first);
            search.run(centres.data() + first, nb);
            for (std::size_t k = 0; k < nr; ++k)
                for (std::size_t c = 0; c < nb; ++c) {
                    const std::size_t i = slot[k] * kBatch + c;
                    const std::uint32_t v = order[centres[first + c]];
                    if (search.wsum[i] > 0.0) m.mean[k][v] = search.sum[i] / search.wsum[i];
                    if (with_sizes) m.size[k][v] = search.count[i];
                }
        }
    }
    stage.finish();
    return m;
}

LevelRoughness weighted_level_roughness(double radius, const std::vector<double>& D, const std::vector<double>& weights,
                                        double outlier_fraction)
{
    if (D.size() != weights.size())
        throw InvalidArgumentError(
            fmt::format("weighted_level_roughness: {} values and {} weights", D.size(), weights.size()));
    LevelRoughness r;
    r.level = 0;
    r.radius = radius;
    std::vector<double> contrib;
    contrib.reserve(D.size());
    double total = 0.0, wtotal = 0.0;
    // Plain sums in vertex order: deterministic.
    for (std::size_t i = 0; i < D.size(); ++i) {
        if (std::isnan(D[i])) continue;
        const double c = weights[i] * D[i] * D[i];
        contrib.push_back(c);
        total += c;
        wtotal += weights[i];
    }
    r.vertices_used = contrib.size();
    if (contrib.empty() || !(wtotal > 0.0)) return r;
    r.sigma = std::sqrt(total / wtotal);
    if (total > 0.0) {
        const auto k = std::max<std::size_t>(1, std::size_t(std::ceil(outlier_fraction * double(contrib.size()))));
        // The k vertices of largest |D| (ties by id), then their share.
        std::vector<std::uint32_t> ids;
        ids.reserve(contrib.size());
        for (std::size_t i = 0; i < D.size(); ++i)
            if (!std::isnan(D[i])) ids.push_back(std::uint32_t(i));
        auto worse = [&](std::uint32_t a, std::uint32_t b) {
            const double da = std::abs(D[a]), db = std::abs(D[b]);
            return da != db ? da > db : a < b;
        };
        const std::size_t m = std::max<std::size_t>(k, std::min<std::size_t>(10, ids.size()));
        std::partial_sort(ids.begin(), ids.begin() + std::ptrdiff_t(m), ids.end(), worse);
        double top = 0.0;
        for (std::size_t i = 0; i < k; ++i) top += weights[ids[i]] * D[ids[i]] * D[ids[i]];
        r.top_share = top / total;
        r.worst_vertices.assign(ids.begin(), ids.begin() + std::ptrdiff_t(std::min<std::size_t>(10, ids.size())));
    } else {
        for (std::size_t i = 0; i < D.size() && r.worst_vertices.size() < 10; ++i)
            if (!std::isnan(D[i])) r.worst_vertices.push_back(std::uint32_t(i));
    }
    return r;
}

}  // namespace meshdiff
