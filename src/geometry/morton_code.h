//! \file morton_code.h (private)
//! \brief Morton (Z-curve) codes of points, 21 bits per axis over a box:
//! shared by the vertex order of the ring and ball searches
//! (roughness/morton.h) and the order in which the surface distance queries
//! a chunk of samples (distance/surface_distance.cpp), so that points close in
//! space come close in the order.
#pragma once

#include "meshdiff/core/mesh.h"

#include <cstdint>

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

//! The extent of \p box for morton_code(): its size, at least 1e-300 on
//! each axis (a flat box divides by it).
inline Vec3 morton_extent(const BoundingBox& box)
{
    return (box.max - box.min).cwiseMax(Vec3::Constant(1e-300));
}

//! The Morton code of \p p in a grid of 2^21 cells per axis over the box
//! from \p lo of extent \p ext (morton_extent()). A point outside the box
//! (by rounding: a sample on a face may lie an ulp beyond its corners) is
//! coded as the nearest cell; a point in the box is coded as it always was.
inline std::uint64_t morton_code(const Vec3& p, const Vec3& lo, const Vec3& ext)
{
    constexpr double kCells = double((1u << 21) - 1);
    const Vec3 q = (p - lo).cwiseQuotient(ext) * kCells;
    const auto cell = [](double x) { return std::uint64_t(x > 0.0 ? (x < kCells ? x : kCells) : 0.0); };
    return spread_bits(cell(q.x())) | spread_bits(cell(q.y())) << 1 | spread_bits(cell(q.z())) << 2;
}

}  // namespace meshdiff::detail
