#include "meshdiff/hausdorff.h"

#include "meshdiff/error.h"
#include "meshdiff/point_triangle.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <vector>

namespace meshdiff {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// Subdivision depth at which a triangle is closed whatever its bound: its
// edges are then 2^-40 (1e-12) of the original ones, the rounding level of
// the midpoints. Its bound still enters the upper bound.
constexpr int kMaxDepth = 40;
// Floor of the tolerance, relative to the largest coordinate magnitude.
constexpr double kRoundingFloor = 1e-13;

// A triangle of A (a face or a part of one) in the search.
struct Cell
{
    std::array<Vec3, 3> corner;
    std::array<double, 3> d;               // exact distance of each corner to B
    std::array<std::uint32_t, 3> closest;  // B's closest face of each corner
    std::uint32_t face = 0;                // the face of A it lies in
    std::uint32_t hint = kNone;            // the face of B that bounded its parent
    int depth = 0;
    double upper = kInf;  // its bound, once evaluated
};

// A candidate for the lower bound: a point of A and its closest point of B.
struct Candidate
{
    double d = -1.0;
    Vec3 point = Vec3::Zero();
    std::uint32_t face = 0;
    Vec3 closest = Vec3::Zero();
    std::uint32_t closest_face = 0;
};

double max_corner_distance(const std::array<Vec3, 3>& c, const Mesh& b, std::uint32_t t, double stop)
{
    const Face& f = b.faces[t];
    const Vec3& p0 = b.points[std::size_t(f[0])];
    const Vec3& p1 = b.points[std::size_t(f[1])];
    const Vec3& p2 = b.points[std::size_t(f[2])];
    double v = 0.0;
    for (const Vec3& q : c) {
        v = std::max(v, closest_point_on_triangle(q, p0, p1, p2).distance);
        if (v >= stop) break;
    }
    return v;
}

// The bit patterns of a point's coordinates: equal for equal computations.
std::array<std::uint64_t, 3> bits(const Vec3& p)
{
    std::array<std::uint64_t, 3> b{};
    std::memcpy(b.data(), p.data(), sizeof(b));
    return b;
}

double largest_coordinate(const Mesh& m)
{
    double s = 0.0;
    for (const Vec3& p : m.points) s = std::max(s, p.cwiseAbs().maxCoeff());
    return s;
}

}  // namespace

void validate(const HausdorffOptions& o)
{
    if (!(std::isfinite(o.relative_tolerance) && o.relative_tolerance >= 0.0 && o.relative_tolerance < 1.0))
        throw InvalidArgumentError(
            fmt::format("HausdorffOptions: relative_tolerance = {} must be in [0, 1)", o.relative_tolerance));
    if (!(std::isfinite(o.absolute_tolerance) && o.absolute_tolerance >= 0.0))
        throw InvalidArgumentError(
            fmt::format("HausdorffOptions: absolute_tolerance = {} must be finite and >= 0", o.absolute_tolerance));
    if (o.relative_tolerance == 0.0 && o.absolute_tolerance == 0.0)
        throw InvalidArgumentError("HausdorffOptions: relative_tolerance and absolute_tolerance are both 0");
}

