//! \file mesh.h
//! \brief The triangle mesh type of meshdiff and its basic geometry (bounding
//! box, face area vectors); topology lives in topology.h.
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

//! The largest coordinate magnitude meshdiff accepts, from a file (read_mesh())
//! or from arrays (validate()): a larger one is an InvalidMeshError naming the
//! vertex. Squared lengths alone would allow
//! ~1e150, but face areas (the norm of a cross product) and the closest-point
//! tests multiply four coordinate differences, which overflows near 1e76 (a
//! sphere of radius 1e78 made the comparison loop forever). 1e30 keeps products
//! of eight differences finite, and lies inside float range, so that the limit
//! is the same for every format. Real meshes stay many decades below it.
inline constexpr double max_coordinate = 1e30;

//! Throws InvalidMeshError (with \p what in the message) if a face index is out
//! of range, a coordinate is not finite or beyond max_coordinate, or the mesh
//! has no face.
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

}  // namespace meshdiff
