#include "meshdiff/neighborhood.h"

#include "meshdiff/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>

namespace meshdiff {

std::vector<int> ring_distances(const Adjacency& adj, std::size_t source, int max_level)
{
    std::vector<int> dist(adj.size(), -1);
    if (source >= adj.size()) throw InvalidArgumentError("ring_distances: source out of range");
    std::deque<std::uint32_t> queue{std::uint32_t(source)};
    dist[source] = 0;
    while (!queue.empty()) {
        const auto v = queue.front();
        queue.pop_front();
        if (dist[v] == max_level) continue;
        for (auto it = adj.begin(v); it != adj.end(v); ++it)
            if (dist[*it] < 0) {
                dist[*it] = dist[v] + 1;
                queue.push_back(*it);
            }
    }
    return dist;
}

namespace {

std::uint64_t spread_bits(std::uint64_t x)
{
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
}

// Vertices sorted along a Morton curve of their positions.
std::vector<std::uint32_t> morton_order(const Mesh& mesh)
{
    const auto box = bounding_box(mesh);
    const Vec3 ext = (box.max - box.min).cwiseMax(Vec3::Constant(1e-300));
    const double cells = double((1u << 21) - 1);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(mesh.n_vertices());
    for (std::size_t i = 0; i < mesh.n_vertices(); ++i) {
        const Vec3 q = (mesh.points[i] - box.min).cwiseQuotient(ext) * cells;
        keys[i] = {spread_bits(std::uint64_t(q.x())) | spread_bits(std::uint64_t(q.y())) << 1 |
                       spread_bits(std::uint64_t(q.z())) << 2,
                   std::uint32_t(i)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<std::uint32_t> order(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].second;
    return order;
}

struct BfsScratch
{
    std::vector<std::uint64_t> seen, frontier, next;
    std::vector<std::uint32_t> flist, nlist, touched;
    std::vector<double> sum;           // [level][64], level 1..Lmax
    std::vector<std::uint32_t> count;  // defined values
    std::vector<std::uint32_t> size;   // all vertices
};

}  // namespace

DiskMeans disk_means(const Mesh& mesh, const Adjacency& adj, const std::vector<double>& values,
                     const std::vector<int>& levels, bool with_sizes)
{
    const std::size_t n = adj.size();
    if (values.size() != n || mesh.n_vertices() != n)
        throw InvalidArgumentError("disk_means: values, adjacency and mesh sizes differ");
    for (int l : levels)
        if (l < 1) throw InvalidArgumentError(fmt::format("disk_means: level {} is < 1", l));
    DiskMeans out;
    out.levels = levels;
    out.mean.assign(levels.size(), std::vector<double>(n, std::numeric_limits<double>::quiet_NaN()));
    if (with_sizes) out.size.assign(levels.size(), std::vector<std::uint32_t>(n, 0));
    if (levels.empty() || n == 0) return out;
    const int lmax = *std::max_element(levels.begin(), levels.end());

    // Centres with a defined value, in Morton order, cut into batches of 64.
    std::vector<std::uint32_t> centres;
    centres.reserve(n);
    for (auto v : morton_order(mesh))
        if (!std::isnan(values[v])) centres.push_back(v);
    const std::size_t n_batches = (centres.size() + 63) / 64;

#pragma omp parallel
    {
        BfsScratch s;
        s.seen.assign(n, 0);
        s.frontier.assign(n, 0);
        s.next.assign(n, 0);
        s.sum.resize(std::size_t(lmax + 1) * 64);
        s.count.resize(std::size_t(lmax + 1) * 64);
        s.size.resize(std::size_t(lmax + 1) * 64);
#pragma omp for schedule(dynamic, 4)
        for (std::ptrdiff_t ib = 0; ib < std::ptrdiff_t(n_batches); ++ib) {
            const std::size_t first = std::size_t(ib) * 64;
            const std::size_t nb = std::min<std::size_t>(64, centres.size() - first);
            std::fill(s.sum.begin(), s.sum.end(), 0.0);
            std::fill(s.count.begin(), s.count.end(), 0u);
            std::fill(s.size.begin(), s.size.end(), 0u);
            s.flist.clear();
            s.touched.clear();
            for (std::size_t k = 0; k < nb; ++k) {
                const auto c = centres[first + k];
                s.seen[c] = s.frontier[c] = std::uint64_t(1) << k;
                s.flist.push_back(c);
                s.touched.push_back(c);
            }
            for (int level = 1; level <= lmax && !s.flist.empty(); ++level) {
                s.nlist.clear();
                for (auto v : s.flist) {
                    const std::uint64_t f = s.frontier[v];
                    for (auto it = adj.begin(v); it != adj.end(v); ++it) {
                        const std::uint64_t add = f & ~s.seen[*it];
                        if (!add) continue;
                        if (!s.next[*it]) s.nlist.push_back(*it);
                        s.next[*it] |= add;
                    }
                }
                for (auto v : s.flist) s.frontier[v] = 0;
                double* lsum = &s.sum[std::size_t(level) * 64];
                std::uint32_t* lcount = &s.count[std::size_t(level) * 64];
                std::uint32_t* lsize = &s.size[std::size_t(level) * 64];
                for (auto w : s.nlist) {
                    std::uint64_t bits = s.next[w];
                    s.next[w] = 0;
                    if (!s.seen[w]) s.touched.push_back(w);
                    s.seen[w] |= bits;
                    s.frontier[w] = bits;
                    const double val = values[w];
                    const bool defined = !std::isnan(val);
                    while (bits) {
                        const int b = __builtin_ctzll(bits);
                        bits &= bits - 1;
                        ++lsize[b];
                        if (defined) {
                            lsum[b] += val;
                            ++lcount[b];
                        }
                    }
                }
                std::swap(s.flist, s.nlist);
            }
            for (auto v : s.flist) s.frontier[v] = 0;
            for (auto v : s.touched) s.seen[v] = 0;
            // Cumulative sums over levels, then the requested means.
            for (int level = 2; level <= lmax; ++level)
                for (std::size_t k = 0; k < 64; ++k) {
                    s.sum[std::size_t(level) * 64 + k] += s.sum[std::size_t(level - 1) * 64 + k];
                    s.count[std::size_t(level) * 64 + k] += s.count[std::size_t(level - 1) * 64 + k];
                    s.size[std::size_t(level) * 64 + k] += s.size[std::size_t(level - 1) * 64 + k];
                }
            for (std::size_t li = 0; li < levels.size(); ++li) {
                const std::size_t base = std::size_t(levels[li]) * 64;
                for (std::size_t k = 0; k < nb; ++k) {
                    const auto c = centres[first + k];
                    const auto cnt = s.count[base + k];
                    if (cnt > 0) out.mean[li][c] = s.sum[base + k] / double(cnt);
                    if (with_sizes) out.size[li][c] = s.size[base + k];
                }
            }
        }
    }
    return out;
}

}  // namespace meshdiff
