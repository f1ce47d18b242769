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

//! Lane k: the closest point q[k] of triangle (a[k], b[k], c[k]) to p[k] and
//! its squared distance d2[k]. Only where use_avx2() (compiled on x86-64 with
//! GCC or Clang; elsewhere never called).
void closest_points_x4(const PairsX4& in, double d2[4], double qx[4], double qy[4], double qz[4]);

}  // namespace meshdiff::detail
