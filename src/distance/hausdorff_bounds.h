//! \file hausdorff_bounds.h (detail)
//! \brief The bounds behind certified_hausdorff() (hausdorff.cpp): upper
//! bounds of the distance to B over a triangle of A (a cell), from the
//! distances of its corners, from B's triangles near them (with descents over
//! B's faces and cuts of the cell along the planes between adjacent
//! triangles), and from the closest-point index.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"
#include "meshdiff/geometry/closest_point.h"

#include "geometry/bvh_build.h"
#include "geometry/point_triangle_kernels.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace meshdiff::detail {

constexpr double kInf = std::numeric_limits<double>::infinity();
//! No face (of B): a boundary edge's neighbour, an unknown hint.
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// Subdivision depth at which a triangle is closed whatever its bound: its
// edges are then 2^-40 (1e-12) of the original ones, the rounding level of
// the midpoints. Its bound still enters the upper bound.
constexpr int kMaxDepth = 40;

// A triangle of A (a face or a part of one) in the search.
struct Cell
{
    std::array<Vec3, 3> corner;
    // Per corner, an upper bound of its distance to B (its distance to the
    // face `closest`), exact where the corner was queried.
    std::array<double, 3> d;
    std::array<std::uint32_t, 3> closest;
    std::uint32_t face = 0;      // the face of A it lies in
    std::uint32_t hint = kNone;  // the face of B that bounded its parent
    int depth = 0;
    double upper = kInf;  // its bound, once evaluated
};

// B's triangles as the bounds read them: the closest-point index's own
// (closest_point_on_triangle()'s primitives, with the thin-triangle test done
// once per triangle), by face, in place (a copy was 80 bytes a face).
using Triangle = Tri;
class Triangles
{
public:
    Triangles() = default;
    explicit Triangles(const ClosestPointIndex& index) : bvh_(&bvh_of(index)) {}
    Triangle operator[](std::size_t face) const { return bvh_->tris[bvh_->position_of[face]]; }

private:
    const Bvh* bvh_ = nullptr;
};

//! Squared distance from p to triangle t: bitwise the square of
//! closest_point_on_triangle()'s distance before its square root.
inline double squared_distance(const Vec3& p, const Triangle& t)
{
    const Vec3 q = t.thin ? thin_triangle_point(p, t.a, t.b, t.c) : triangle_point(p, t.a, t.b, t.c);
    return (p - q).squaredNorm();
}

//! Distance from p to face t of B (closest_point_on_triangle()'s value).
inline double face_distance(const Vec3& p, const Triangles& b, std::uint32_t t)
{
    return std::sqrt(squared_distance(p, b[t]));
}

//! Per face, a face across each of its three edges (kNone where there is none).
using Neighbours = std::vector<std::array<std::uint32_t, 3>>;

//! For each face of \p m, a face across each of its three edges (kNone on a
//! boundary edge or a collapsed one; around a non-manifold edge the faces are
//! linked in a cycle, in EdgeMap order, so every one is reachable): the graph
//! of the descents.
Neighbours edge_neighbours(const MeshData& m);

//! edge_neighbours() of a mesh whose every edge has two half-edges in
//! opposite directions (closed, edge-manifold, consistently oriented: a mesh
//! pseudo_normals() accepts), from its \p opposite half-edges
//! (PseudoNormals::opposite): the face of each half-edge's opposite. The
//! same table, without an edge map.
Neighbours neighbours_across(const std::vector<std::uint32_t>& opposite);

//! Local descent over B's faces: face \p t of B is at distance \p d from
//! \p p; moves \p t to a neighbour closer to p (and \p d to its exact
//! distance) while there is one, until d <= goal, at most 16 moves. \p d
//! stays the exact distance of the face \p t holds, so it is always an upper
//! bound of d(p, B).
void descend_point(const Vec3& p, const Triangles& b, const Neighbours& nbr, std::uint32_t& t, double& d, double goal);

//! Mesh B as the bounds use it.
struct BoundsTarget
{
    BoundsTarget(const Mesh& m, const ClosestPointIndex& i);

    //! Distinct for every target made in the process (the threads' caches of
    //! B's bisecting planes are keyed by it: hausdorff_bounds.cpp).
    const std::uint64_t id;
    const Mesh& mesh;
    const ClosestPointIndex& index;
    std::vector<double> diameter;  //!< longest edge per face
    double longest = 0.0;          //!< longest edge of all faces
    Neighbours nbr;                //!< edge_neighbours(mesh) (or neighbours_across())
    Triangles tris;                //!< the index's triangles, by face
};

//! Sets \p c.upper to an upper bound of d(., B) over cell \p c, each step
//! taken only while the bound is above \p threshold: the largest corner bound
//! plus the cell's covering radius (and nothing more when the cell is wider
//! than 2 x threshold + B's longest edge, below kMaxDepth); the largest
//! distance from its corners to the best of the faces that bounded its
//! corners and its parent, lowered by a descent over B's faces; the bound of
//! the cell cut along the planes between adjacent triangles of B from that
//! face; ClosestPointIndex::hull_distance_bound(). The descent, the cuts and
//! the index only where one face of B can be near all the corners (at
//! kMaxDepth always), the index not after a descent that stopped at a local
//! minimum. \p c.hint becomes the face of B the descent ended on or the
//! index found, where there is one.
void bound_cell(Cell& c, double threshold, const BoundsTarget& target);

}  // namespace meshdiff::detail
