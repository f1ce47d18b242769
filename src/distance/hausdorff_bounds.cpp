#include "distance/hausdorff_bounds.h"

#include "meshdiff/core/topology.h"

#include "geometry/point_triangle_x4.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <vector>

namespace meshdiff::detail {

namespace {
std::atomic<std::uint64_t> next_target_id{1};
}  // namespace

BoundsTarget::BoundsTarget(const Mesh& m, const ClosestPointIndex& i)
    : id(next_target_id.fetch_add(1, std::memory_order_relaxed)), mesh(m), index(i)
{}

namespace {

// The squared distances from the \p n points \p pts to triangle t, into
// \p d2 (room for n rounded up to 4): squared_distance() of each, four at a
// time with AVX2 (bitwise the same, geometry/point_triangle_x4.h).
void squared_distances(const Vec3* pts, int n, const Triangle& t, double* d2)
{
    if (t.thin || n < 2 || !use_avx2()) {
        for (int i = 0; i < n; ++i) d2[i] = squared_distance(pts[i], t);
        return;
    }
    PairsX4 in;
    for (int k = 0; k < 4; ++k) {
        in.a[k] = t.a.data();
        in.b[k] = t.b.data();
        in.c[k] = t.c.data();
    }
    double qx[4], qy[4], qz[4];
    for (int i0 = 0; i0 < n; i0 += 4) {
        for (int k = 0; k < 4; ++k) in.p[k] = pts[std::min(i0 + k, n - 1)].data();
        closest_points_x4(in, d2 + i0, qx, qy, qz, SharedX4::kTriangle);
    }
}

// The largest distance from the corners c to face t of B, or +inf as soon as
// it reaches stop (then only "not below stop" is known).
double max_corner_distance(const std::array<Vec3, 3>& c, const Triangles& b, std::uint32_t t, double stop)
{
    const double stop2 = stop * stop;
    double d2[4];
    squared_distances(c.data(), 3, b[t], d2);
    double v = 0.0;
    for (int k = 0; k < 3; ++k) {
        v = std::max(v, d2[k]);
        if (v >= stop2) return kInf;
    }
    return std::sqrt(v);
}

// The largest distance from a point of triangle c to its nearest corner: the
// circumradius of an acute triangle, half the longest edge otherwise (a
// segment or a point included). Rounded up by a relative 1e-12.
double covering_radius(const Cell& c)
{
    const Vec3 e0 = c.corner[1] - c.corner[0], e1 = c.corner[2] - c.corner[1], e2 = c.corner[0] - c.corner[2];
    std::array<double, 3> sq{e0.squaredNorm(), e1.squaredNorm(), e2.squaredNorm()};
    std::sort(sq.begin(), sq.end());
    const double longest = std::sqrt(sq[2]);
    double r = 0.5 * longest;
    if (sq[2] < sq[0] + sq[1]) {  // acute
        const double twice_area = e0.cross(e2).norm();
        if (twice_area > 0.0)
            r = std::min(std::sqrt(sq[0] * sq[1] * sq[2]) / (2.0 * twice_area), longest / std::sqrt(3.0));
        else
            r = longest / std::sqrt(3.0);
        r = std::max(r, 0.5 * longest);
    }
    return r * (1.0 + 1e-12);
}

// The longest distance between two corners of cell c.
double cell_diameter(const Cell& c)
{
    return std::max(
        {(c.corner[0] - c.corner[1]).norm(), (c.corner[1] - c.corner[2]).norm(), (c.corner[2] - c.corner[0]).norm()});
}

// Local descents over B's faces, each keeping the exact value of a face it
// holds (so any result is a valid upper bound). At most kMaxSteps moves.
constexpr int kMaxSteps = 16;
// The cuts of a cell along planes between adjacent triangles of B: at most
// this deep, and this many parts evaluated per cell.
constexpr int kPieceDepth = 8;
constexpr int kPieceWork = 48;

// descend_point() for the largest distance from the corners \p c to a face (\p u
// for face \p t): descends while a neighbour has a smaller one, until u <= goal.
// True if it stopped at a local minimum (a face with neighbours, none better).
bool descend_hull(const std::array<Vec3, 3>& c, const Triangles& b, const Neighbours& nbr, std::uint32_t& t, double& u,
                  double goal)
{
    for (int step = 0; step < kMaxSteps && u > goal; ++step) {
        std::uint32_t next = t;
        bool any = false;
        for (const std::uint32_t n : nbr[t]) {
            if (n == kNone) continue;
            any = true;
            const double v = max_corner_distance(c, b, n, u);
            if (v < u) {
                u = v;
                next = n;
            }
        }
        if (next == t) return any;
        t = next;
    }
    return false;
}

// A convex polygon: a piece of a cell cut along the planes between adjacent
// triangles of B.
constexpr int kMaxPiece = 16;
struct Piece
{
    std::array<Vec3, kMaxPiece> p;
    int n = 0;
};

// Cuts \p in by the plane through \p o with normal \p m: the part where
// (v - o).m >= 0 into \p keep, the part where it is <= 0 into \p rest (the
// crossing points into both, so that together they cover \p in up to the
// rounding of those points). False if a part would exceed kMaxPiece corners.
bool cut(const Piece& in, const Vec3& o, const Vec3& m, Piece& keep, Piece& rest)
{
    keep.n = rest.n = 0;
    auto push = [](Piece& q, const Vec3& v) {
        if (q.n == kMaxPiece) return false;
        q.p[std::size_t(q.n++)] = v;
        return true;
    };
    for (int i = 0; i < in.n; ++i) {
        const Vec3& a = in.p[std::size_t(i)];
        const Vec3& b = in.p[std::size_t((i + 1) % in.n)];
        const double sa = (a - o).dot(m), sb = (b - o).dot(m);
        if (sa >= 0.0 && !push(keep, a)) return false;
        if (sa <= 0.0 && !push(rest, a)) return false;
        if ((sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0)) {
            const Vec3 x = a + (sa / (sa - sb)) * (b - a);
            if (!push(keep, x) || !push(rest, x)) return false;
        }
    }
    return true;
}

// The plane between face t of B and its neighbour t2 across edge k (corners
// k, k + 1 of t): through that edge, bisecting the angle between the two
// faces; \p m points to t's side. False for a collapsed edge or neighbour.
bool bisector(const Mesh& b, std::uint32_t t, std::size_t k, std::uint32_t t2, Vec3& o, Vec3& m)
{
    const Face& f = b.faces[t];
    const int v0 = f[k], v1 = f[(k + 1) % 3], vo = f[(k + 2) % 3];
    int wo = -1;
    for (const int w : b.faces[t2])
        if (w != v0 && w != v1) wo = w;
    if (wo < 0) return false;
    o = b.points[std::size_t(v0)];
    const Vec3 e = b.points[std::size_t(v1)] - o;
    const double ee = e.squaredNorm();
    if (!(ee > 0.0)) return false;
    auto across = [&](int v) -> Vec3 {  // unit vector from the edge towards v, across it
        Vec3 d = b.points[std::size_t(v)] - o;
        d -= (d.dot(e) / ee) * e;
        const double len = d.norm();
        return len > 0.0 ? Vec3(d / len) : Vec3(Vec3::Zero());
    };
    const Vec3 u = across(vo), u2 = across(wo);
    m = u - u2;
    if (!(m.squaredNorm() > 1e-12)) m = u;
    return m.squaredNorm() > 0.0;
}

// The bisecting planes of B's edges lately made on this thread (bisector()'s
// normal m, or none for a collapsed edge), by half-edge 3 t + k: the cells are
// bounded in the order of A's faces, near each other, so that a plane is made
// about 3.4 times and found here 7 times in 10 on a 2M-face pair (4,096
// entries, 128 KB a thread). A found plane is the one bisector() makes, the
// same bits.
class BisectorCache
{
public:
    // Empties the cache when it holds another target's planes.
    void use_for(std::uint64_t target)
    {
        if (target_ == target) return;
        target_ = target;
        for (Entry& e : entries_) e.key = kEmpty;
    }
    // bisector(b, t, k, t2, o, m) through the cache.
    bool plane(const Mesh& b, std::uint32_t t, std::size_t k, std::uint32_t t2, Vec3& o, Vec3& m)
    {
        const std::uint64_t half_edge = 3 * std::uint64_t(t) + k;
        Entry& e = entries_[std::size_t((half_edge * 0x9E3779B97F4A7C15ull) >> (64 - kBits))];
        if ((e.key >> 1) == half_edge) {
            if (!(e.key & 1u)) return false;
            o = b.points[std::size_t(b.faces[t][k])];
            m = e.m;
            return true;
        }
        const bool ok = bisector(b, t, k, t2, o, m);
        e.key = half_edge << 1 | std::uint64_t(ok);
        if (ok) e.m = m;
        return ok;
    }

private:
    static constexpr int kBits = 12;
    static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);  // no half-edge: 3 x 2^32 < 2^63
    struct Entry
    {
        std::uint64_t key = kEmpty;  // half-edge << 1 | (a plane, not a collapsed edge)
        Vec3 m;
    };
    std::uint64_t target_ = 0;
    std::array<Entry, std::size_t(1) << kBits> entries_;
};

thread_local BisectorCache bisectors;

// An upper bound of d(., B) over the convex piece \p q: the largest distance
// from its corners to face t (convexity), and where that exceeds \p goal and
// q reaches across an edge of t, the larger of the bounds of its two parts
// cut along the bisecting plane of that edge, the far part bounded by the
// neighbour (so around a vertex of B a piece is passed along its fan). +inf
// when it cannot get below \p goal within \p depth cuts or \p work piece
// evaluations. Any cut gives a valid bound: every point of q lies in a part.
double piece_bound(const Piece& q, std::uint32_t t, int depth, double goal, const Mesh& b, const Triangles& tris,
                   const Neighbours& nbr, int& work)
{
    if (q.n == 0) return 0.0;
    if (--work < 0) return kInf;
    // The corners four at a time, stopping once one is farther than the goal
    // (then only that is used): the largest of all otherwise, in the order
    // of one pass.
    std::array<double, kMaxPiece> d2;
    double v2 = 0.0, v = 0.0;
    bool above = false;
    for (int i0 = 0; i0 < q.n && !above; i0 += 4) {
        const int k = std::min(4, q.n - i0);
        squared_distances(q.p.data() + i0, k, tris[t], d2.data() + i0);
        for (int i = i0; i < i0 + k; ++i) v2 = std::max(v2, d2[std::size_t(i)]);
        v = std::sqrt(v2);
        above = !(v <= goal);
    }
    if (!above) return v;
    if (depth == 0) return kInf;
    for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t t2 = nbr[t][k];
        Vec3 o, m;
        if (t2 == kNone || !bisectors.plane(b, t, k, t2, o, m)) continue;
        // Outside beyond rounding: the crossing points of an earlier cut along
        // this plane lie on it up to a few ulps.
        double most = 0.0, least = 0.0;
        for (int i = 0; i < q.n; ++i) {
            const double s = (q.p[std::size_t(i)] - o).dot(m);
            most = std::max(most, std::abs(s));
            least = std::min(least, s);
        }
        const bool outside = least < -1e-9 * most;
        if (!outside) continue;
        Piece keep, rest;
        if (!cut(q, o, m, keep, rest)) return kInf;
        const double near = keep.n ? piece_bound(keep, t, depth - 1, goal, b, tris, nbr, work) : 0.0;
        if (near > goal) return kInf;
        const double far = piece_bound(rest, t2, depth - 1, goal, b, tris, nbr, work);
        return far > goal ? kInf : std::max(near, far);
    }
    return kInf;  // inside t's wedge and still above the goal
}

}  // namespace

