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
//! Thin and degenerate triangles are handled as in point_triangle.h, whose
//! closest_point_on_triangle() is the exact per-triangle query the index runs.
//!
//! Ties and determinism. Among triangles at the same computed distance the one
//! with the lowest face index wins. Batch queries run in parallel over fixed
//! blocks of consecutive queries (each query starting its search from the
//! previous one's triangle), so their results are bit-identical for any number
//! of OpenMP threads.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"
#include "meshdiff/geometry/point_triangle.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace meshdiff {

//! Bounding-volume hierarchy over the triangles of a mesh, built once (binned
//! SAH split, at most 4 triangles per leaf) and queried many times. A node
//! whose axis-aligned box is far larger than its triangles (slivers: around a
//! vertex of valence 100,000 every triangle's box holds the hub, and every
//! query near it would visit them all) also gets an oriented box (principal
//! axes, padded against rounding); the farther of the two bounds prunes. The
//! answer is the same (the bounds only order and prune the search). The index
//! keeps its own copy of the triangles; the mesh may be destroyed afterwards.
//! Queries are const and thread-safe.
class ClosestPointIndex;

namespace detail {
struct Bvh;
//! The index's tree and its triangles (src/geometry/bvh_build.h), for the
//! library's own stages that read them in place (the certification's bounds).
const Bvh& bvh_of(const ClosestPointIndex& index);
//! ClosestPointIndex::distances() with visit(i, closest point, region,
//! position): the Voronoi region of the closest point's triangle the point
//! lies in, as src/geometry/point_triangle_x4.h numbers them (kRegionUnknown
//! where the triangle was tested alone: a thin one, or a machine without
//! AVX2), and the triangle's position in the index (Bvh::tris). For the signs
//! (signed_distance.cpp), which then need not find the region or the triangle
//! again.
//! Without \p visit, the distances only. \p beside, if given, is run once by
//! one thread of the team while the others query (the surface distance folds
//! the previous chunk of samples so); its exception is rethrown at the end.
//! \p order, if given (a permutation of 0 .. n - 1), is the order in which
//! the queries run (each still writes out[i] and visits i): consecutive
//! queries close in space share the index's cache lines and start near
//! their answer. The answers do not depend on it, only their cost.
void distances_with_regions(const ClosestPointIndex& index, const Vec3* queries, std::size_t n, double* out,
                            const std::function<void(std::size_t, const ClosestPoint&, unsigned, std::uint32_t)>& visit,
                            const std::function<void()>& beside = {}, const std::uint32_t* order = nullptr);
}  // namespace detail

class ClosestPointIndex
{
public:
    //! Builds the index over all faces of \p mesh (degenerate ones included).
    //! \throw InvalidMeshError if \p mesh is invalid (see meshdiff::validate()).
    explicit ClosestPointIndex(const Mesh& mesh);
    //! The same from \p data, the derived data of the mesh (mesh_data.h),
    //! which validates the mesh once.
    explicit ClosestPointIndex(const MeshData& data);
    ~ClosestPointIndex();
    ClosestPointIndex(ClosestPointIndex&&) noexcept;
    ClosestPointIndex& operator=(ClosestPointIndex&&) noexcept;
    ClosestPointIndex(const ClosestPointIndex&) = delete;
    ClosestPointIndex& operator=(const ClosestPointIndex&) = delete;

    //! Exact closest point to \p p.
    ClosestPoint closest_point(const Vec3& p) const;

    //! The same answer, the search starting at face \p near_face (faster when
    //! that face is close to \p p; any value is allowed).
    ClosestPoint closest_point(const Vec3& p, std::uint32_t near_face) const;

    //! Closest points of many queries, in parallel (OpenMP) over fixed blocks
    //! of queries; the result does not depend on the thread count.
    std::vector<ClosestPoint> closest_points(const std::vector<Vec3>& queries) const;

    //! As closest_points(), distances only (less memory).
    std::vector<double> distances(const std::vector<Vec3>& queries) const;

    //! The same for the \p n queries at \p queries, written to \p out[0, n).
    void distances(const Vec3* queries, std::size_t n, double* out) const;

    //! The same, calling \p visit(i, closest point of query i) once per query,
    //! concurrently from the worker threads (for signed_distance.h, which
    //! needs only the face, without storing it).
    void distances(const Vec3* queries, std::size_t n, double* out,
                   const std::function<void(std::size_t, const ClosestPoint&)>& visit) const;

    //! An upper bound of the distance to the mesh of every point of the
    //! triangle (or segment, or point) spanned by \p corners: the smallest,
    //! over the indexed triangles t, of the largest distance from a corner to
    //! t. The distance to one triangle is a convex function of the query
    //! point, so over the spanned triangle it is largest at a corner; the
    //! distance to the mesh is at most the distance to any one triangle. The
    //! search is a branch and bound, a node's bound being the largest distance
    //! from a corner to its box. With \p good_enough > 0 it looks only for a
    //! value at most \p good_enough: it returns the first one found, or +inf
    //! if there is none (nodes and triangles beyond it are skipped, which
    //! makes a failing search cheap). With \p good_enough <= 0 it returns the
    //! smallest value. \p face gets the triangle (or ~0u). +inf for an index
    //! without triangles.
    double hull_distance_bound(const std::array<Vec3, 3>& corners, double good_enough,
                               std::uint32_t* face = nullptr) const;

    std::size_t n_faces() const;       //!< number of indexed triangles
    BoundingBox bounds() const;        //!< box of the indexed triangles
    std::size_t memory_bytes() const;  //!< approximate heap memory of the index

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    friend const detail::Bvh& detail::bvh_of(const ClosestPointIndex& index);
    friend void detail::distances_with_regions(
        const ClosestPointIndex& index, const Vec3* queries, std::size_t n, double* out,
        const std::function<void(std::size_t, const ClosestPoint&, unsigned, std::uint32_t)>& visit,
        const std::function<void()>& beside, const std::uint32_t* order);
};

}  // namespace meshdiff
