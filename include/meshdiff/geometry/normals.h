//! \file normals.h
//! \brief Angle-weighted vertex normals (Thuermer & Wuethrich 1998; METHOD.md
//! section 3): the sum of the unit normals of the incident faces, each weighted
//! by the face's interior angle at the vertex, normalised.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"
#include "meshdiff/core/topology.h"

#include <vector>

namespace meshdiff {

//! One unit normal per vertex, oriented like the faces (counter-clockwise seen
//! from outside gives outward normals). Degenerate faces contribute nothing. A
//! vertex with no non-degenerate face, or whose weighted normals cancel (the
//! length of the sum is below 1e-6 times the sum of the angle weights), gets
//! the zero vector: callers treat it as "no normal".
std::vector<Vec3> vertex_normals(const Mesh& mesh);
//! The same from \p data, the derived data of the mesh (its degenerate faces
//! and vertex-face incidence, derived there if not yet).
std::vector<Vec3> vertex_normals(const MeshData& data);
//! The same from \p data's degenerate faces and \p vertex_faces, the mesh's
//! vertex-face incidence (vertex_faces(data.mesh())), when the caller has it
//! and would rather not keep it in \p data. Throws InvalidArgumentError when
//! it has not one row per vertex.
std::vector<Vec3> vertex_normals(const MeshData& data, const Adjacency& vertex_faces);

}  // namespace meshdiff