// Each half-edge of an edge with two or more points at the face of the next
// one, the last at the first's (EdgeMap order: by face, then corner).
Neighbours edge_neighbours(const MeshData& data)
{
    const Mesh& m = data.mesh();
    const EdgeMap edges = edge_map(data);
    Neighbours nbr(m.n_faces(), {kNone, kNone, kNone});
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const std::size_t count = edges.count(e);
        if (count < 2) continue;
        const std::uint32_t* h = edges.begin(e);
        for (std::size_t q = 0; q < count; ++q) nbr[h[q] / 3][h[q] % 3] = h[q + 1 < count ? q + 1 : 0] / 3;
    }
    return nbr;
}

Neighbours neighbours_across(const std::vector<std::uint32_t>& opposite)
{
    Neighbours nbr(opposite.size() / 3);
    const auto nf = std::int64_t(nbr.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < nf; ++i) {
        const auto f = std::size_t(i);
        for (std::size_t k = 0; k < 3; ++k) nbr[f][k] = opposite[3 * f + k] / 3;
    }
    return nbr;
}

// Face \p t of B is at distance \p d from \p p; moves to a neighbour closer to
// p while there is one, until d <= goal.
void descend_point(const Vec3& p, const Triangles& b, const Neighbours& nbr, std::uint32_t& t, double& d, double goal)
{
    for (int step = 0; step < kMaxSteps && d > goal; ++step) {
        std::uint32_t next = t;
        for (const std::uint32_t n : nbr[t]) {
            if (n == kNone) continue;
            const double dn = face_distance(p, b, n);
            if (dn < d) {
                d = dn;
                next = n;
            }
        }
        if (next == t) break;
        t = next;
    }
}

