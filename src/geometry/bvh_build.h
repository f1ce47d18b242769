//! \file bvh_build.h (detail)
//! \brief The bounding-volume hierarchy of ClosestPointIndex
//! (meshdiff/geometry/closest_point.h): its triangle, node and oriented-box
//! types, shared by the builder (bvh_build.cpp) and the queries
//! (closest_point.cpp), and the builder.
#pragma once

#include "meshdiff/core/mesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace meshdiff::detail {

//! A triangle of the index: its corners, its face in the mesh, and whether
//! it is thin.
struct Tri
{
    Vec3 a, b, c;
    std::uint32_t face;
    bool thin;  // see detail::is_thin_triangle
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

//! The tree and its tables, as the queries read them.
struct Bvh
{
    std::vector<Tri> tris;  // in leaf order
    std::vector<Node> nodes;
    std::vector<std::uint32_t> parent_of;    // per node (root: 0)
    std::vector<std::uint32_t> leaf_of;      // per triangle position: its leaf
    std::vector<std::uint32_t> position_of;  // per face: its position in tris
    std::vector<Obb> obbs;                   // oriented boxes of the nodes with kHasObb
    std::vector<std::uint32_t> obb_slot;     // per node: its index in obbs (read only with kHasObb)
};

//! Builds the tree over all faces of \p mesh into \p out (whose vectors are
//! empty): binned SAH splits (median splits where the SAH split is one-sided
//! or the tree deep), at most 4 triangles per leaf, oriented boxes for the
//! nodes whose axis-aligned box is far larger than their triangles; the
//! root's two subtrees on two threads for a large mesh, the same tree, node
//! for node, as the serial build. Reports the stage "index" to the calling
//! thread's Progress.
//! \throw Cancelled if the run is cancelled.
void build_bvh(const Mesh& mesh, Bvh& out);

}  // namespace meshdiff::detail
