#include "meshdiff/geometry/closest_point.h"

#include "meshdiff/error.h"

#include "core/stage_progress.h"
#include "geometry/bvh_build.h"
#include "geometry/point_triangle_kernels.h"
#include "geometry/point_triangle_x4.h"
#include "geometry/query_block.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace meshdiff {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();
using detail::kHasObb;
using detail::Node;
using detail::Obb;
using detail::Tri;

inline Vec3 tri_point(const Vec3& p, const Tri& t)
{
    return t.thin ? detail::thin_triangle_point(p, t.a, t.b, t.c) : detail::triangle_point(p, t.a, t.b, t.c);
}

inline double obb_distance2(const Obb& b, const Vec3& p)
{
    const double dx = p.x() - b.centre[0], dy = p.y() - b.centre[1], dz = p.z() - b.centre[2];
    double d2 = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double s = b.axis[k][0] * dx + b.axis[k][1] * dy + b.axis[k][2] * dz;
        const double e = std::max(std::abs(s) - b.half[k], 0.0);
        d2 += e * e;
    }
    return d2;
}

inline double box_distance2(const Node& n, const Vec3& p)
{
    const double ex = std::max(std::max(n.lo[0] - p.x(), p.x() - n.hi[0]), 0.0);
    const double ey = std::max(std::max(n.lo[1] - p.y(), p.y() - n.hi[1]), 0.0);
    const double ez = std::max(std::max(n.lo[2] - p.z(), p.z() - n.hi[2]), 0.0);
    return ex * ex + ey * ey + ez * ez;
}

// Queries per parallel block (fixed: results do not depend on threads).
constexpr std::size_t kBlock = detail::kQueryBlock;

}  // namespace

struct ClosestPointIndex::Impl : detail::Bvh
{
    // A lower bound of the distance^2 from p to any triangle below node k: its
    // box's, or its oriented box's if that is farther.
    double node_distance2(std::uint32_t k, const Vec3& p) const
    {
        const Node& n = nodes[k];
        const double d2 = box_distance2(n, p);
        if (!(n.count & kHasObb)) return d2;
        return std::max(d2, obb_distance2(obbs[obb_slot[k]], p));
    }
    // Lexicographic minimum of (squared distance, face) over all triangles;
    // `hint` (a position in `tris`, or kNoFace) only changes the search order:
    // the search starts in the hint's leaf and climbs towards the root.
    ClosestPoint query(const Vec3& p, std::uint32_t hint, std::uint32_t* hit) const;
    // Smallest over triangles of the largest squared distance from the corners
    // c to the triangle, stopping at the first value <= good2.
    double hull_query(const std::array<Vec3, 3>& c, double good2, std::uint32_t* face) const;
};