CertifiedHausdorff certified_hausdorff(const Mesh& a, const Mesh& b, const ClosestPointIndex& b_index,
                                       const HausdorffOptions& options, const std::optional<HausdorffSeed>& seed)
{
    validate(options);
    validate(a, "certified_hausdorff: mesh A");
    validate(b, "certified_hausdorff: mesh B");
    if (b_index.n_faces() != b.n_faces())
        throw InvalidArgumentError(fmt::format("certified_hausdorff: the index holds {} faces but mesh B has {}",
                                               b_index.n_faces(), b.n_faces()));
    const double floor = kRoundingFloor * std::max(largest_coordinate(a), largest_coordinate(b));
    auto tolerance = [&](double lower) {
        return std::max({options.relative_tolerance * lower, options.absolute_tolerance, floor});
    };
    const std::size_t budget =
        options.max_evaluations ? options.max_evaluations : 2'000'000 + 20 * std::size_t(a.n_faces());

    CertifiedHausdorff r;
    Candidate best;
    if (seed) {
        const ClosestPoint q = b_index.closest_point(seed->point);
        best = {std::max(seed->distance, q.distance), seed->point, seed->face, q.point, q.face};
        ++r.point_evaluations;
    }

    // Exact distances of the vertices that faces use; each vertex's face is
    // the lowest-index face using it.
    std::vector<std::uint32_t> first_face(a.n_vertices(), kNone);
    for (std::size_t f = a.n_faces(); f-- > 0;)
        for (auto v : a.faces[f]) first_face[std::size_t(v)] = std::uint32_t(f);
    const std::vector<ClosestPoint> vq = b_index.closest_points(a.points);
    for (std::size_t v = 0; v < a.n_vertices(); ++v) {
        if (first_face[v] == kNone) continue;
        ++r.point_evaluations;
        if (vq[v].distance > best.d) best = {vq[v].distance, a.points[v], first_face[v], vq[v].point, vq[v].face};
    }

    std::vector<Cell> cells(a.n_faces());
    for (std::size_t f = 0; f < a.n_faces(); ++f) {
        Cell& c = cells[f];
        for (std::size_t k = 0; k < 3; ++k) {
            const auto v = std::size_t(a.faces[f][k]);
            c.corner[k] = a.points[v];
            c.d[k] = vq[v].distance;
            c.closest[k] = vq[v].face;
        }
        c.face = std::uint32_t(f);
    }

    // The longest edge of B's triangles: a cell of A whose corners are
    // farther apart than 2 x threshold + that length has no triangle of B
    // within threshold of all its corners (|c_i - c_j| <= d(c_i, t) +
    // diam(t) + d(c_j, t)), so its bound cannot close it: it is split
    // without searching.
    double longest_b = 0.0;
    for (const Face& f : b.faces)
        for (std::size_t k = 0; k < 3; ++k)
            longest_b =
                std::max(longest_b, (b.points[std::size_t(f[k])] - b.points[std::size_t(f[(k + 1) % 3])]).norm());
    auto diameter = [](const Cell& c) {
        return std::max({(c.corner[0] - c.corner[1]).norm(), (c.corner[1] - c.corner[2]).norm(),
                         (c.corner[2] - c.corner[0]).norm()});
    };

    double upper_done = 0.0;  // the largest bound of the closed triangles
    // Bounds every cell; keeps those above lower + tolerance in `cells`.
    auto bound_and_prune = [&](std::vector<Cell>& list) {
        const double threshold = best.d + tolerance(best.d);
        const auto n = std::int64_t(list.size());
#pragma omp parallel for schedule(dynamic, 256)
        for (std::int64_t i = 0; i < n; ++i) {
            Cell& c = list[std::size_t(i)];
            // d(., B) is 1-Lipschitz and every point of the cell is within
            // diam / sqrt(3) of a corner (the circumradius of an acute
            // triangle, half the longest edge otherwise): a bound always.
            const double diam = diameter(c);
            double u = std::max({c.d[0], c.d[1], c.d[2]}) + diam / std::sqrt(3.0);
            if (u <= threshold || (c.depth < kMaxDepth && diam > 2.0 * threshold + longest_b)) {
                c.upper = u;
                continue;
            }
            std::array<std::uint32_t, 4> tried{c.closest[0], c.closest[1], c.closest[2], c.hint};
            for (std::size_t k = 0; k < 4; ++k) {
                const std::uint32_t t = tried[k];
                if (t == kNone ||
                    std::find(tried.begin(), tried.begin() + std::ptrdiff_t(k), t) != tried.begin() + std::ptrdiff_t(k))
                    continue;
                u = std::min(u, max_corner_distance(c.corner, b, t, u));
            }
            if (u > threshold) {
                std::uint32_t t = kNone;
                const double v = b_index.hull_distance_bound(c.corner, threshold, &t);
                if (v < u) {
                    u = v;
                    c.hint = t;
                }
            }
            c.upper = u;
        }
        r.bound_evaluations += list.size();
        std::size_t kept = 0;
        for (Cell& c : list) {
            if (c.upper <= threshold || c.depth >= kMaxDepth) {
                upper_done = std::max(upper_done, c.upper);
            } else {
                list[kept++] = c;
            }
        }
        list.resize(kept);
    };

    bound_and_prune(cells);
    std::vector<Cell> next;
    std::vector<Candidate> found;
    std::vector<Vec3> mids;
    std::vector<std::uint32_t> order, slot, unique;
    std::vector<ClosestPoint> answers;
    while (!cells.empty()) {
        if (r.bound_evaluations + 4 * cells.size() > budget) {
            r.budget_exhausted = true;
            break;
        }
        ++r.rounds;
        // Split every open triangle at its edge midpoints; the midpoints'
        // distances are new lower-bound candidates. A midpoint of an edge that
        // two open triangles share is queried once (the same bits from both
        // sides: 0.5 * (a + b) is symmetric in a and b).
        const std::size_t n = cells.size();
        mids.resize(3 * n);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t k = 0; k < 3; ++k)
                mids[3 * i + k] = 0.5 * (cells[i].corner[k] + cells[i].corner[(k + 1) % 3]);  // edge k, k + 1
        order.resize(3 * n);
        std::iota(order.begin(), order.end(), std::uint32_t(0));
        std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
            return bits(mids[x]) < bits(mids[y]) || (bits(mids[x]) == bits(mids[y]) && x < y);
        });
        slot.resize(3 * n);
        unique.clear();
        for (std::size_t j = 0; j < order.size(); ++j) {
            if (j == 0 || bits(mids[order[j]]) != bits(mids[order[j - 1]])) unique.push_back(order[j]);
            slot[order[j]] = std::uint32_t(unique.size() - 1);
        }
        answers.resize(unique.size());
        const auto n_unique = std::int64_t(unique.size());
