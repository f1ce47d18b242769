//! \file mesh.h
//! \brief The triangle mesh type of meshdiff and its topology helpers.
//!
//! meshdiff works on an indexed triangle set in double precision. Files are
//! read through OpenMesh's readers (see io.h) but not into an OpenMesh
//! halfedge structure, because that structure silently refuses faces that make
//! an edge or vertex non-manifold; meshdiff must count such defects and keep
//! computing on the faces that are there (METHOD.md section 1).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace meshdiff {

using Vec3 = Eigen::Vector3d;
using Face = std::array<std::int32_t, 3>;

//! Indexed triangle mesh. Every face index is a valid vertex index (io.h and
//! the shape generators guarantee it; validate() checks it).
struct Mesh
{
    std::vector<Vec3> points;  //!< vertex positions
    std::vector<Face> faces;   //!< triangles, counter-clockwise seen from outside

    std::size_t n_vertices() const { return points.size(); }
    std::size_t n_faces() const { return faces.size(); }
};

//! Throws InvalidMeshError (with \p what in the message) if a face index is out
//! of range, a coordinate is not finite, or the mesh has no face.
void validate(const Mesh& mesh, const std::string& what = "mesh");

//! Axis-aligned bounding box.
struct BoundingBox
{
    Vec3 min = Vec3::Constant(0.0);
    Vec3 max = Vec3::Constant(0.0);
    double diagonal() const { return (max - min).norm(); }
};
BoundingBox bounding_box(const Mesh& mesh);

//! Twice the area vector (cross product of two edges) of face \p f.
Vec3 face_cross(const Mesh& mesh, std::size_t f);

//! Total surface area.
double surface_area(const Mesh& mesh);

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

//! Per-face flag: true where the face has zero area, i.e. |cross| <= eps *
//! diag^2 with eps = 1e-14 (diag: bbox diagonal). Such faces contribute no
//! normal and no distance samples.
std::vector<char> degenerate_face_mask(const Mesh& mesh);

//! Per-vertex flag: true where the vertex lies on a boundary edge (an edge
//! with exactly one face) or on a non-manifold edge.
std::vector<char> boundary_vertex_mask(const Mesh& mesh);

}  // namespace meshdiff