ClosestPoint ClosestPointIndex::Impl::query(const Vec3& p, std::uint32_t hint, std::uint32_t* hit) const
{
    double best_d2 = kInf;
    std::uint32_t best_face = kNoFace;
    std::uint32_t best_pos = kNoFace;
    Vec3 best_point = Vec3::Zero();
    auto offer = [&](double d2, std::uint32_t pos, const Vec3& q) {
        const std::uint32_t face = tris[pos].face;
        if (d2 < best_d2 || (d2 == best_d2 && face < best_face)) {
            best_d2 = d2;
            best_face = face;
            best_pos = pos;
            best_point = q;
        }
    };
    auto consider = [&](std::uint32_t pos) {
        const Vec3 q = tri_point(p, tris[pos]);
        offer((p - q).squaredNorm(), pos, q);
    };
    // A leaf's triangles: with AVX2, up to four at once (bitwise the same
    // values, geometry/point_triangle_x4.h); thin ones one by one.
    const bool x4 = detail::use_avx2();
    auto consider_leaf = [&](const Node& leaf) {
        const std::uint32_t first = leaf.first, count = leaf.triangles();
        if (!x4 || count < 2) {
            for (std::uint32_t i = 0; i < count; ++i) consider(first + i);
            return;
        }
        detail::PairsX4 in;
        for (std::uint32_t k = 0; k < 4; ++k) {
            const Tri& t = tris[first + std::min(k, count - 1)];
            in.p[k] = p.data();
            in.a[k] = t.a.data();
            in.b[k] = t.b.data();
            in.c[k] = t.c.data();
        }
        double d2[4], qx[4], qy[4], qz[4];
        detail::closest_points_x4(in, d2, qx, qy, qz);
        for (std::uint32_t i = 0; i < count; ++i) {
            if (tris[first + i].thin)
                consider(first + i);
            else
                offer(d2[i], first + i, Vec3(qx[i], qy[i], qz[i]));
        }
    };

    // A node is skipped only if its box is farther than the best so far by a
    // margin above rounding, so that ties and near-ties are still examined.
    constexpr double keep = 1.0 - 1e-12;
    struct Entry
    {
        std::uint32_t node;
        double d2;
    };
    std::array<Entry, 128> stack;
    // Branch and bound below `root`, nearest child first.
    auto descend = [&](std::uint32_t root, double root_d2) {
        std::size_t top = 0;
        stack[top++] = {root, root_d2};
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.d2 * keep > best_d2) continue;
            const Node& node = nodes[e.node];
            if (node.triangles() > 0) {
                consider_leaf(node);
                continue;
            }
            const double dl = node_distance2(node.first, p);
            const double dr = node_distance2(node.first + 1, p);
            const Entry l{node.first, dl};
            const Entry r{node.first + 1, dr};
            // Push the farther child first so that the nearer one is visited first.
            const Entry& near = dl <= dr ? l : r;
            const Entry& far = dl <= dr ? r : l;
            if (far.d2 * keep <= best_d2) stack[top++] = far;
            if (near.d2 * keep <= best_d2) stack[top++] = near;
        }
    };

    if (hint == kNoFace) {
        descend(0, node_distance2(0, p));
    } else {
        // Start in the hint's leaf and climb to the root, searching the sibling
        // subtree at each level: every triangle is in exactly one of these.
        std::uint32_t node = leaf_of[hint];
        consider_leaf(nodes[node]);
        while (node != 0) {
            const std::uint32_t parent = parent_of[node];
            const std::uint32_t sibling = node == nodes[parent].first ? node + 1 : node - 1;
            const double d2 = node_distance2(sibling, p);
            if (d2 * keep <= best_d2) descend(sibling, d2);
            node = parent;
        }
    }
    if (hit) *hit = best_pos;
    ClosestPoint r;
    r.distance = std::sqrt(best_d2);
    r.point = best_point;
    r.face = best_face;
    return r;
}

double ClosestPointIndex::Impl::hull_query(const std::array<Vec3, 3>& c, double good2, std::uint32_t* face) const
{
    double best = kInf;
    std::uint32_t best_face = kNoFace;
    // With a target (good2 > 0) only a value <= good2 is of interest: a node
    // or a triangle that cannot reach it is skipped. Without one (good2 <=
    // 0), the minimum is searched.
    const double cut = good2 > 0.0 ? good2 : kInf;
    // A node's bound: no triangle below it is closer to corner i than its
    // box, so the largest of the three box distances bounds the value of
    // every triangle below it from below.
    auto bound = [&](std::uint32_t k) {
        return std::max({node_distance2(k, c[0]), node_distance2(k, c[1]), node_distance2(k, c[2])});
    };
    struct Entry
    {
        std::uint32_t node;
        double d2;
    };
    std::array<Entry, 128> stack;
    std::size_t top = 0;
    stack[top++] = {0, bound(0)};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.d2 >= best || e.d2 > cut) continue;
        const Node& node = nodes[e.node];
        if (node.triangles() > 0) {
            for (std::uint32_t i = 0; i < node.triangles(); ++i) {
                const Tri& t = tris[node.first + i];
                double v = 0.0;
                for (const Vec3& q : c) {
                    v = std::max(v, (q - tri_point(q, t)).squaredNorm());
                    if (v >= best || v > cut) break;
                }
                if (v < best && v <= cut) {
                    best = v;
                    best_face = t.face;
                    if (best <= good2) {
                        if (face) *face = best_face;
                        return best;
                    }
                }
            }
            continue;
        }
        const Entry l{node.first, bound(node.first)};
        const Entry r{node.first + 1, bound(node.first + 1)};
        const Entry& near = l.d2 <= r.d2 ? l : r;
        const Entry& far = l.d2 <= r.d2 ? r : l;
        if (far.d2 < best && far.d2 <= cut) stack[top++] = far;
        if (near.d2 < best && near.d2 <= cut) stack[top++] = near;
    }
    if (face) *face = best_face;
    return best;
}

ClosestPointIndex::ClosestPointIndex(const Mesh& mesh) : impl_(std::make_unique<Impl>())
{
    validate(mesh, "ClosestPointIndex");
    detail::build_bvh(mesh, *impl_);
}

