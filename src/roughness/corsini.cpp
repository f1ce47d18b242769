#include "meshdiff/roughness/corsini.h"

#include "meshdiff/core/topology.h"
#include "meshdiff/error.h"
#include "meshdiff/roughness/metric_levels.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace meshdiff {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The dihedral angle of each unique edge (sorted by (a, b)), NaN where none,
// with the edge ends.
struct DihedralEdges
{
    std::vector<std::uint32_t> a, b;
    std::vector<double> theta;
};

DihedralEdges dihedral_edges(const Mesh& mesh)
{
    const std::vector<char> degenerate = degenerate_face_mask(mesh);
    std::vector<Vec3> normal(mesh.n_faces(), Vec3::Zero());
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        if (!degenerate[f]) normal[f] = face_cross(mesh, f).normalized();
    const EdgeMap edges = edge_map(mesh);
    DihedralEdges e;
    e.a.reserve(edges.size());
    e.b.reserve(edges.size());
    e.theta.reserve(edges.size());
    for (std::size_t k = 0; k < edges.size(); ++k) {
        double theta = kNaN;
        // A repeated face (the same face twice on one edge) is not a pair.
        if (edges.count(k) == 2) {
            const std::uint32_t f = edges.begin(k)[0] / 3, g = edges.begin(k)[1] / 3;
            if (f != g && !degenerate[f] && !degenerate[g]) {
                const Vec3& n1 = normal[f];
                const Vec3& n2 = normal[g];
                theta = std::atan2(n1.cross(n2).norm(), n1.dot(n2));
            }
        }
        e.a.push_back(edges.edges[k].a);
        e.b.push_back(edges.edges[k].b);
        e.theta.push_back(theta);
    }
    return e;
}

// Variance from the sums of n values x (shifted), their sum and their sum of
// squares; NaN when too few.
double variance(double n, double s1, double s2, bool unbiased)
{
    if (n < (unbiased ? 2.0 : 1.0)) return kNaN;
    const double mean = s1 / n;
    const double ss = std::max(0.0, s2 - n * mean * mean);
    return ss / (unbiased ? n - 1.0 : n);
}

}  // namespace

void validate(const CorsiniOptions& o)
{
    if (o.levels.size() > kMaxLevels)
        throw OptionError("profile.levels", fmt::format("more than the limit of {} levels", kMaxLevels));
    for (int L : o.levels)
        if (L < 1 || L > kMaxLevel)
            throw OptionError("profile.levels", fmt::format("level {} is out of 1..{}", L, kMaxLevel));
    if (o.levels.empty() && !o.global)
        throw OptionError("profile.levels", "no level to compute: no ring level and no {profile.global} level");
}

std::vector<double> dihedral_angles(const Mesh& mesh)
{
    return dihedral_edges(mesh).theta;
}

namespace {

// The number, mean and maximum of the dihedral angles (the edges that have one).
void summarise_dihedrals(const DihedralEdges& e, CorsiniProfile& p)
{
    double sum = 0.0;
    for (double t : e.theta)
        if (!std::isnan(t)) {
            ++p.dihedral_edges;
            sum += t;
            p.max_dihedral = std::max(p.max_dihedral, t);
        }
    p.mean_dihedral = p.dihedral_edges ? sum / double(p.dihedral_edges) : 0.0;
}

// The global level: the variance of all the dihedral angles.
void global_level(const DihedralEdges& e, double shift, std::size_t n, const CorsiniOptions& options, CorsiniProfile& p)
{
    p.has_global = true;
    double s1 = 0.0, s2 = 0.0;
    for (double t : e.theta)
        if (!std::isnan(t)) {
            s1 += t - shift;
            s2 += (t - shift) * (t - shift);
        }
    const double v = variance(double(p.dihedral_edges), s1, s2, options.unbiased);
    p.global.level = 0;
    p.global.roughness = std::isnan(v) ? 0.0 : v;
    p.global.vertices_used = std::isnan(v) ? 0 : n;
    p.global.no_neighborhood = std::isnan(v) ? n : 0;
    p.global.mean_edges = std::isnan(v) ? 0.0 : double(p.dihedral_edges);
}

// The angle of each adjacency slot (NaN where the edge has none).
std::vector<double> slot_angles(const Adjacency& adj, const DihedralEdges& e, double shift)
{
    std::vector<double> slot(adj.index.size(), kNaN);
    auto slot_of = [&](std::uint32_t from, std::uint32_t to) {
        return std::size_t(std::lower_bound(adj.begin(from), adj.end(from), to) - adj.index.data());
    };
    for (std::size_t k = 0; k < e.theta.size(); ++k)
        if (!std::isnan(e.theta[k])) {
            slot[slot_of(e.a[k], e.b[k])] = e.theta[k] - shift;
            slot[slot_of(e.b[k], e.a[k])] = e.theta[k] - shift;
        }
    return slot;
}

// The sums about vertex v: c, s1 and s2 (index d) over the edges within
// distance d of v, from a breadth-first search to max_level. dist (all -1)
// and queue are the caller's scratch; dist is left all -1 again.
void ring_sums(std::uint32_t v, const Adjacency& adj, const std::vector<double>& slot, int max_level,
               std::vector<int>& dist, std::vector<std::uint32_t>& queue, std::vector<double>& c,
               std::vector<double>& s1, std::vector<double>& s2)
{
    std::fill(c.begin(), c.end(), 0.0);
    std::fill(s1.begin(), s1.end(), 0.0);
    std::fill(s2.begin(), s2.end(), 0.0);
    queue.clear();
    queue.push_back(v);
    dist[v] = 0;
    // Breadth-first search to max_level. Each edge within the disk is
    // counted once, at the end processed last: its farther end (by
    // distance, then by id), so under the distance of that end.
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::uint32_t u = queue[head];
        const int du = dist[u];
        for (auto it = adj.begin(u); it != adj.end(u); ++it) {
            const std::uint32_t w = *it;
            const int dw = dist[w];
            if (dw < 0) {
                if (du < max_level) {
                    dist[w] = du + 1;
                    queue.push_back(w);
                }
                continue;
            }
            if (dw < du || (dw == du && w < u)) {
                const double t = slot[std::size_t(it - adj.index.data())];
                if (std::isnan(t)) continue;
                c[std::size_t(du)] += 1.0;
                s1[std::size_t(du)] += t;
                s2[std::size_t(du)] += t * t;
            }
        }
    }
    for (std::uint32_t u : queue) dist[u] = -1;
    for (std::size_t d = 1; d < c.size(); ++d) {
        c[d] += c[d - 1];
        s1[d] += s1[d - 1];
        s2[d] += s2[d - 1];
    }
}

