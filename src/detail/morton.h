//! \file morton.h
//! \brief Vertices in Morton (Z-curve) order of their positions: the order in
//! which the ring search (neighborhood.cpp) and the ball search
//! (metric_levels.cpp) take their centres, so that consecutive centres are
//! close in space.
#pragma once

#include "meshdiff/mesh.h"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace meshdiff::detail {

//! The lowest 21 bits of \p x spread to every third bit.
inline std::uint64_t spread_bits(std::uint64_t x)
{
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
}

//! The vertex ids of \p mesh sorted along a Morton curve of their positions
//! (21 bits per axis over the bounding box; ties by id).
inline std::vector<std::uint32_t> morton_order(const Mesh& mesh)
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

}  // namespace meshdiff::detail