ClosestPointIndex::ClosestPointIndex(const MeshData& data) : impl_(std::make_unique<Impl>())
{
    data.validate("ClosestPointIndex");
    detail::build_bvh(data.mesh(), *impl_);
}

ClosestPointIndex::~ClosestPointIndex() = default;
ClosestPointIndex::ClosestPointIndex(ClosestPointIndex&&) noexcept = default;
ClosestPointIndex& ClosestPointIndex::operator=(ClosestPointIndex&&) noexcept = default;

ClosestPoint ClosestPointIndex::closest_point(const Vec3& p) const
{
    return impl_->query(p, kNoFace, nullptr);
}

ClosestPoint ClosestPointIndex::closest_point(const Vec3& p, std::uint32_t near_face) const
{
    const std::uint32_t hint = near_face < impl_->position_of.size() ? impl_->position_of[near_face] : kNoFace;
    return impl_->query(p, hint, nullptr);
}

namespace {
// Runs f(i, hint) -> hit over fixed blocks of queries in parallel; within a
// block, each query is seeded with the previous query's triangle.
template <class F>
void for_blocks(std::size_t n, F&& f)
{
    const auto n_blocks = std::int64_t((n + kBlock - 1) / kBlock);
    detail::StageProgress stage("distances", n);
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t b = 0; b < n_blocks; ++b) {
        const std::size_t end = std::min(n, std::size_t(b + 1) * kBlock);
        if (!stage.tick(end - std::size_t(b) * kBlock)) continue;
        std::uint32_t hint = kNoFace;
        for (std::size_t i = std::size_t(b) * kBlock; i < end; ++i) hint = f(i, hint);
    }
    stage.finish();
}
}  // namespace

std::vector<ClosestPoint> ClosestPointIndex::closest_points(const std::vector<Vec3>& queries) const
{
    std::vector<ClosestPoint> out(queries.size());
    const Impl& impl = *impl_;
    for_blocks(queries.size(), [&](std::size_t i, std::uint32_t hint) {
        std::uint32_t hit = kNoFace;
        out[i] = impl.query(queries[i], hint, &hit);
        return hit;
    });
    return out;
}

std::vector<double> ClosestPointIndex::distances(const std::vector<Vec3>& queries) const
{
    std::vector<double> out(queries.size());
    distances(queries.data(), queries.size(), out.data());
    return out;
}

void ClosestPointIndex::distances(const Vec3* queries, std::size_t n, double* out) const
{
    const Impl& impl = *impl_;
    for_blocks(n, [&](std::size_t i, std::uint32_t hint) {
        std::uint32_t hit = kNoFace;
        out[i] = impl.query(queries[i], hint, &hit).distance;
        return hit;
    });
}

void ClosestPointIndex::distances(const Vec3* queries, std::size_t n, double* out,
                                  const std::function<void(std::size_t, const ClosestPoint&)>& visit) const
{
    const Impl& impl = *impl_;
    for_blocks(n, [&](std::size_t i, std::uint32_t hint) {
        std::uint32_t hit = kNoFace;
        const ClosestPoint c = impl.query(queries[i], hint, &hit);
        out[i] = c.distance;
        visit(i, c);
        return hit;
    });
}

double ClosestPointIndex::hull_distance_bound(const std::array<Vec3, 3>& corners, double good_enough,
                                              std::uint32_t* face) const
{
    if (impl_->tris.empty()) {
        if (face) *face = kNoFace;
        return kInf;
    }
    const double good2 = good_enough > 0.0 ? good_enough * good_enough : (good_enough == 0.0 ? 0.0 : -1.0);
    return std::sqrt(impl_->hull_query(corners, good2, face));
}

std::size_t ClosestPointIndex::n_faces() const
{
    return impl_->tris.size();
}

BoundingBox ClosestPointIndex::bounds() const
{
    BoundingBox b;
    const Node& root = impl_->nodes[0];
    b.min = Vec3(root.lo[0], root.lo[1], root.lo[2]);
    b.max = Vec3(root.hi[0], root.hi[1], root.hi[2]);
    return b;
}

std::size_t ClosestPointIndex::memory_bytes() const
{
    return impl_->tris.capacity() * sizeof(Tri) + impl_->nodes.capacity() * sizeof(Node) +
           impl_->obbs.capacity() * sizeof(Obb) +
           (impl_->parent_of.capacity() + impl_->leaf_of.capacity() + impl_->obb_slot.capacity() +
            impl_->position_of.capacity()) *
               sizeof(std::uint32_t);
}

}  // namespace meshdiff
