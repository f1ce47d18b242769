//! \file hub_tree.h (detail)
//! \brief The k-d trees over the neighbours of hub vertices (degree above
//! kMaxFitNeighbors + 1) that the curvature fits' neighbourhood search uses
//! (curvature.cpp, its only user): the k nearest neighbours of a point,
//! exactly in the order (squared distance, id).
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/roughness/curvature.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace meshdiff::detail {

// Squared distance, the one key of every "nearest" below.
inline double dist2(const Vec3& a, const Vec3& b)
{
    return (a - b).squaredNorm();
}

using Ranked = std::pair<double, std::uint32_t>;  // (squared distance, vertex id): the order of "nearest"

// A k-d tree over the neighbours of one hub vertex: the k nearest of them to a
// point, exactly in the order (squared distance, id). First a radius that
// certainly holds k of them: the k-th nearest within the smallest subtree on
// the point's path that has k items; then every item within that radius (a
// subtree is skipped only if its splitting plane alone is farther, so ties
// are kept), and the k first of those.
class HubTree
{
public:
    HubTree(const std::vector<Vec3>& points, const std::uint32_t* first, const std::uint32_t* last)
        : points_(&points), ids_(first, last)
    {
        nodes_.push_back({0, std::uint32_t(ids_.size())});
        expand(0);
    }

    // The k nearest into `out` (cleared first), in no particular order.
    void nearest(const Vec3& p, std::size_t k, std::vector<Ranked>& out) const
    {
        out.clear();
        if (k == 0) return;
        std::uint32_t node = 0;
        while (nodes_[node].left != 0) {
            const Node& n = nodes_[node];
            const std::uint32_t child = p[n.axis] - n.split <= 0.0 ? n.left : n.left + 1;
            if (nodes_[child].end - nodes_[child].begin < k) break;
            node = child;
        }
        for (std::uint32_t i = nodes_[node].begin; i < nodes_[node].end; ++i)
            out.push_back({dist2((*points_)[ids_[i]], p), ids_[i]});
        if (out.size() > k) {
            std::nth_element(out.begin(), out.begin() + std::ptrdiff_t(k - 1), out.end());
            const double r2 = out[k - 1].first;
            out.clear();
            within(0, p, r2, out);
            std::nth_element(out.begin(), out.begin() + std::ptrdiff_t(k - 1), out.end());
            out.resize(k);
        }
    }

private:
    struct Node
    {
        std::uint32_t begin, end;  // the items of the subtree
        std::uint32_t left = 0;    // children left, left + 1 (0: leaf)
        int axis = 0;
        double split = 0.0;
    };
    static constexpr std::uint32_t kLeaf = 8;
    const std::vector<Vec3>* points_;
    std::vector<std::uint32_t> ids_;
    std::vector<Node> nodes_;

    // Splits a node at the median of its longest axis, recursively; the
    // children of a node are adjacent in nodes_. Items before the median have
    // coordinate <= split, items from it on >= split.
    void expand(std::uint32_t k_node)
    {
        const std::uint32_t begin = nodes_[k_node].begin, end = nodes_[k_node].end;
        if (end - begin <= kLeaf) return;
        const auto& pts = *points_;
        Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
        for (std::uint32_t i = begin; i < end; ++i) {
            lo = lo.cwiseMin(pts[ids_[i]]);
            hi = hi.cwiseMax(pts[ids_[i]]);
        }
        int axis = 0;
        (hi - lo).maxCoeff(&axis);
        const std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(ids_.begin() + begin, ids_.begin() + mid, ids_.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             const double xa = pts[a][axis], xb = pts[b][axis];
                             return xa < xb || (xa == xb && a < b);
                         });
        const auto left = std::uint32_t(nodes_.size());
        nodes_.push_back({begin, mid});
        nodes_.push_back({mid, end});
        nodes_[k_node].left = left;
        nodes_[k_node].axis = axis;
        nodes_[k_node].split = pts[ids_[mid]][axis];
        expand(left);
        expand(left + 1);
    }

    void within(std::uint32_t k_node, const Vec3& p, double r2, std::vector<Ranked>& out) const
    {
        const Node& n = nodes_[k_node];
        if (n.left == 0) {
            for (std::uint32_t i = n.begin; i < n.end; ++i) {
                const double d2 = dist2((*points_)[ids_[i]], p);
                if (d2 <= r2) out.push_back({d2, ids_[i]});
            }
            return;
        }
        const double diff = p[n.axis] - n.split;
        if (diff <= 0.0 || diff * diff <= r2) within(n.left, p, r2, out);
        if (diff >= 0.0 || diff * diff <= r2) within(n.left + 1, p, r2, out);
    }
};

// The k-d trees of the vertices of degree above kMaxFitNeighbors + 1 (hubs):
// a 2-ring through such a vertex is always capped.
struct HubTrees
{
    std::vector<std::int32_t> slot;  // per vertex: index in `trees`, or -1
    std::vector<HubTree> trees;
};

constexpr std::size_t kHubDegree = kMaxFitNeighbors + 1;

}  // namespace meshdiff::detail
