//! \file closest_point.h
//! \brief Exact closest point on a triangle mesh: a bounding-volume hierarchy
//! over the triangles, queried many times (stateful, PImpl).
//!
//! Exactness. The distance is the Euclidean distance from the query to the
//! closest point of the union of the mesh's triangles (point-to-triangle, after
//! Ericson, "Real-Time Collision Detection", 2005, section 5.1.5), not to the
//! closest vertex. There is no distance cut-off: a query arbitrarily far away
//! gets its true distance. The traversal (nearest child first, branch and
//! bound) prunes a node only when its box is provably farther than the best
//! triangle found, so the answer equals the brute-force minimum over all
//! triangles (to the last bits of rounding).
//!
//! Degenerate triangles. A triangle whose two edges at corner 0 are (numerically)
//! parallel, sin(angle) <= 1e-8, or that has a zero-length edge or a repeated
//! corner, is treated as the union of its three edges: exact for a segment or
//! a point, and off by at most the triangle's width (below 1e-8 of its longest
//! edge) for a nearly flat one.
//!
//! Ties and determinism. Among triangles at the same computed distance the one
//! with the lowest face index wins. Batch queries run in parallel over fixed
//! blocks of consecutive queries (each query starting its search from the
//! previous one's triangle), so their results are bit-identical for any number
//! of OpenMP threads.
#pragma once

#include "meshdiff/mesh.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace meshdiff {

//! The closest point of a mesh (or triangle) to a query point.
struct ClosestPoint
{
    double distance = 0.0;      //!< Euclidean distance, in the mesh's length unit
    Vec3 point = Vec3::Zero();  //!< the closest point on the surface
    std::uint32_t face = 0;     //!< the face it lies on (lowest index on ties)
};

//! Closest point of triangle (a, b, c) to \p p (Ericson's Voronoi-region
//! method); degenerate triangles as described in the file comment. `face` is 0.
ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

//! Closest point of segment [a, b] to \p p (a point if a == b). `face` is 0.
ClosestPoint closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b);

//! Reference implementation: the minimum of closest_point_on_triangle over all
//! faces of \p mesh, O(#faces). Meant for tests.
ClosestPoint closest_point_brute_force(const Mesh& mesh, const Vec3& p);

//! Bounding-volume hierarchy over the triangles of a mesh, built once (binned
//! SAH split, at most 4 triangles per leaf) and queried many times. The index
//! keeps its own copy of the triangles; the mesh may be destroyed afterwards.
//! Queries are const and thread-safe.
class ClosestPointIndex
{
public:
    //! Builds the index over all faces of \p mesh (degenerate ones included).
    //! \throw InvalidMeshError if \p mesh is invalid (see meshdiff::validate()).
    explicit ClosestPointIndex(const Mesh& mesh);
    ~ClosestPointIndex();
    ClosestPointIndex(ClosestPointIndex&&) noexcept;
    ClosestPointIndex& operator=(ClosestPointIndex&&) noexcept;
    ClosestPointIndex(const ClosestPointIndex&) = delete;
    ClosestPointIndex& operator=(const ClosestPointIndex&) = delete;

    //! Exact closest point to \p p.
    ClosestPoint closest_point(const Vec3& p) const;

    //! Closest points of many queries, in parallel (OpenMP) over fixed blocks
    //! of queries; the result does not depend on the thread count.
    std::vector<ClosestPoint> closest_points(const std::vector<Vec3>& queries) const;

    //! As closest_points(), distances only (less memory).
    std::vector<double> distances(const std::vector<Vec3>& queries) const;

    std::size_t n_faces() const;       //!< number of indexed triangles
    BoundingBox bounds() const;        //!< box of the indexed triangles
    std::size_t memory_bytes() const;  //!< approximate heap memory of the index

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace meshdiff