// One ring level from R_L(v) and the angle counts of its vertices: the
// area-weighted mean of R_L over the vertices that have one.
CorsiniLevel ring_level(int level, const std::vector<double>& R, const std::vector<double>& count,
                        const std::vector<double>& area)
{
    const std::size_t n = R.size();
    CorsiniLevel l;
    l.level = level;
    double num = 0.0, den = 0.0, edges = 0.0;
    for (std::size_t v = 0; v < n; ++v) {
        if (std::isnan(R[v])) {
            ++l.no_neighborhood;
            continue;
        }
        ++l.vertices_used;
        num += area[v] * R[v];
        den += area[v];
        edges += count[v];
    }
    l.roughness = den > 0.0 ? num / den : 0.0;
    l.mean_edges = l.vertices_used ? edges / double(l.vertices_used) : 0.0;
    return l;
}

}  // namespace

CorsiniProfile corsini_profile(const Mesh& mesh, const CorsiniOptions& options)
{
    validate(options);
    const std::size_t n = mesh.n_vertices();
    CorsiniProfile p;
    p.options = options;
    p.vertices = n;
    const DihedralEdges e = dihedral_edges(mesh);
    p.edges = e.theta.size();
    summarise_dihedrals(e, p);
    // Angles are summed about their mean, so that the variances do not
    // cancel digits.
    const double shift = p.mean_dihedral;

    if (options.global) global_level(e, shift, n, options, p);
    if (options.levels.empty()) return p;

    const Adjacency adj = vertex_adjacency(mesh);
    const std::vector<double> slot = slot_angles(adj, e, shift);

    const int max_level = *std::max_element(options.levels.begin(), options.levels.end());
    const std::size_t nl = options.levels.size();
    // Per vertex and requested level: R_L(v) and the number of angles.
    std::vector<std::vector<double>> R(nl, std::vector<double>(n, kNaN));
    std::vector<std::vector<double>> count(nl, std::vector<double>(n, 0.0));
#pragma omp parallel
    {
        std::vector<int> dist(n, -1);
        std::vector<std::uint32_t> queue;
        // Sums over the edges whose farther end is at distance d (index d).
        std::vector<double> c(std::size_t(max_level) + 1), s1(c.size()), s2(c.size());
#pragma omp for schedule(dynamic, 256)
        for (std::ptrdiff_t iv = 0; iv < std::ptrdiff_t(n); ++iv) {
            const auto v = std::uint32_t(iv);
            ring_sums(v, adj, slot, max_level, dist, queue, c, s1, s2);
            for (std::size_t k = 0; k < nl; ++k) {
                const auto L = std::size_t(options.levels[k]);
                R[k][v] = variance(c[L], s1[L], s2[L], options.unbiased);
                count[k][v] = c[L];
            }
        }
    }

    const std::vector<double> area = vertex_areas(mesh);
    double total = 0.0;
    for (std::size_t k = 0; k < nl; ++k) {
        const CorsiniLevel l = ring_level(options.levels[k], R[k], count[k], area);
        total += l.roughness;
        p.levels.push_back(l);
    }
    p.multiscale = total / double(nl);
    if (options.keep_vertex_data) p.R = std::move(R);
    return p;
}

namespace {
LevelValue corsini_value(const CorsiniLevel& l)
{
    return {l.level, 0.0, l.roughness, l.vertices_used > 0};
}
}  // namespace

CorsiniDistance corsini_distance(const CorsiniProfile& a, const CorsiniProfile& b, double k)
{
    if (!(k > 0.0) || !std::isfinite(k)) throw OptionError("k", fmt::format("{} must be finite and > 0", k));
    auto values = [](const CorsiniProfile& p) {
        std::vector<LevelValue> v;
        for (const auto& l : p.levels) v.push_back(corsini_value(l));
        return v;
    };
    CorsiniDistance d;
    d.k = k;
    d.levels = level_distances(values(a), values(b), k);
    if (a.has_global && b.has_global) {
        d.has_global = true;
        d.global = level_distance(corsini_value(a.global), corsini_value(b.global), k);
    }
    if (!a.levels.empty() && a.options.levels == b.options.levels) {
        d.has_multiscale = true;
        d.multiscale = level_distance(0, a.multiscale, b.multiscale, k);
    }
    return d;
}

}  // namespace meshdiff
