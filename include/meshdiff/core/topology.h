//! \file topology.h
//! \brief The topology of a triangle mesh: vertex adjacency, vertex-face
//! incidence, unique edges and their half-edges (EdgeMap), boundary and
//! degenerate masks, and the topology report of METHOD.md section 1. All of
//! meshdiff takes these from here.
//!
//! "Degenerate" has one meaning in meshdiff: a face is degenerate when it has a
//! repeated corner or its area is zero relative to the mesh, |cross| <=
//! kDegenerateArea x diag^2. Two numerical guards of a different kind sit beside
//! it and are documented with it: kFlatCornerSine (cotangent.h: a corner too
//! flat for a finite cotangent) and kThinTriangleSine (point_triangle.h: a
//! triangle too thin for the face-region projection). Neither changes which
//! faces count as degenerate.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/tolerances.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace meshdiff {

// kDegenerateArea, the one rule of a degenerate face, is in tolerances.h.

//! Compressed sparse row adjacency: the neighbours of vertex i are
//! `index[offset[i]] .. index[offset[i+1]-1]`, sorted ascending, without i.
struct Adjacency
{
    std::vector<std::uint32_t> offset;  //!< size n+1
    std::vector<std::uint32_t> index;

    std::size_t size() const { return offset.empty() ? 0 : offset.size() - 1; }
    std::size_t degree(std::size_t i) const { return offset[i + 1] - offset[i]; }
    const std::uint32_t* begin(std::size_t i) const { return index.data() + offset[i]; }
    const std::uint32_t* end(std::size_t i) const { return index.data() + offset[i + 1]; }
};

//! Vertex-vertex adjacency over mesh edges (each face contributes its three
//! edges; edges shared by several faces appear once).
Adjacency vertex_adjacency(const Mesh& mesh);

//! The same, from the mesh's vertex-face incidence (vertex_faces(mesh), or
//! MeshData::vertex_faces()) when the caller has it. Throws
//! InvalidArgumentError when \p vertex_faces has not one row per vertex.
Adjacency vertex_adjacency(const Mesh& mesh, const Adjacency& vertex_faces);

//! An undirected edge a < b and the lowest-numbered face that has it.
struct Edge
{
    std::uint32_t a, b, face;
};

//! The unique undirected edges of the faces, sorted by (a, b), each with the
//! lowest face that has it. Edges of a face with a repeated corner are kept
//! unless their two ends coincide. (edge_map(mesh).edges, without the rest.)
std::vector<Edge> unique_edges(const Mesh& mesh);

class MeshData;

//! The same from \p data's mesh, with its vertex-face incidence (derived there
//! if not yet): each vertex's edges to higher ends found in its row, one
//! vertex at a time, in parallel.
std::vector<Edge> unique_edges(const MeshData& data);

//! The half-edges of a mesh grouped by undirected edge: the one edge table of
//! meshdiff (topology report, edge sampling, dihedral angles, the descents of
//! the certified Hausdorff distance, the pseudo-normals of signed distances).
//! Half-edge h = 3 f + k runs from corner k of face f to corner k + 1 (mod 3);
//! a collapsed corner (both ends the same vertex) is on no edge. Edge e has
//! count(e) half-edges: 1 is a boundary edge, more than 2 a non-manifold one; a
//! face that has an edge twice (a repeated face, or a repeated corner) counts
//! twice.
struct EdgeMap
{
    //! No edge (of a collapsed corner), no opposite half-edge.
    static constexpr std::uint32_t kNone = 0xffffffffu;

    std::vector<Edge> edges;            //!< as unique_edges(): sorted by (a, b), each with its lowest face
    std::vector<std::uint32_t> offset;  //!< size edges.size() + 1, into half_edge
    //! The half-edges of edge e, half_edge[offset[e] .. offset[e+1]-1], in
    //! ascending order (so by face, then corner).
    std::vector<std::uint32_t> half_edge;
    std::vector<std::uint32_t> edge_of;  //!< per half-edge 3 f + k: its edge, kNone for a collapsed corner
    //! Per half-edge 3 f + k: the other half-edge of its edge where the edge has
    //! exactly two and they run in opposite directions; kNone otherwise.
    std::vector<std::uint32_t> opposite;
    //! The edges with one half-edge, with more than two, and with two in the
    //! same direction (an orientation conflict), as topology_report() counts them.
    std::size_t boundary_edges = 0, non_manifold_edges = 0, misoriented_edges = 0;

    std::size_t size() const { return edges.size(); }
    std::size_t count(std::size_t e) const { return offset[e + 1] - offset[e]; }
    const std::uint32_t* begin(std::size_t e) const { return half_edge.data() + offset[e]; }
    const std::uint32_t* end(std::size_t e) const { return half_edge.data() + offset[e + 1]; }
    //! Two half-edges in the same direction.
    bool misoriented(std::size_t e) const { return count(e) == 2 && opposite[half_edge[offset[e]]] == kNone; }
};

//! The EdgeMap of \p mesh: a counting sort of the half-edges on the lower end
//! of their edge, then a sort per vertex (a hub of degree D costs D log D).
//! Throws InvalidMeshError when 3 x faces does not fit below EdgeMap::kNone.
EdgeMap edge_map(const Mesh& mesh);

//! The same from \p data's mesh, with its vertex-face incidence (derived there
//! if not yet): each vertex's edges to higher ends found in its row, one
//! vertex at a time, in parallel.
EdgeMap edge_map(const MeshData& data);

//! Mean length over the edges of \p adj (vertex_adjacency() of \p mesh), each
//! edge counted once; 0 without edges.
double mean_edge_length(const Mesh& mesh, const Adjacency& adj);

//! Vertex-face incidence: the faces around vertex i, ascending.
Adjacency vertex_faces(const Mesh& mesh);

//! Topological facts of a mesh, all counts (METHOD.md section 1).
struct TopologyReport
{
    std::size_t vertices = 0;
    std::size_t faces = 0;
    std::size_t edges = 0;
    std::size_t components = 0;             //!< connected components over edges
    std::size_t boundary_edges = 0;         //!< edges with exactly one face
    std::size_t boundary_loops = 0;         //!< components of the boundary-edge graph
    std::size_t non_manifold_edges = 0;     //!< edges with more than two faces
    std::size_t non_manifold_vertices = 0;  //!< vertices whose faces form more than one fan
    std::size_t degenerate_faces = 0;       //!< zero-area faces (relative to the bbox)
    std::size_t duplicate_faces = 0;        //!< faces on the same vertex set as an earlier one
    std::size_t orientation_conflicts = 0;  //!< edges used twice in the same direction
    std::size_t isolated_vertices = 0;      //!< vertices in no face
    bool closed() const { return boundary_edges == 0; }
};
TopologyReport topology_report(const Mesh& mesh);

//! Per-face flag: true where the face is degenerate (see kDegenerateArea):
//! a repeated corner, or |cross| <= kDegenerateArea x diag^2 (cross: the
//! face's cross product of two edges, twice its area; diag: the mesh's
//! bounding-box diagonal). Such faces contribute no normal, no curvature term
//! and no face samples.
std::vector<char> degenerate_face_mask(const Mesh& mesh);
//! The same from the mesh's bounding box \p box (bounding_box(mesh)).
std::vector<char> degenerate_face_mask(const Mesh& mesh, const BoundingBox& box);

//! Per-vertex flag: true where the vertex lies on a boundary edge (an edge
//! with exactly one face) or on a non-manifold edge.
std::vector<char> boundary_vertex_mask(const Mesh& mesh);

}  // namespace meshdiff
