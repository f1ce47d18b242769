#include "geometry/bvh_build.h"

#include "core/stage_progress.h"
#include "geometry/point_triangle_kernels.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include <omp.h>

namespace meshdiff::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

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
// Oriented boxes: tried for a node whose box's half area exceeds its
// triangles' area this many times (slivers, such as the fan of triangles
// around a vertex of very high valence, whose boxes all contain the hub), and
// kept when their half area is below this share of the box's.
constexpr double kObbTryRatio = 8.0;
constexpr double kObbKeepShare = 0.25;
// Padding of an oriented box, relative to the size of its coordinates: far
// above the rounding of its projections, far below any distance that matters.
constexpr double kObbPad = 1e-9;

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

// The triangles of the mesh, by face, with their boxes, centroids and areas.
// Per triangle, independent: in parallel (as the loops after the tree).
void set_up_triangles(const Mesh& mesh, std::vector<Tri>& tris, std::vector<Box>& boxes, std::vector<Vec3>& centroid,
                      std::vector<double>& area)
{
    const std::size_t n = mesh.n_faces();
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
}

// The growth of the tree: the per-triangle data it reads, the permutation of
// the triangles (`order`, by face) it sorts into leaf order, and the progress.
struct Builder
{
    const std::vector<Tri>& tris;
    const std::vector<Box>& boxes;
    const std::vector<Vec3>& centroid;
    const std::vector<double>& area;
    std::vector<std::uint32_t>& order;
    StageProgress& stage;

    bool fit_obb(std::uint32_t begin, std::uint32_t end, Obb& out) const;
    std::uint32_t split(const Task task, const Box& cbox);
    void process(const Task task, Part& out);
    void grow(Part& part);
    void grow_subtrees(Part& tree);
};

// The oriented box of the triangles order[begin..end): principal axes of
// their corners, extents over the corners, padded.
bool Builder::fit_obb(std::uint32_t begin, std::uint32_t end, Obb& out) const
{
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
}

// The split of an inner node's triangles order[task.begin..task.end), whose
// centroids' box is `cbox`: they are reordered so that the left child's come
// first, and the first of the right child's is returned.
std::uint32_t Builder::split(const Task task, const Box& cbox)
{
    const std::uint32_t count = task.end - task.begin;
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
    return mid;
}

// Processes one node: its boxes, and its triangles as a leaf or its two
// children, created in `out` and pushed on its stack (left on top).
void Builder::process(const Task task, Part& out)
{
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
    const std::uint32_t mid = split(task, cbox);
    const auto left = std::uint32_t(out.nodes.size());
    out.nodes.push_back({});
    out.nodes.push_back({});
    out.nodes[task.node].first = left;
    out.nodes[task.node].count = 0;
    out.stack.push_back({left + 1, mid, task.end, task.depth + 1});
    out.stack.push_back({left, task.begin, mid, task.depth + 1});
}

// Depth first, left child first, as the tasks come off the stack.
void Builder::grow(Part& part)
{
    while (!part.stack.empty()) {
        stage.check();  // a node costs O(its triangles), the root O(n)
        const Task task = part.stack.back();
        part.stack.pop_back();
        process(task, part);
    }
}

// The subtrees `sub` of the root of `tree`, each numbered from 0 (its root),
// appended to `tree` as the serial build numbers them (see grow_subtrees()).
void append_subtrees(Part& tree, const Part (&sub)[2])
{
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
}

// The root's two subtrees (the two tasks on the stack of `tree`, whose root
// is processed) on two threads, each numbered from 0 (its root), then
// appended as the serial build numbers them: the left subtree's root is node
// 1, its other nodes follow from 3 in their order; the right one's root is
// node 2, its other nodes follow those. Their triangle ranges are disjoint.
// The same tree, node for node, as the serial build.
void Builder::grow_subtrees(Part& tree)
{
    Part sub[2];
    for (int k = 0; k < 2; ++k) {
        const Task t = tree.stack[std::size_t(1 - k)];  // left on top
        sub[k].nodes.push_back({});
        sub[k].stack.push_back({0, t.begin, t.end, t.depth});
    }
    auto right = std::async(std::launch::async, [&] { grow(sub[1]); });
    grow(sub[0]);
    right.get();
    append_subtrees(tree, sub);
}

// The tables of `out` from the grown tree and the permutation `order` of the
// triangles into leaf order: the triangles in that order, the oriented boxes'
// slots, and the parent, leaf and position tables.
void make_tables(Part& tree, const std::vector<std::uint32_t>& order, Bvh& out)
{
    const std::size_t n = order.size();
    out.nodes = std::move(tree.nodes);
    out.obbs = std::move(tree.obbs);
    const auto obb_of = std::move(tree.obb_of);
    std::vector<Tri> ordered(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) ordered[i] = out.tris[order[i]];
    out.tris.swap(ordered);
    out.obb_slot.assign(out.obbs.empty() ? 0 : out.nodes.size(), 0);
    for (const auto& [node, slot] : obb_of) {
        out.nodes[node].count |= kHasObb;
        out.obb_slot[node] = slot;
    }
    out.parent_of.assign(out.nodes.size(), 0);
    out.leaf_of.assign(n, 0);
    out.position_of.assign(n, 0);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) out.position_of[out.tris[i].face] = std::uint32_t(i);
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < out.nodes.size(); ++k) {
        const Node& node = out.nodes[k];
        if (node.triangles() > 0) {
            for (std::uint32_t i = 0; i < node.triangles(); ++i) out.leaf_of[node.first + i] = std::uint32_t(k);
        } else {
            out.parent_of[node.first] = out.parent_of[node.first + 1] = std::uint32_t(k);
        }
    }
}

}  // namespace

void build_bvh(const Mesh& mesh, Bvh& out)
{
    const std::size_t n = mesh.n_faces();
    // Progress: the triangles placed in leaves. The tree is grown outside
    // OpenMP regions (its check() may throw Cancelled).
    StageProgress stage("index", n);
    out.tris.resize(n);
    std::vector<Box> boxes(n);
    std::vector<Vec3> centroid(n);
    std::vector<double> area(n);
    set_up_triangles(mesh, out.tris, boxes, centroid, area);
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    Builder builder{out.tris, boxes, centroid, area, order, stage};

    Part tree;
    tree.nodes.reserve(2 * (n / kLeafSize + 1));
    tree.nodes.push_back({});
    stage.check();
    builder.process({0, 0, std::uint32_t(n), 0}, tree);
    if (tree.stack.size() == 2 && n >= kParallelBuild && omp_get_max_threads() > 1) {
        builder.grow_subtrees(tree);
    } else {
        builder.grow(tree);
    }
    make_tables(tree, order, out);
    stage.finish();
}

}  // namespace meshdiff::detail
