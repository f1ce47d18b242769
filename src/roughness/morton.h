//! \file morton.h
//! \brief Vertices in Morton (Z-curve) order of their positions, and the
//! compact batches of centres built from it, shared by the ring search
//! (neighborhood.cpp) and the ball search (metric_levels.cpp) so that the
//! centres of a batch are close in space.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/topology.h"

#include "core/parallel_sort.h"
#include "geometry/morton_code.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshdiff::detail {

//! The vertex ids of \p mesh sorted along a Morton curve of their positions
//! (21 bits per axis over \p box, the bounding box of the positions; ties by
//! id), the codes made and sorted on the OpenMP threads (the same order).
inline std::vector<std::uint32_t> morton_order(const Mesh& mesh, const BoundingBox& box)
{
    const Vec3 ext = morton_extent(box);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(mesh.n_vertices());
    const auto n = std::ptrdiff_t(keys.size());
#pragma omp parallel for schedule(static)
    for (std::ptrdiff_t j = 0; j < n; ++j) {
        const auto i = std::size_t(j);
        keys[i] = {morton_code(mesh.points[i], box.min, ext), std::uint32_t(i)};
    }
    std::vector<std::uint32_t> order;
    order.reserve(keys.size());
    for_each_sorted_distinct(keys, [&](const auto& key) { order.push_back(key.second); });  // distinct: the ids differ
    return order;
}

//! Centres grouped into compact patches of the mesh graph: seeds are taken in
//! \p morton (morton_order()), and each patch grows by breadth-first search over vertices
//! not yet assigned until it holds \p batch centres (or its component is
//! exhausted). Compact batches keep the union of their disks small.
inline std::vector<std::uint32_t> clustered_order(const std::vector<std::uint32_t>& morton, const Adjacency& adj,
                                                  const std::vector<double>& values, std::size_t batch)
{
    const std::size_t n = adj.size();
    std::vector<char> assigned(n, 0);
    std::vector<std::uint32_t> order;
    order.reserve(n);
    std::vector<std::uint32_t> queue;
    std::size_t in_batch = 0;
    for (auto seed : morton) {
        if (assigned[seed] || std::isnan(values[seed])) continue;
        queue.assign(1, seed);
        assigned[seed] = 1;
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const auto v = queue[q];
            order.push_back(v);
            if (++in_batch == batch) {
                in_batch = 0;
                // Release what was queued but not taken.
                for (std::size_t r = q + 1; r < queue.size(); ++r) assigned[queue[r]] = 0;
                break;
            }
            for (auto it = adj.begin(v); it != adj.end(v); ++it)
                if (!assigned[*it] && !std::isnan(values[*it])) {
                    assigned[*it] = 1;
                    queue.push_back(*it);
                }
        }
    }
    return order;
}

}  // namespace meshdiff::detail
