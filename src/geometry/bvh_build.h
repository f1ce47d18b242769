//! \file bvh_build.h (detail)
//! \brief The bounding-volume hierarchy of ClosestPointIndex
//! (meshdiff/geometry/closest_point.h): its triangle, node and oriented-box
//! types, shared by the builder (bvh_build.cpp) and the queries
//! (closest_point.cpp), and the builder.
#pragma once

#include "meshdiff/core/mesh.h"

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace meshdiff::detail {

//! A triangle of the index as the queries read it: its corners (in the
//! index's own copy of the points, LeafTriangles), its face in the mesh, and
//! whether it is thin (see detail::is_thin_triangle). A view, made by
//! LeafTriangles::operator[].
struct Tri
{
    const Vec3& a;
    const Vec3& b;
    const Vec3& c;
    std::uint32_t face;
    bool thin;
};

//! The index's triangles in leaf order: per triangle the positions of its
//! corners in `points` and its face (with the thin bit), 16 bytes; `points`
//! holds the mesh's vertices that faces use, in the order the leaves first
//! use them (so that a leaf's corners are near each other in memory), 24
//! bytes each. A 2M-face mesh: 56 MB, not the 160 MB of the corners copied
//! into every triangle; the same coordinates, so the same distances.
struct LeafTriangles
{
    //! The bit of Corners::face_thin set for a thin triangle; a face is below
    //! it (build_bvh() checks).
    static constexpr std::uint32_t kThin = 0x80000000u;
    struct Corners
    {
        Corners() {}  // not zeroed: the build writes every one
        std::array<std::uint32_t, 3> v;
        std::uint32_t face_thin;
    };
    std::vector<Corners> corners;
    std::vector<Vec3> points;
    // Read by detail::closest_points_indexed_x4() as three positions and a
    // word per triangle, 4 words apart.
    static_assert(sizeof(Corners) == 4 * sizeof(std::uint32_t), "a triangle is four words");

    //! The face and the thin bit of a triangle's Corners::face_thin.
    static std::uint32_t face_of(std::uint32_t face_thin) { return face_thin & ~kThin; }
    static bool thin_of(std::uint32_t face_thin) { return (face_thin & kThin) != 0; }

    Tri operator[](std::size_t i) const
    {
        const Corners& t = corners[i];
        return Tri{points[t.v[0]], points[t.v[1]], points[t.v[2]], face_of(t.face_thin), thin_of(t.face_thin)};
    }
    std::size_t size() const { return corners.size(); }
    bool empty() const { return corners.empty(); }
    std::size_t memory_bytes() const { return corners.capacity() * sizeof(Corners) + points.capacity() * sizeof(Vec3); }
};

//! A node has an oriented box besides its axis-aligned one (Bvh::obbs) when
//! this bit of `count` is set.
constexpr std::uint32_t kHasObb = 0x80000000u;

//! A node of the tree: its axis-aligned box, and its triangles (a leaf) or
//! its two children (an inner node).
struct Node
{
    std::array<double, 3> lo, hi;
    std::uint32_t first;  // leaf: first triangle; inner: left child (right = first + 1)
    std::uint32_t count;  // leaf: number of triangles (> 0); inner: 0; | kHasObb
    std::uint32_t triangles() const { return count & ~kHasObb; }
};

//! An oriented bounding box: |axis[k] . (p - centre)| <= half[k], its half
//! extents padded by kObbPad (bvh_build.cpp) times the size of its
//! coordinates, so that rounding cannot put it farther from a query than a
//! triangle inside it.
struct Obb
{
    std::array<double, 3> centre;
    std::array<std::array<double, 3>, 3> axis;
    std::array<double, 3> half;
};

//! A node of the 4-wide tree the queries read, made from the binary tree
//! above by opening each inner node's inner children: its slots are its
//! binary node's children, or their children where those are inner, in the
//! binary tree's order (up to 4; a slot is a leaf or a wide node). The first
//! `split` slots are the binary left child's (1: a leaf; 2: its children), the
//! others the right child's, so that the binary tree can be walked on it (the
//! certification's hull bounds do, with the binary nodes' exact boxes: see
//! Bvh::exact_box and closest_point.cpp). The slots' boxes are floats rounded
//! outwards (each contains its binary node's box, so that no bound computed
//! from it exceeds the true distance); an unused slot's is empty (+inf,
//! -inf). Two cache lines.
struct alignas(64) WideNode
{
    WideNode() {}                                // not zeroed: the build writes every field of every node
    std::array<std::array<float, 4>, 3> lo, hi;  // [axis][slot]
    std::array<std::uint32_t, 4> child;          // wide node, or a leaf's first triangle
    std::array<std::uint8_t, 4> count;           // leaf: number of triangles (> 0); wide node: 0
    std::uint32_t obb_first;                     // in Bvh::obbs: the oriented boxes of this node's slots, then halves
    std::uint8_t obb_mask;                       // bit s < 4: slot s has one; bit 4 + h: the inner half h has one
    std::uint8_t slots;                          // 2..4
    std::uint8_t split;                          // slots of the left half: 1 or 2
};

//! The tree and its tables, as the queries read them.
struct Bvh
{
    LeafTriangles tris;                            // in leaf order
    std::vector<WideNode> nodes;                   // the root first; none if the root is a leaf
    std::vector<std::uint32_t> parent_of;          // per wide node: 4 x its parent + its slot there (root: 0)
    std::vector<std::uint32_t> leaf_of;            // per triangle position: 4 x its leaf's wide node + slot
    std::vector<std::uint32_t> position_of;        // per face: its position in tris
    std::vector<Obb> obbs;                         // oriented boxes, per wide node in obb_mask's bit order
    std::vector<std::array<double, 6>> exact_box;  // per wide node: its binary node's box (lo, hi)
    std::array<double, 3> root_lo{}, root_hi{};    // the root's box
    std::uint32_t root_obb = std::numeric_limits<std::uint32_t>::max();  // in obbs, or none
    std::uint32_t root_count = 0;  // triangles of the root when it is a leaf (nodes empty)
};

//! Builds the tree over all faces of \p mesh into \p out (whose vectors are
//! empty): binned SAH splits (median splits where the SAH split is one-sided
//! or the tree deep), at most 4 triangles per leaf, oriented boxes for the
//! nodes whose axis-aligned box is far larger than their triangles; the
//! root's two subtrees on two threads for a large mesh, the same tree, node
//! for node, as the serial build; then made 4-wide (WideNode), its subtrees
//! below the top two levels in parallel, each where one depth-first walk
//! numbers it (the same tables at any thread count). Reports the stage
//! "index" to the calling thread's Progress.
//! \throw Cancelled if the run is cancelled.
void build_bvh(const Mesh& mesh, Bvh& out);

}  // namespace meshdiff::detail
