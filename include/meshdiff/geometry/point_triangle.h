//! \file point_triangle.h
//! \brief Exact closest point of a triangle or a segment to a point, and the
//! brute-force closest point of a whole mesh (the oracle of the BVH in
//! closest_point.h).
//!
//! The triangle query is Ericson's Voronoi-region method ("Real-Time Collision
//! Detection", 2005, section 5.1.5); the face region projects onto the plane,
//! which is stable for thin triangles.
//!
//! Thin triangles. A triangle whose two edges at corner 0 are numerically
//! parallel, sin(angle) <= kThinTriangleSine, or that has a zero-length edge or
//! a repeated corner, is treated as the union of its three edges: exact for a
//! segment or a point, and off by at most the triangle's width (below
//! kThinTriangleSine of its longest edge) for a nearly flat one. This is a
//! numerical guard of the query, not meshdiff's notion of a degenerate face
//! (topology.h, kDegenerateArea), which does not depend on it.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/tolerances.h"

#include <cstdint>

namespace meshdiff {

// kThinTriangleSine, the sine below which a triangle is queried as the union
// of its edges (see the file comment), is in core/tolerances.h.

//! The closest point of a mesh (or triangle) to a query point.
struct ClosestPoint
{
    double distance = 0.0;      //!< Euclidean distance, in the mesh's length unit
    Vec3 point = Vec3::Zero();  //!< the closest point on the surface
    std::uint32_t face = 0;     //!< the face it lies on (lowest index on ties)
};

//! Closest point of triangle (a, b, c) to \p p (Ericson's Voronoi-region
//! method); thin triangles as described in the file comment. `face` is 0.
ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

//! Closest point of segment [a, b] to \p p (a point if a == b). `face` is 0.
ClosestPoint closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b);

//! Reference implementation: the minimum of closest_point_on_triangle over all
//! faces of \p mesh, O(#faces). Meant for tests.
ClosestPoint closest_point_brute_force(const Mesh& mesh, const Vec3& p);

}  // namespace meshdiff