void bound_cell(Cell& c, double threshold, const BoundsTarget& target)
{
    const Mesh& b = target.mesh;
    const ClosestPointIndex& b_index = target.index;
    const std::vector<double>& diameter_b = target.diameter;
    const double longest_b = target.longest;
    const Neighbours& nbr = target.nbr;
    const Triangles& tris = target.tris;
    // d(., B) is 1-Lipschitz and every point of the cell is within
    // covering_radius(c) of a corner: a bound always.
    const double diam = cell_diameter(c);
    double u = std::max({c.d[0], c.d[1], c.d[2]}) + covering_radius(c);
    if (u <= threshold || (c.depth < kMaxDepth && diam > 2.0 * threshold + longest_b)) {
        c.upper = u;
        return;
    }
    std::array<std::uint32_t, 4> tried{c.closest[0], c.closest[1], c.closest[2], c.hint};
    std::uint32_t best_face = kNone;
    double best_face_u = kInf;
    for (std::size_t k = 0; k < 4; ++k) {
        const std::uint32_t t = tried[k];
        if (t == kNone ||
            std::find(tried.begin(), tried.begin() + std::ptrdiff_t(k), t) != tried.begin() + std::ptrdiff_t(k))
            continue;
        const double v = max_corner_distance(c.corner, tris, t, best_face_u);
        if (v < best_face_u) {
            best_face_u = v;
            best_face = t;
        }
    }
    bool settled = false;
    double local = 0.0;
    for (const std::uint32_t t : tried)
        if (t != kNone) local = std::max(local, diameter_b[t]);
    const bool coverable = c.depth >= kMaxDepth || diam <= 2.0 * threshold + 2.0 * local;
    if (best_face != kNone && std::min(u, best_face_u) > threshold && coverable) {
        settled = descend_hull(c.corner, tris, nbr, best_face, best_face_u, threshold);
        c.hint = best_face;
    }
    u = std::min(u, best_face_u);
    // Across edges of B: the cell cut along the planes between
    // adjacent triangles, each part bounded by its own triangle.
    if (u > threshold && best_face != kNone && coverable) {
        bisectors.use_for(target.id);
        Piece q;
        q.n = 3;
        for (std::size_t k = 0; k < 3; ++k) q.p[k] = c.corner[k];
        int work = kPieceWork;
        const double v = piece_bound(q, best_face, kPieceDepth, threshold, b, tris, nbr, work);
        if (v <= threshold) {
            // The crossing points are rounded: a point of the cell is
            // within a few ulps of its coordinates from a part.
            const double slack = 1e-14 * (diam + c.corner[0].cwiseAbs().maxCoeff());
            u = std::min(u, v + slack);
        }
    }
    // A search is worth it only if one triangle of B can be near all
    // the corners: not when the cell is much wider than the triangles
    // near them (a cost heuristic: skipping only means splitting).
    if (u > threshold && (c.depth >= kMaxDepth || (!settled && coverable))) {
        std::uint32_t t = kNone;
        const double v = b_index.hull_distance_bound(c.corner, threshold, &t);
        if (v < u) {
            u = v;
            c.hint = t;
        }
    }
    c.upper = u;
}

}  // namespace meshdiff::detail
