#include "geometry/bvh_build.h"

#include "meshdiff/error.h"

#include "core/release.h"
#include "core/stage_progress.h"
#include "geometry/point_triangle_kernels.h"

#include <fmt/format.h>
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
    void grow(const Vec3& l, const Vec3& h)
    {
        lo = lo.cwiseMin(l);
        hi = hi.cwiseMax(h);
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
// The nodes reserved for n triangles: a binary tree with leaves of at most
// kLeafSize triangles has 2 x leaves - 1 nodes; its leaves hold 3.3
// triangles on average on real and generated meshes (a 2M-face torus: 1.23M
// nodes), so that 2/3 of n rarely grows (by doubling, which held up to 3
// times the array for a moment).
std::size_t node_estimate(std::size_t n)
{
    return n * 2 / 3 + 64;
}
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

// What the build reads of a face: its box, centroid and area. Not zeroed
// when allocated (set_up_faces() writes every one, in parallel).
struct FaceFacts
{
    FaceFacts() {}
    Vec3 lo, hi, centroid;
    double area;
};

// The corner k of face f.
inline const Vec3& corner(const Mesh& mesh, std::uint32_t f, int k)
{
    return mesh.points[std::size_t(mesh.faces[f][k])];
}

// The facts of every face. Per face, independent: in parallel (as the loops
// after the tree).
void set_up_faces(const Mesh& mesh, std::vector<FaceFacts>& facts)
{
    const std::size_t n = mesh.n_faces();
#pragma omp parallel for schedule(static)
    for (std::size_t f = 0; f < n; ++f) {
        const Vec3& a = corner(mesh, std::uint32_t(f), 0);
        const Vec3& b = corner(mesh, std::uint32_t(f), 1);
        const Vec3& c = corner(mesh, std::uint32_t(f), 2);
        Box box;
        box.grow(a);
        box.grow(b);
        box.grow(c);
        FaceFacts& x = facts[f];
        x.lo = box.lo;
        x.hi = box.hi;
        x.centroid = (a + b + c) / 3.0;
        x.area = 0.5 * (b - a).cross(c - a).norm();
    }
}

// The triangles in leaf order (position i holds face order[i]), their
// corners' points in the order the leaves first use them, and the triangles'
// positions by face. The numbering of the points is one serial pass (a face
// of a 2M-face mesh takes a few ns); the rest in parallel.
void set_up_triangles(const Mesh& mesh, const std::vector<std::uint32_t>& order, Bvh& out)
{
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    const std::size_t n = order.size(), nv = mesh.n_vertices();
    std::vector<std::uint32_t> slot(nv, kUnused);
    std::uint32_t used = 0;
    for (const std::uint32_t f : order)
        for (const int v : mesh.faces[f])
            if (slot[std::size_t(v)] == kUnused) slot[std::size_t(v)] = used++;
    LeafTriangles& tris = out.tris;
    tris.points.resize(used);  // not zeroed (Eigen): written once below
    tris.corners.resize(n);
    out.position_of.resize(n);
    const auto n_v = std::int64_t(nv);
#pragma omp parallel for schedule(static)
    for (std::int64_t v = 0; v < n_v; ++v)
        if (slot[std::size_t(v)] != kUnused) tris.points[slot[std::size_t(v)]] = mesh.points[std::size_t(v)];
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t f = order[i];
        LeafTriangles::Corners& t = tris.corners[i];
        for (int k = 0; k < 3; ++k) t.v[std::size_t(k)] = slot[std::size_t(mesh.faces[f][k])];
        const bool thin = detail::is_thin_triangle(corner(mesh, f, 0), corner(mesh, f, 1), corner(mesh, f, 2));
        t.face_thin = f | (thin ? LeafTriangles::kThin : 0u);
        out.position_of[f] = std::uint32_t(i);
    }
}

