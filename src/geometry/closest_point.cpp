#include "meshdiff/geometry/closest_point.h"

#include "meshdiff/error.h"

#include "core/stage_progress.h"
#include "geometry/point_triangle_kernels.h"
#include "geometry/point_triangle_x4.h"
#include "geometry/query_block.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <limits>
#include <numeric>

#include <omp.h>

namespace meshdiff {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNoFace = std::numeric_limits<std::uint32_t>::max();
struct Tri
{
    Vec3 a, b, c;
    std::uint32_t face;
    bool thin;  // see detail::is_thin_triangle
};

inline Vec3 tri_point(const Vec3& p, const Tri& t)
{
    return t.thin ? detail::thin_triangle_point(p, t.a, t.b, t.c) : detail::triangle_point(p, t.a, t.b, t.c);
}

// A node has an oriented box besides its axis-aligned one (Impl::obbs) when
// this bit of `count` is set.
constexpr std::uint32_t kHasObb = 0x80000000u;

struct Node
{
    std::array<double, 3> lo, hi;
    std::uint32_t first;  // leaf: first triangle; inner: left child (right = first + 1)
    std::uint32_t count;  // leaf: number of triangles (> 0); inner: 0; | kHasObb
    std::uint32_t triangles() const { return count & ~kHasObb; }
};

// An oriented bounding box: |axis[k] . (p - centre)| <= half[k], its half
// extents padded by kObbPad times the size of its coordinates, so that
// rounding cannot put it farther from a query than a triangle inside it.
struct Obb
{
    std::array<double, 3> centre;
    std::array<std::array<double, 3>, 3> axis;
    std::array<double, 3> half;
};

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

struct Box
{
    Vec3 lo = Vec3::Constant(kInf);
    Vec3 hi = Vec3::Constant(-kInf);
    void grow(const Vec3& p)
    {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    void grow(const Box& b)
    {
        lo = lo.cwiseMin(b.lo);
        hi = hi.cwiseMax(b.hi);
    }
    double half_area() const
    {
        if (!(hi.x() >= lo.x())) return 0.0;
        const Vec3 d = hi - lo;
        return d.x() * d.y() + d.y() * d.z() + d.z() * d.x();
    }
};

constexpr std::uint32_t kLeafSize = 4;
// Triangles from which the build splits the root's two subtrees between two
// threads.
constexpr std::size_t kParallelBuild = 4096;
constexpr int kBins = 16;
constexpr std::uint32_t kMaxSahDepth = 48;
// Queries per parallel block (fixed: results do not depend on threads).
constexpr std::size_t kBlock = detail::kQueryBlock;
// Oriented boxes: tried for a node whose box's half area exceeds its
// triangles' area this many times (slivers, such as the fan of triangles
// around a vertex of very high valence, whose boxes all contain the hub), and
// kept when their half area is below this share of the box's.
constexpr double kObbTryRatio = 8.0;
constexpr double kObbKeepShare = 0.25;
// Padding of an oriented box, relative to the size of its coordinates: far
// above the rounding of its projections, far below any distance that matters.
constexpr double kObbPad = 1e-9;

}  // namespace

struct ClosestPointIndex::Impl
{
    std::vector<Tri> tris;  // in leaf order
    std::vector<Node> nodes;
    std::vector<std::uint32_t> parent_of;    // per node (root: 0)
    std::vector<std::uint32_t> leaf_of;      // per triangle position: its leaf
    std::vector<std::uint32_t> position_of;  // per face: its position in tris
    std::vector<Obb> obbs;                   // oriented boxes of the nodes with kHasObb
    std::vector<std::uint32_t> obb_slot;     // per node: its index in obbs (read only with kHasObb)

