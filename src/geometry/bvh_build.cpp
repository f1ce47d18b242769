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
    void grow_subtrees(Part& tree, Part (&sub)[2]);
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

// The root's two subtrees (the two tasks on the stack of `tree`, whose root
// is processed) on two threads, into `sub`, each numbered from 0 (its root).
// Their triangle ranges are disjoint. The same nodes as the serial build
// grows, numbered per part (Grown reads the three parts as one tree).
void Builder::grow_subtrees(Part& tree, Part (&sub)[2])
{
    std::vector<Node>(tree.nodes).swap(tree.nodes);  // the serial build's reserve is not needed
    for (int k = 0; k < 2; ++k) {
        const Task t = tree.stack[std::size_t(1 - k)];  // left on top
        sub[k].nodes.reserve(node_estimate(t.end - t.begin));
        sub[k].nodes.push_back({});
        sub[k].stack.push_back({0, t.begin, t.end, t.depth});
    }
    auto right = std::async(std::launch::async, [&] { grow(sub[1]); });
    grow(sub[0]);
    right.get();
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

// A node of the grown binary tree: its part (Grown) and its number there.
struct NodeRef
{
    std::uint32_t part, id;
};

// The grown binary tree, read in place: one part (the serial build), or the
// root's part and its two subtrees' (grow_subtrees(), whose roots stand for
// the root part's nodes 1 and 2), not copied into one numbering (a 2M-face
// mesh: 1.2M nodes, 68 MB and 0.12 s on one thread). The 4-wide tree made
// from it depends on its shape only, not on how its nodes are numbered.
class Grown
{
public:
    explicit Grown(Part& whole) : parts_{&whole, nullptr, nullptr}, split_(false) { mark(); }
    Grown(Part& root, Part (&sub)[2]) : parts_{&root, &sub[0], &sub[1]}, split_(true) { mark(); }

    const Node& node(NodeRef k) const { return parts_[k.part]->nodes[k.id]; }
    // Child h of the inner node k.
    NodeRef child(NodeRef k, std::uint32_t h) const
    {
        if (split_ && k.part == 0) return {1 + h, 0};
        return {k.part, node(k).first + h};
    }
    // Node k's oriented box, or none.
    const Obb* obb(NodeRef k) const
    {
        if (!(node(k).count & kHasObb)) return nullptr;
        const Part& p = *parts_[k.part];
        const auto it = std::lower_bound(p.obb_of.begin(), p.obb_of.end(), std::make_pair(k.id, std::uint32_t(0)));
        return &p.obbs[it->second];
    }

private:
    // The nodes with an oriented box flagged (kHasObb), their (node, slot)
    // pairs sorted by node for obb().
    void mark()
    {
        for (Part* p : parts_) {
            if (!p) continue;
            std::sort(p->obb_of.begin(), p->obb_of.end());
            for (const auto& [node, slot] : p->obb_of) p->nodes[node].count |= kHasObb;
        }
    }
    std::array<Part*, 3> parts_;
    bool split_;
};

// The 4-wide tree of `out` from the binary tree `bin`: wide nodes in
// depth-first order, the root first, each slot's and inner half's oriented
// box copied into out.obbs in the order of obb_mask's bits. The top levels
// on the calling thread, the subtrees below them in parallel, each written
// at the place the depth-first order gives it (its size counted first): the
// same tables as one depth-first walk.
struct Collapse
{
    const Grown& bin;
    Bvh& out;

    // The slots of an inner node: its children, or theirs where those are
    // inner; the first `split` the left child's. The inner halves' boxes.
    struct Slots
    {
        std::array<NodeRef, 4> slot{};
        std::array<const Obb*, 2> half{nullptr, nullptr};
        std::uint8_t n = 0, split = 0;
    };
    Slots slots_of(NodeRef k) const
    {
        Slots s;
        for (std::uint32_t h = 0; h < 2; ++h) {
            const NodeRef c = bin.child(k, h);
            if (bin.node(c).triangles() > 0) {
                s.slot[s.n++] = c;
            } else {
                s.slot[s.n++] = bin.child(c, 0);
                s.slot[s.n++] = bin.child(c, 1);
                s.half[h] = bin.obb(c);
            }
            if (h == 0) s.split = s.n;
        }
        return s;
    }
    bool inner(NodeRef k) const { return bin.node(k).triangles() == 0; }

    // The wide nodes and oriented boxes made from the inner node k.
    struct Size
    {
        std::size_t nodes = 0, obbs = 0;
    };
    Size size(NodeRef k) const
    {
        const Slots s = slots_of(k);
        Size z{1, 0};
        for (std::uint32_t i = 0; i < s.n; ++i) {
            z.obbs += bin.obb(s.slot[i]) ? 1 : 0;
            if (inner(s.slot[i])) {
                const Size c = size(s.slot[i]);
                z.nodes += c.nodes;
                z.obbs += c.obbs;
            }
        }
        for (const Obb* h : s.half) z.obbs += h ? 1 : 0;
        return z;
    }

    // The wide node of the inner node k (slots s) at w, slot `up` % 4 of wide
    // node `up` / 4, its oriented boxes from o in out.obbs; its inner slots'
    // children are left to the caller. Returns the number of boxes.
    std::size_t write(NodeRef k, const Slots& s, std::uint32_t up, std::uint32_t w, std::size_t o)
    {
        const Node& b = bin.node(k);
        out.parent_of[w] = up;
        out.exact_box[w] = {b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]};
        WideNode node;
        for (std::size_t a = 0; a < 3; ++a) {
            node.lo[a].fill(std::numeric_limits<float>::infinity());
            node.hi[a].fill(-std::numeric_limits<float>::infinity());
        }
        node.child.fill(0);
        node.count.fill(0);
        node.slots = s.n;
        node.split = s.split;
        node.obb_mask = 0;
        node.obb_first = std::uint32_t(o);
        std::size_t boxes = 0;
        for (std::uint32_t i = 0; i < s.n; ++i) {
            const Node& c = bin.node(s.slot[i]);
            for (std::size_t a = 0; a < 3; ++a) {
                node.lo[a][i] = float_below(c.lo[a]);
                node.hi[a][i] = float_above(c.hi[a]);
            }
            if (const Obb* box = bin.obb(s.slot[i])) {
                node.obb_mask = std::uint8_t(node.obb_mask | (1u << i));
                out.obbs[o + boxes++] = *box;
            }
        }
        for (std::uint32_t h = 0; h < 2; ++h) {
            if (s.half[h]) {
                node.obb_mask = std::uint8_t(node.obb_mask | (1u << (4 + h)));
                out.obbs[o + boxes++] = *s.half[h];
            }
        }
        for (std::uint32_t i = 0; i < s.n; ++i) {
            const Node& c = bin.node(s.slot[i]);
            if (c.triangles() > 0) {
                node.child[i] = c.first;
                node.count[i] = std::uint8_t(c.triangles());
                for (std::uint32_t t = 0; t < c.triangles(); ++t) out.leaf_of[c.first + t] = 4 * w + i;
            }
        }
        out.nodes[w] = node;
        return boxes;
    }

    // The wide subtree of the inner node k, depth first from wide node w and
    // box o (both advanced past it).
    void subtree(NodeRef k, std::uint32_t up, std::uint32_t& w, std::size_t& o)
    {
        const Slots s = slots_of(k);
        const std::uint32_t me = w++;
        o += write(k, s, up, me, o);
        for (std::uint32_t i = 0; i < s.n; ++i) {
            if (!inner(s.slot[i])) continue;
            out.nodes[me].child[i] = w;
            subtree(s.slot[i], 4 * me + i, w, o);
        }
    }

    // A subtree left to a thread: its inner node, parent slot and places.
    struct Job
    {
        NodeRef k;
        std::uint32_t up, w;
        std::size_t o;
    };
    // The wide nodes of the top `depth` levels under k, at w and o; the
    // subtrees below them into `jobs`, at the places they take.
    void top(NodeRef k, std::uint32_t up, std::uint32_t w, std::size_t o, int depth, std::vector<Job>& jobs)
    {
        if (depth == 0) {
            jobs.push_back({k, up, w, o});
            return;
        }
        const Slots s = slots_of(k);
        o += write(k, s, up, w, o);
        std::uint32_t next = w + 1;
        for (std::uint32_t i = 0; i < s.n; ++i) {
            if (!inner(s.slot[i])) continue;
            out.nodes[w].child[i] = next;
            top(s.slot[i], 4 * w + i, next, o, depth - 1, jobs);
            const Size z = size(s.slot[i]);
            next += std::uint32_t(z.nodes);
            o += z.obbs;
        }
    }
};