#pragma omp parallel for schedule(dynamic, 256)
        for (std::int64_t u = 0; u < n_unique; ++u) {
            const std::uint32_t at = unique[std::size_t(u)];
            answers[std::size_t(u)] = b_index.closest_point(mids[at], cells[at / 3].closest[at % 3]);
        }
        r.point_evaluations += unique.size();
        next.assign(4 * n, Cell{});
        found.assign(n, Candidate{});
#pragma omp parallel for schedule(dynamic, 256)
        for (std::int64_t ii = 0; ii < std::int64_t(n); ++ii) {
            const auto i = std::size_t(ii);
            const Cell& c = cells[i];
            std::array<Vec3, 3> m;
            std::array<ClosestPoint, 3> q;
            Candidate& cand = found[i];
            for (std::size_t k = 0; k < 3; ++k) {
                m[k] = mids[3 * i + k];
                q[k] = answers[slot[3 * i + k]];
                if (q[k].distance > cand.d) cand = {q[k].distance, m[k], c.face, q[k].point, q[k].face};
            }
            // Children: the three corner triangles and the middle one.
            for (std::size_t k = 0; k < 3; ++k) {
                Cell& ch = next[4 * i + k];
                const std::size_t prev = (k + 2) % 3;  // edge (k - 1, k)
                ch.corner = {c.corner[k], m[k], m[prev]};
                ch.d = {c.d[k], q[k].distance, q[prev].distance};
                ch.closest = {c.closest[k], q[k].face, q[prev].face};
            }
            Cell& mid = next[4 * i + 3];
            mid.corner = m;
            mid.d = {q[0].distance, q[1].distance, q[2].distance};
            mid.closest = {q[0].face, q[1].face, q[2].face};
            for (std::size_t k = 0; k < 4; ++k) {
                Cell& ch = next[4 * i + k];
                ch.face = c.face;
                ch.hint = c.hint;
                ch.depth = c.depth + 1;
            }
        }
        for (const Candidate& cand : found)  // in order: the lowest index wins ties
            if (cand.d > best.d) best = cand;
        cells.swap(next);
        bound_and_prune(cells);
    }

    double upper = std::max(upper_done, best.d);
    for (const Cell& c : cells) upper = std::max(upper, c.upper);
    r.lower = best.d;
    r.upper = upper;
    r.tolerance = tolerance(best.d);
    r.certified = !r.budget_exhausted && r.upper - r.lower <= r.tolerance;
    r.location = {best.point, best.face, best.closest, best.closest_face};
    return r;
}

CertifiedHausdorff certified_hausdorff(const Mesh& a, const Mesh& b, const HausdorffOptions& options)
{
    validate(b, "certified_hausdorff: mesh B");
    const ClosestPointIndex index(b);
    return certified_hausdorff(a, b, index, options);
}

}  // namespace meshdiff
