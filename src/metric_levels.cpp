#include "meshdiff/metric_levels.h"

#include "meshdiff/error.h"

#include "detail/morton.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace meshdiff {

std::vector<double> default_radii()
{
    std::vector<double> r;
    for (int k = 0; k <= 6; ++k) r.push_back(0.0125 * std::pow(2.0, 0.5 * k));
    return r;
}

void check_radii(const std::vector<double>& radii)
{
    for (double r : radii)
        if (!(r > 0.0) || !std::isfinite(r))
            throw InvalidArgumentError(fmt::format("profile: radius {} must be finite and > 0", r));
}

std::vector<double> vertex_areas(const Mesh& mesh)
{
    std::vector<double> a(mesh.n_vertices(), 0.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const Face& t = mesh.faces[f];
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
        const double third = face_cross(mesh, f).norm() / 6.0;  // |cross| / 2 / 3
        if (!(third > 0.0) || !std::isfinite(third)) continue;
        for (int k = 0; k < 3; ++k) a[std::size_t(t[std::size_t(k)])] += third;
    }
    return a;
}

namespace {

// One centre's ball search, with buffers reused across centres (one per thread).
class BallSearch
{
public:
    BallSearch(const Mesh& mesh, const Adjacency& adj)
        : mesh_(mesh), adj_(adj), seen_(mesh.n_vertices()), b2_(mesh.n_vertices(), 0.0)
    {}

    // Finds the vertices joined to \p v inside B(p_v, sqrt(r2max)), in
    // breadth-first order (v first), and for each the smallest squared radius
    // whose ball joins it to v (key()).
    void run(std::uint32_t v, double r2max)
    {
        ++current_;
        found_.clear();
        const Vec3& c = mesh_.points[v];
        seen_[v] = {0.0, current_};
        found_.push_back(v);
        bool exact_needed = false;
        for (std::size_t q = 0; q < found_.size(); ++q) {
            const std::uint32_t u = found_[q];
            const double du = seen_[u].d2;
            bool lower = false;
            for (const std::uint32_t* it = adj_.begin(u); it != adj_.end(u); ++it) {
                const std::uint32_t w = *it;
                Seen& sw = seen_[w];
                if (sw.stamp != current_) {
                    sw.stamp = current_;
                    sw.d2 = (mesh_.points[w] - c).squaredNorm();
                    if (sw.d2 <= r2max) found_.push_back(w);
                }
                if (sw.d2 < du) lower = true;
            }
            // A vertex with no neighbour nearer to v may be joined to v only
            // through vertices farther than itself: its smallest radius is
            // then not its distance.
            if (q > 0 && !lower) exact_needed = true;
        }
        key_.resize(found_.size());
        if (!exact_needed) {
            for (std::size_t q = 0; q < found_.size(); ++q) key_[q] = seen_[found_[q]].d2;
            return;
        }
        // Minimax path (Dijkstra on the largest squared distance along the
        // path), restricted to the vertices found.
        const double inf = std::numeric_limits<double>::infinity();
        for (std::uint32_t u : found_) b2_[u] = inf;
        b2_[v] = 0.0;
        using Item = std::pair<double, std::uint32_t>;
        std::priority_queue<Item, std::vector<Item>, std::greater<>> heap;
        heap.emplace(0.0, v);
        while (!heap.empty()) {
            const auto [b, u] = heap.top();
            heap.pop();
            if (b > b2_[u]) continue;
            for (const std::uint32_t* it = adj_.begin(u); it != adj_.end(u); ++it) {
                const std::uint32_t w = *it;
                if (seen_[w].stamp != current_ || seen_[w].d2 > r2max) continue;
                const double cand = std::max(b, seen_[w].d2);
                if (cand < b2_[w]) {
                    b2_[w] = cand;
                    heap.emplace(cand, w);
                }
            }
        }
        for (std::size_t q = 0; q < found_.size(); ++q) key_[q] = b2_[found_[q]];
    }

