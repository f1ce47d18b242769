//! \file point_triangle.h (detail)
//! \brief The inline primitives behind meshdiff/geometry/point_triangle.h, shared with
//! the BVH of closest_point.cpp so that its inner loop inlines them.
#pragma once

#include "meshdiff/geometry/point_triangle.h"

#include <Eigen/Geometry>

#include <utility>

namespace meshdiff::detail {

// True where the face-region projection is not used: sin(angle at a) <=
// kThinTriangleSine (point_triangle.h), a zero-length edge or a repeated corner.
inline bool is_thin_triangle(const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    constexpr double kThinTriangleSine2 = 1e-16;  // kThinTriangleSine^2 (tolerances.h), as a literal
    return !(ab.cross(ac).squaredNorm() > kThinTriangleSine2 * ab.squaredNorm() * ac.squaredNorm());
}

inline Vec3 segment_point(const Vec3& p, const Vec3& a, const Vec3& b)
{
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    if (!(len2 > 0.0)) return a;
    const double t = ab.dot(p - a) / len2;
    if (t <= 0.0) return a;
    if (t >= 1.0) return b;
    return a + t * ab;
}

// Closest point of the union of the three edges (exact for a collinear or
// point-like triangle). Ties: the first edge in the order ab, bc, ca.
inline Vec3 thin_triangle_point(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    Vec3 best = segment_point(p, a, b);
    double best_d2 = (p - best).squaredNorm();
    for (const auto& [u, v] : {std::pair<const Vec3*, const Vec3*>{&b, &c}, {&c, &a}}) {
        const Vec3 q = segment_point(p, *u, *v);
        const double d2 = (p - q).squaredNorm();
        if (d2 < best_d2) {
            best_d2 = d2;
            best = q;
        }
    }
    return best;
}

// Ericson, Real-Time Collision Detection, 5.1.5, for a non-degenerate
// triangle; the face region projects onto the plane (stable for thin
// triangles, unlike the barycentric combination).
inline Vec3 triangle_point(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Vec3 ap = p - a;
    const double d1 = ab.dot(ap);
    const double d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;

    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp);
    const double d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return b;

    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;

    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp);
    const double d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return c;

    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;

    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);

    const Vec3 n = ab.cross(ac);
    return p - (n.dot(ap) / n.squaredNorm()) * n;
}

//! The closest point of triangle (a, b, c) to p: the union of its edges for a
//! thin triangle, Ericson's Voronoi-region method otherwise.
inline Vec3 closest_triangle_point(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    return is_thin_triangle(a, b, c) ? thin_triangle_point(p, a, b, c) : triangle_point(p, a, b, c);
}

}  // namespace meshdiff::detail
