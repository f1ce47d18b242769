// Private: the closest points of four (point, triangle) pairs at once, in
// AVX2 registers, for the inner loops of the closest-point index. Bitwise the
// results of detail::triangle_point() (point_triangle.h) and of the squared
// distance (p - q).squaredNorm(): the same operations on each lane in the
// same order (no fused multiply-add: the variant is compiled for AVX2 alone,
// whose target has none), every Voronoi region computed and the lane's one
// selected. For triangles that are not thin (detail::is_thin_triangle()).
#pragma once

#include "meshdiff/core/mesh.h"

#include "geometry/simd.h"

namespace meshdiff::detail {

//! Pointers to the 3 coordinates of each lane's point and corners.
struct PairsX4
{
    const double* p[4];
    const double* a[4];
    const double* b[4];
    const double* c[4];
};

//! The Voronoi regions of a triangle (a, b, c), in the order in which
//! detail::triangle_point() tests them: corner a, corner b, edge ab, corner c,
//! edge ac, edge bc, then the face's interior.
enum : unsigned
{
    kRegionA,
    kRegionB,
    kRegionAB,
    kRegionC,
    kRegionAC,
    kRegionBC,
    kRegionInterior,
    kRegionUnknown  //!< not known (a thin triangle, or a query without the kernel)
};

//! Lane k: the closest point q[k] of triangle (a[k], b[k], c[k]) to p[k] and
//! its squared distance d2[k]. Returns the lanes' regions, 4 bits per region
//! from kRegionA to kRegionBC (bit 4 r + k: lane k lies in region r; a lane in
//! none lies in the interior); see lane_region(). Only where use_avx2()
//! (compiled on x86-64 with GCC or Clang; elsewhere never called).
//!
//! \p shared: what the four lanes share, read once and broadcast rather than
//! gathered lane by lane (the same values, so the same results): nothing, or
//! the triangle in.a[0], in.b[0], in.c[0] (corners of a cell against one
//! triangle); the other lanes' pointers of what is shared are not read.
enum class SharedX4
{
    kNothing,
    kTriangle
};
unsigned closest_points_x4(const PairsX4& in, double d2[4], double qx[4], double qy[4], double qz[4],
                           SharedX4 shared = SharedX4::kNothing);

//! closest_points_x4() of the point \p p and up to four triangles given by
//! the positions of their corners in \p points: lane k's corners are
//! points[corners[4 j + i]], i = 0, 1, 2, with j = min(k, count - 1) (the lanes
//! past the last triangle repeat it; count 1 to 4). The corners' coordinates
//! are loaded three at a time and transposed into the lanes, not gathered
//! one by one: the same values, so the same results. For the leaves of the
//! closest-point index, whose triangles are three positions and a fourth word.
unsigned closest_points_indexed_x4(const double* p, const Vec3* points, const std::uint32_t* corners, unsigned count,
                                   double d2[4], double qx[4], double qy[4], double qz[4]);

//! Lane \p lane's region (kRegionA .. kRegionInterior) from the masks
//! closest_points_x4() returned.
inline unsigned lane_region(unsigned masks, unsigned lane)
{
    // The lane's bit of each region (a lane lies in one region at most: the
    // lowest bit is its first).
    const unsigned m = (masks >> lane) & 0x111111u;
    return m != 0 ? unsigned(__builtin_ctz(m)) / 4 : kRegionInterior;
}

}  // namespace meshdiff::detail