    void build(const Mesh& mesh);
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

void ClosestPointIndex::Impl::build(const Mesh& mesh)
{
    const std::size_t n = mesh.n_faces();
    // Progress: the triangles placed in leaves. The tree is grown outside
    // OpenMP regions (its check() may throw Cancelled).
    detail::StageProgress stage("index", n);
    tris.resize(n);
    std::vector<Box> boxes(n);
    std::vector<Vec3> centroid(n);
    std::vector<double> area(n);
    // Per triangle, independent: in parallel (as the loops after the tree).
#pragma omp parallel for schedule(static)
    for (std::size_t f = 0; f < n; ++f) {
        const Face& t = mesh.faces[f];
        Tri& tri = tris[f];
        tri.a = mesh.points[std::size_t(t[0])];
        tri.b = mesh.points[std::size_t(t[1])];
        tri.c = mesh.points[std::size_t(t[2])];
        tri.face = std::uint32_t(f);
        tri.thin = detail::is_thin_triangle(tri.a, tri.b, tri.c);

        boxes[f].grow(tri.a);
        boxes[f].grow(tri.b);
        boxes[f].grow(tri.c);
        centroid[f] = (tri.a + tri.b + tri.c) / 3.0;
        area[f] = 0.5 * (tri.b - tri.a).cross(tri.c - tri.a).norm();
    }
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    // The oriented box of the triangles order[begin..end): principal axes of
    // their corners, extents over the corners, padded.
    auto fit_obb = [&](std::uint32_t begin, std::uint32_t end, Obb& out) {
        Vec3 mean = Vec3::Zero();
        for (std::uint32_t i = begin; i < end; ++i) {
            const Tri& t = tris[order[i]];
            mean += t.a + t.b + t.c;
        }
        mean /= 3.0 * double(end - begin);
        Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
        for (std::uint32_t i = begin; i < end; ++i) {
            const Tri& t = tris[order[i]];
            for (const Vec3* q : {&t.a, &t.b, &t.c}) {
                const Vec3 d = *q - mean;
                cov += d * d.transpose();
            }
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
        eig.computeDirect(cov);
        Vec3 a0 = eig.eigenvectors().col(2);
        Vec3 a1 = eig.eigenvectors().col(1);
        if (!(a0.allFinite() && a1.allFinite() && a0.norm() > 0.5)) return false;
        a0.normalize();
        a1 = (a1 - a1.dot(a0) * a0);
        if (!(a1.norm() > 0.5)) return false;
        a1.normalize();
        const Vec3 a2 = a0.cross(a1).normalized();
        const std::array<Vec3, 3> ax{a0, a1, a2};
        Vec3 lo = Vec3::Constant(kInf), hi = Vec3::Constant(-kInf);
        for (std::uint32_t i = begin; i < end; ++i) {
            const Tri& t = tris[order[i]];
            for (const Vec3* q : {&t.a, &t.b, &t.c}) {
                const Vec3 s(ax[0].dot(*q), ax[1].dot(*q), ax[2].dot(*q));
                lo = lo.cwiseMin(s);
                hi = hi.cwiseMax(s);
            }
        }
        const Vec3 mid = (lo + hi) / 2.0;
        const Vec3 half = (hi - lo) / 2.0;
        const Vec3 centre = mid.x() * a0 + mid.y() * a1 + mid.z() * a2;
        const double pad = kObbPad * (centre.cwiseAbs().maxCoeff() + half.maxCoeff() + lo.cwiseAbs().maxCoeff() +
                                      hi.cwiseAbs().maxCoeff());
        for (std::size_t k = 0; k < 3; ++k) {
            out.centre[k] = centre[Eigen::Index(k)];
            out.half[k] = half[Eigen::Index(k)] + pad;
            for (std::size_t c = 0; c < 3; ++c) out.axis[k][c] = ax[k][Eigen::Index(c)];
        }
        return std::isfinite(pad);
    };

    struct Task
    {
        std::uint32_t node, begin, end, depth;
    };
    // A tree or a subtree being built: its nodes (numbered from 0 in the
    // order the build creates them), oriented boxes (in the order of their
    // nodes' processing) with their (node, slot) pairs, and the tasks left.
    struct Part
    {
        std::vector<Node> nodes;
        std::vector<Obb> obbs;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> obb_of;
        std::vector<Task> stack;
    };
    // Processes one node: its boxes, and its triangles as a leaf or its two
    // children, created in `out` and pushed on its stack (left on top).
    auto process = [&](const Task task, Part& out) {
        Box box, cbox;
        for (std::uint32_t i = task.begin; i < task.end; ++i) {
            box.grow(boxes[order[i]]);
            cbox.grow(centroid[order[i]]);
        }
        Node& node = out.nodes[task.node];
        for (int k = 0; k < 3; ++k) {
            node.lo[std::size_t(k)] = box.lo[k];
            node.hi[std::size_t(k)] = box.hi[k];
        }
        const std::uint32_t count = task.end - task.begin;
        double tri_area = 0.0;
        for (std::uint32_t i = task.begin; i < task.end; ++i) tri_area += area[order[i]];
        if (box.half_area() > kObbTryRatio * tri_area) {
            Obb obb;
            if (fit_obb(task.begin, task.end, obb)) {
                const double obb_half_area =
                    4.0 * (obb.half[0] * obb.half[1] + obb.half[1] * obb.half[2] + obb.half[2] * obb.half[0]);
                if (obb_half_area < kObbKeepShare * box.half_area()) {
                    out.obb_of.push_back({task.node, std::uint32_t(out.obbs.size())});
                    out.obbs.push_back(obb);
                }
            }
        }
        if (count <= kLeafSize) {
            node.first = task.begin;
            node.count = count;
            if (!stage.tick(count)) stage.check();
            return;
        }
        // Binned SAH along the longest centroid axis; median split if the
        // centroids coincide or the SAH split is one-sided.
        int axis = 0;
        const Vec3 ext = cbox.hi - cbox.lo;
        if (ext.y() > ext[axis]) axis = 1;
        if (ext.z() > ext[axis]) axis = 2;
        std::uint32_t mid = task.begin + count / 2;
        if (ext[axis] > 0.0) {
            std::array<Box, kBins> bin_box;
            std::array<std::uint32_t, kBins> bin_count{};
            // With subnormal extents kBins / ext overflows to infinity and a
            // centroid at cbox.lo gives 0 * inf = NaN: such bins go to 0, the
            // others to kBins - 1 (the finite case is untouched).
            const double scale = kBins / ext[axis];
            auto bin_of = [&](std::uint32_t f) {
                const double x = (centroid[f][axis] - cbox.lo[axis]) * scale;
                if (!(x >= 0.0)) return 0;
                return x < double(kBins) ? std::min(kBins - 1, int(x)) : kBins - 1;
            };
            for (std::uint32_t i = task.begin; i < task.end; ++i) {
                const int b = bin_of(order[i]);
                bin_box[std::size_t(b)].grow(boxes[order[i]]);
                ++bin_count[std::size_t(b)];
            }
            std::array<double, kBins> right_cost{};
            Box acc;
            std::uint32_t acc_n = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.grow(bin_box[std::size_t(b)]);
                acc_n += bin_count[std::size_t(b)];
                right_cost[std::size_t(b)] = acc.half_area() * acc_n;
            }
            acc = Box();
            acc_n = 0;
            double best = kInf;
            int best_split = -1;
            for (int b = 0; b < kBins - 1; ++b) {
                acc.grow(bin_box[std::size_t(b)]);
                acc_n += bin_count[std::size_t(b)];
                if (acc_n == 0 || acc_n == count) continue;
                const double cost = acc.half_area() * acc_n + right_cost[std::size_t(b + 1)];
                if (cost < best) {
                    best = cost;
                    best_split = b;
                }
            }
            // Deep trees (one-sided SAH splits) fall back to median splits, which
            // bound the depth, and so the traversal stack, by 48 + log2(n).
            if (best_split >= 0 && task.depth < kMaxSahDepth) {
                auto it = std::partition(order.begin() + task.begin, order.begin() + task.end,
                                         [&](std::uint32_t f) { return bin_of(f) <= best_split; });
                mid = std::uint32_t(it - order.begin());
            } else {
                std::nth_element(order.begin() + task.begin, order.begin() + mid, order.begin() + task.end,
                                 [&](std::uint32_t x, std::uint32_t y) {
                                     return centroid[x][axis] < centroid[y][axis] ||
                                            (centroid[x][axis] == centroid[y][axis] && x < y);
                                 });
            }
        }
        const auto left = std::uint32_t(out.nodes.size());
        out.nodes.push_back({});
        out.nodes.push_back({});
        out.nodes[task.node].first = left;
        out.nodes[task.node].count = 0;
        out.stack.push_back({left + 1, mid, task.end, task.depth + 1});
        out.stack.push_back({left, task.begin, mid, task.depth + 1});
    };
    // Depth first, left child first, as the tasks come off the stack.
    auto grow = [&](Part& part) {
        while (!part.stack.empty()) {
            stage.check();  // a node costs O(its triangles), the root O(n)
            const Task task = part.stack.back();
            part.stack.pop_back();
            process(task, part);
        }
    };

    Part tree;
    tree.nodes.reserve(2 * (n / kLeafSize + 1));
    tree.nodes.push_back({});
    stage.check();
    process({0, 0, std::uint32_t(n), 0}, tree);
    if (tree.stack.size() == 2 && n >= kParallelBuild && omp_get_max_threads() > 1) {
        // The root's two subtrees on two threads, each numbered from 0 (its
        // root), then appended as the serial build numbers them: the left
        // subtree's root is node 1, its other nodes follow from 3 in their
        // order; the right one's root is node 2, its other nodes follow
        // those. Their triangle ranges are disjoint. The same tree, node for
        // node, as the serial build.
        Part sub[2];
        for (int k = 0; k < 2; ++k) {
            const Task t = tree.stack[std::size_t(1 - k)];  // left on top
            sub[k].nodes.push_back({});
            sub[k].stack.push_back({0, t.begin, t.end, t.depth});
        }
        auto right = std::async(std::launch::async, [&] { grow(sub[1]); });
        grow(sub[0]);
        right.get();
        tree.nodes.resize(3);
        const std::uint32_t offset[2] = {2, std::uint32_t(sub[0].nodes.size()) + 1};  // for local ids >= 1
        for (std::uint32_t k = 0; k < 2; ++k) {
            auto global = [&](std::uint32_t local) { return local == 0 ? 1 + k : local + offset[k]; };
            for (std::size_t i = 0; i < sub[k].nodes.size(); ++i) {
                Node node = sub[k].nodes[i];
                if (node.triangles() == 0) node.first = global(node.first);
                if (i == 0)
                    tree.nodes[1 + k] = node;
                else
                    tree.nodes.push_back(node);
            }
            const auto slot0 = std::uint32_t(tree.obbs.size());
            tree.obbs.insert(tree.obbs.end(), sub[k].obbs.begin(), sub[k].obbs.end());
            for (const auto& [node, slot] : sub[k].obb_of) tree.obb_of.push_back({global(node), slot0 + slot});
        }
    } else {
        grow(tree);
    }
    nodes = std::move(tree.nodes);
    obbs = std::move(tree.obbs);
    const auto obb_of = std::move(tree.obb_of);
    std::vector<Tri> ordered(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) ordered[i] = tris[order[i]];
    tris.swap(ordered);
    obb_slot.assign(obbs.empty() ? 0 : nodes.size(), 0);
    for (const auto& [node, slot] : obb_of) {
        nodes[node].count |= kHasObb;
        obb_slot[node] = slot;
    }
    parent_of.assign(nodes.size(), 0);
    leaf_of.assign(n, 0);
    position_of.assign(n, 0);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) position_of[tris[i].face] = std::uint32_t(i);
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const Node& node = nodes[k];
        if (node.triangles() > 0) {
            for (std::uint32_t i = 0; i < node.triangles(); ++i) leaf_of[node.first + i] = std::uint32_t(k);
        } else {
            parent_of[node.first] = parent_of[node.first + 1] = std::uint32_t(k);
        }
    }
    stage.finish();
}

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
    impl_->build(mesh);
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