// The tables of `out` from the grown tree (its triangles already in leaf
// order): the 4-wide tree with its oriented boxes, and the parent and leaf
// tables.
void make_tables(const Grown& bin, Bvh& out)
{
    const std::size_t n = out.tris.size();
    out.leaf_of.assign(n, 0);
    const NodeRef root_ref{0, 0};
    const Node& root = bin.node(root_ref);
    for (std::size_t a = 0; a < 3; ++a) {
        out.root_lo[a] = root.lo[a];
        out.root_hi[a] = root.hi[a];
    }
    const Obb* root_obb = bin.obb(root_ref);
    if (root.triangles() > 0 || n == 0) {
        out.root_count = root.triangles();
        if (root_obb) {
            out.root_obb = 0;
            out.obbs.assign(1, *root_obb);
        }
        return;
    }
    Collapse collapse{bin, out};
    const Collapse::Size total = collapse.size(root_ref);
    // Every entry is written once below (WideNode is not zeroed).
    out.nodes.resize(total.nodes);
    out.parent_of.resize(total.nodes);
    out.exact_box.resize(total.nodes);
    out.obbs.resize((root_obb ? 1 : 0) + total.obbs);
    if (root_obb) {
        out.root_obb = 0;
        out.obbs[0] = *root_obb;
    }
    // Two levels: up to 16 subtrees shared out between the threads.
    std::vector<Collapse::Job> jobs;
    collapse.top(root_ref, 0, 0, root_obb ? 1 : 0, 2, jobs);
#pragma omp parallel for schedule(dynamic, 1)
    for (std::ptrdiff_t j = 0; j < std::ptrdiff_t(jobs.size()); ++j) {
        const Collapse::Job& job = jobs[std::size_t(j)];
        std::uint32_t w = job.w;
        std::size_t o = job.o;
        collapse.subtree(job.k, job.up, w, o);
    }
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

    Part tree, sub[2];
    tree.nodes.reserve(node_estimate(n));
    tree.nodes.push_back({});
    stage.check();
    builder.process({0, 0, std::uint32_t(n), 0}, tree);
    const bool split = tree.stack.size() == 2 && n >= kParallelBuild && omp_get_max_threads() > 1;
    if (split) {
        builder.grow_subtrees(tree, sub);
    } else {
        builder.grow(tree);
    }
    // The facts are done with: freed before the triangles are made, in leaf
    // order (they are not held beside them, nor permuted: 160 MB each for a
    // 2M-face mesh).
    detail::release(facts);
    set_up_triangles(mesh, order, out);
    detail::release(order);
    make_tables(split ? Grown(tree, sub) : Grown(tree), out);
    stage.finish();
}

}  // namespace meshdiff::detail