// The growth of the tree: the mesh and the per-face facts it reads, the
// permutation of the faces (`order`) it sorts into leaf order, and the
// progress.
struct Builder
{
    const Mesh& mesh;
    const std::vector<FaceFacts>& facts;
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
    for (std::uint32_t i = begin; i < end; ++i)
        mean += corner(mesh, order[i], 0) + corner(mesh, order[i], 1) + corner(mesh, order[i], 2);
    mean /= 3.0 * double(end - begin);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (std::uint32_t i = begin; i < end; ++i) {
        for (int k = 0; k < 3; ++k) {
            const Vec3 d = corner(mesh, order[i], k) - mean;
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
        for (int k = 0; k < 3; ++k) {
            const Vec3& q = corner(mesh, order[i], k);
            const Vec3 s(ax[0].dot(q), ax[1].dot(q), ax[2].dot(q));
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
            const double x = (facts[f].centroid[axis] - cbox.lo[axis]) * scale;
            if (!(x >= 0.0)) return 0;
            return x < double(kBins) ? std::min(kBins - 1, int(x)) : kBins - 1;
        };
        for (std::uint32_t i = task.begin; i < task.end; ++i) {
            const int b = bin_of(order[i]);
            bin_box[std::size_t(b)].grow(facts[order[i]].lo, facts[order[i]].hi);
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
                                 const double cx = facts[x].centroid[axis], cy = facts[y].centroid[axis];
                                 return cx < cy || (cx == cy && x < y);
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
        const FaceFacts& x = facts[order[i]];
        box.grow(x.lo, x.hi);
        cbox.grow(x.centroid);
    }
    Node& node = out.nodes[task.node];
    for (int k = 0; k < 3; ++k) {
        node.lo[std::size_t(k)] = box.lo[k];
        node.hi[std::size_t(k)] = box.hi[k];
    }
    const std::uint32_t count = task.end - task.begin;
    double tri_area = 0.0;
    for (std::uint32_t i = task.begin; i < task.end; ++i) tri_area += facts[order[i]].area;
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
    // The nodes at their final count (the estimate reserved for the serial
    // build would grow by doubling: 2M triangles, 1.2M nodes).
    {
        const Node root = tree.nodes[0];
        detail::release(tree.nodes);
        tree.nodes.reserve(1 + sub[0].nodes.size() + sub[1].nodes.size());
        tree.nodes.push_back(root);
    }
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
    std::vector<Node>(tree.nodes).swap(tree.nodes);  // the serial build's reserve is not needed
    Part sub[2];
    for (int k = 0; k < 2; ++k) {
        const Task t = tree.stack[std::size_t(1 - k)];  // left on top
        sub[k].nodes.reserve(node_estimate(t.end - t.begin));
        sub[k].nodes.push_back({});
        sub[k].stack.push_back({0, t.begin, t.end, t.depth});
    }
    auto right = std::async(std::launch::async, [&] { grow(sub[1]); });
    grow(sub[0]);
    right.get();
    append_subtrees(tree, sub);
}

// x rounded to a float downwards, and upwards.
float float_below(double x)
{
    const auto f = static_cast<float>(x);
    return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float float_above(double x)
{
    const auto f = static_cast<float>(x);
    return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// The 4-wide tree of `out` from the binary tree `bin` (whose oriented boxes
// are `obbs`, node k's at bin_obb[k] or kNoSlot): wide nodes in depth-first
// order, the root first, each slot's and inner half's oriented box copied
// into out.obbs in the order of obb_mask's bits.
struct Collapse
{
    static constexpr std::uint32_t kNoSlot = std::numeric_limits<std::uint32_t>::max();
    const std::vector<Node>& bin;
    const std::vector<Obb>& obbs;
    const std::vector<std::uint32_t>& bin_obb;
    Bvh& out;

    std::uint32_t obb_of(std::uint32_t k) const { return bin[k].count & kHasObb ? bin_obb[k] : kNoSlot; }

    // The number of wide nodes made from the inner binary node k.
    std::size_t count(std::uint32_t k) const
    {
        std::size_t n = 1;
        for (std::uint32_t h = 0; h < 2; ++h) {
            const std::uint32_t c = bin[k].first + h;
            if (bin[c].triangles() > 0) continue;
            for (std::uint32_t g = 0; g < 2; ++g)
                if (bin[bin[c].first + g].triangles() == 0) n += count(bin[c].first + g);
        }
        return n;
    }

    // The wide node of the inner binary node k, slot `up` % 4 of wide node
    // `up` / 4.
    std::uint32_t wide(std::uint32_t k, std::uint32_t up)
    {
        const auto w = std::uint32_t(out.nodes.size());
        out.nodes.push_back({});
        out.parent_of.push_back(up);
        out.exact_box.push_back({bin[k].lo[0], bin[k].lo[1], bin[k].lo[2], bin[k].hi[0], bin[k].hi[1], bin[k].hi[2]});
        std::array<std::uint32_t, 4> slot{};  // binary node of each slot
        std::array<std::uint32_t, 2> half_obb{kNoSlot, kNoSlot};
        std::uint8_t n = 0, split = 0;
        for (std::uint32_t h = 0; h < 2; ++h) {
            const std::uint32_t c = bin[k].first + h;
            if (bin[c].triangles() > 0) {
                slot[n++] = c;
            } else {
                slot[n++] = bin[c].first;
                slot[n++] = bin[c].first + 1;
                half_obb[h] = obb_of(c);
            }
            if (h == 0) split = n;
        }
        WideNode node;
        for (std::size_t a = 0; a < 3; ++a) {
            node.lo[a].fill(std::numeric_limits<float>::infinity());
            node.hi[a].fill(-std::numeric_limits<float>::infinity());
        }
        node.child.fill(0);
        node.count.fill(0);
        node.slots = n;
        node.split = split;
        node.obb_mask = 0;
        node.obb_first = std::uint32_t(out.obbs.size());
        for (std::uint32_t s = 0; s < n; ++s) {
            const Node& b = bin[slot[s]];
            for (std::size_t a = 0; a < 3; ++a) {
                node.lo[a][s] = float_below(b.lo[a]);
                node.hi[a][s] = float_above(b.hi[a]);
            }
            if (obb_of(slot[s]) != kNoSlot) {
                node.obb_mask = std::uint8_t(node.obb_mask | (1u << s));
                out.obbs.push_back(obbs[obb_of(slot[s])]);
            }
        }
        for (std::uint32_t h = 0; h < 2; ++h) {
            if (half_obb[h] != kNoSlot) {
                node.obb_mask = std::uint8_t(node.obb_mask | (1u << (4 + h)));
                out.obbs.push_back(obbs[half_obb[h]]);
            }
        }
        for (std::uint32_t s = 0; s < n; ++s) {
            const Node& b = bin[slot[s]];
            if (b.triangles() > 0) {
                node.child[s] = b.first;
                node.count[s] = std::uint8_t(b.triangles());
                for (std::uint32_t i = 0; i < b.triangles(); ++i) out.leaf_of[b.first + i] = 4 * w + s;
            }
        }
        out.nodes[w] = node;
        for (std::uint32_t s = 0; s < n; ++s) {
            if (bin[slot[s]].triangles() == 0) {
                const std::uint32_t child = wide(slot[s], 4 * w + s);
                out.nodes[w].child[s] = child;
            }
        }
        return w;
    }
};

// The tables of `out` from the grown tree (its triangles already in leaf
// order): the 4-wide tree with its oriented boxes, and the parent and leaf
// tables.
void make_tables(Part& tree, Bvh& out)
{
    const std::size_t n = out.tris.size();
    const std::vector<Node>& bin = tree.nodes;
    std::vector<std::uint32_t> bin_obb(tree.obbs.empty() ? 0 : bin.size(), 0);
    for (const auto& [node, slot] : tree.obb_of) {
        tree.nodes[node].count |= kHasObb;
        bin_obb[node] = slot;
    }
    out.leaf_of.assign(n, 0);
    const Node& root = bin[0];
    for (std::size_t a = 0; a < 3; ++a) {
        out.root_lo[a] = root.lo[a];
        out.root_hi[a] = root.hi[a];
    }
    Collapse collapse{bin, tree.obbs, bin_obb, out};
    if (root.count & kHasObb) {
        out.root_obb = std::uint32_t(out.obbs.size());
        out.obbs.push_back(tree.obbs[bin_obb[0]]);
    }
    if (root.triangles() > 0 || n == 0) {
        out.root_count = root.triangles();
    } else {
        const std::size_t n_wide = collapse.count(0);
        out.nodes.reserve(n_wide);
        out.parent_of.reserve(n_wide);
        out.exact_box.reserve(n_wide);
        collapse.wide(0, 0);
    }
    out.obbs.shrink_to_fit();
}

}  // namespace

void build_bvh(const Mesh& mesh, Bvh& out)
{
    const std::size_t n = mesh.n_faces();
    if (n >= LeafTriangles::kThin)
        throw InvalidArgumentError(
            fmt::format("the closest-point index takes at most {} faces, not {}", LeafTriangles::kThin - 1, n));
    // Progress: the triangles placed in leaves. The tree is grown outside
    // OpenMP regions (its check() may throw Cancelled).
    StageProgress stage("index", n);
    std::vector<FaceFacts> facts(n);
    set_up_faces(mesh, facts);
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    Builder builder{mesh, facts, order, stage};

    Part tree;
    tree.nodes.reserve(node_estimate(n));
    tree.nodes.push_back({});
    stage.check();
    builder.process({0, 0, std::uint32_t(n), 0}, tree);
    if (tree.stack.size() == 2 && n >= kParallelBuild && omp_get_max_threads() > 1) {
        builder.grow_subtrees(tree);
    } else {
        builder.grow(tree);
    }
    // The facts are done with: freed before the triangles are made, in leaf
    // order (they are not held beside them, nor permuted: 160 MB each for a
    // 2M-face mesh).
    detail::release(facts);
    set_up_triangles(mesh, order, out);
    detail::release(order);
    make_tables(tree, out);
    stage.finish();
}

}  // namespace meshdiff::detail