    const std::vector<std::uint32_t>& found() const { return found_; }
    const std::vector<double>& key() const { return key_; }

private:
    const Mesh& mesh_;
    const Adjacency& adj_;
    struct Seen
    {
        double d2 = 0.0;  // squared distance to the centre
        std::uint32_t stamp = 0;
    };
    std::vector<Seen> seen_;
    std::vector<double> b2_;
    std::uint32_t current_ = 0;
    std::vector<std::uint32_t> found_;
    std::vector<double> key_;
};

using detail::morton_order;

void check_sizes(const Mesh& mesh, const Adjacency& adj)
{
    if (adj.size() != mesh.n_vertices())
        throw InvalidArgumentError(
            fmt::format("ball search: adjacency of {} vertices for a mesh of {}", adj.size(), mesh.n_vertices()));
}

}  // namespace

std::vector<std::uint32_t> ball_patch(const Mesh& mesh, const Adjacency& adj, std::size_t centre, double radius)
{
    check_radii({radius});
    check_sizes(mesh, adj);
    if (centre >= mesh.n_vertices())
        throw InvalidArgumentError(fmt::format("ball_patch: centre {} of {} vertices", centre, mesh.n_vertices()));
    BallSearch s(mesh, adj);
    s.run(std::uint32_t(centre), radius * radius);
    std::vector<std::uint32_t> ids(s.found().begin() + 1, s.found().end());
    std::sort(ids.begin(), ids.end());
    return ids;
}

BallMeans ball_means(const Mesh& mesh, const Adjacency& adj, const std::vector<double>& values,
                     const std::vector<double>& weights, const std::vector<double>& radii, bool with_sizes)
{
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
    const std::size_t nb = r2.size();
    const double r2max = r2.back();

    // A copy of the mesh renumbered in Morton order, so that the balls of
    // consecutive centres share cache lines. Each vertex keeps the order of
    // its neighbour list: the search visits the same vertices in the same
    // order as on the original numbering, so the sums are the same.
    const std::vector<std::uint32_t> order = morton_order(mesh);
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

#pragma omp parallel
    {
        BallSearch search(pm, padj);
        std::vector<double> sum(nb), wsum(nb);
        std::vector<std::uint32_t> defined(nb), count(nb);
#pragma omp for schedule(dynamic, 64)
        for (std::ptrdiff_t iv = 0; iv < std::ptrdiff_t(n); ++iv) {
            const auto v = std::uint32_t(iv);
            if (std::isnan(pvalues[v])) continue;
            search.run(v, r2max);
            std::fill(sum.begin(), sum.end(), 0.0);
            std::fill(wsum.begin(), wsum.end(), 0.0);
            std::fill(defined.begin(), defined.end(), 0);
            std::fill(count.begin(), count.end(), 0);
            const auto& found = search.found();
            const auto& key = search.key();
            // In breadth-first order: a fixed order for a given mesh.
            for (std::size_t q = 1; q < found.size(); ++q) {
                const auto b = std::size_t(std::lower_bound(r2.begin(), r2.end(), key[q]) - r2.begin());
                ++count[b];
                const double x = pvalues[found[q]];
                if (std::isnan(x)) continue;
                const double w = pweights[found[q]];
                sum[b] += w * x;
                wsum[b] += w;
                ++defined[b];
            }
            for (std::size_t b = 1; b < nb; ++b) {
                sum[b] += sum[b - 1];
                wsum[b] += wsum[b - 1];
                defined[b] += defined[b - 1];
                count[b] += count[b - 1];
            }
            for (std::size_t k = 0; k < nr; ++k) {
                const std::size_t b = slot[k];
                if (defined[b] > 0 && wsum[b] > 0.0) m.mean[k][order[v]] = sum[b] / wsum[b];
                if (with_sizes) m.size[k][order[v]] = count[b];
            }
        }
    }
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
