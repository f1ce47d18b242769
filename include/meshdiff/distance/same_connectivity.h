//! \file same_connectivity.h
//! \brief Metrics of a processed mesh that kept the original's connectivity
//! (smoothing, watermarking, noise: only the vertex positions moved):
//! per-vertex displacement and the angle between corresponding face normals
//! (METHOD.md section 6).
//!
//! Conventions. Two meshes have the same connectivity when they have the same
//! vertex count and the same face list, index for index and in the same order
//! (as loaded: meshdiff's readers drop unreferenced vertices and faces with a
//! repeated index, and fan-triangulate polygons, the same way for both).
//! Displacement of vertex i: |p'_i - p_i|, over every vertex, each counted
//! once. Normal deviation of face f: the angle between the unit normals of f in
//! both meshes, atan2(|n x n'|, n . n') in degrees (in [0, 180]), over the
//! faces that are non-degenerate in both meshes, each face counted once.
//! Distances are in the meshes' length unit, in the original coordinates.
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/mesh_data.h"

#include <cstddef>
#include <optional>
#include <string>

namespace meshdiff {

//! Result of same_connectivity().
struct SameConnectivity
{
    std::size_t vertices = 0;          //!< vertices compared (all)
    double displacement_rms = 0.0;     //!< sqrt(sum |p' - p|^2 / n)
    double displacement_max = 0.0;     //!< max |p' - p|
    std::size_t max_vertex = 0;        //!< first vertex at the maximum displacement
    std::size_t faces = 0;             //!< faces compared (non-degenerate in both meshes)
    std::size_t degenerate_faces = 0;  //!< faces left out (degenerate in either mesh)
    double normal_rms_deg = 0.0;       //!< sqrt(sum angle^2 / faces), degrees
    double normal_max_deg = 0.0;       //!< max angle, degrees
    std::size_t max_face = 0;          //!< first face at the maximum angle
};

//! The metrics, or std::nullopt if \p original and \p processed do not have the
//! same connectivity; then \p reason (if given) says why, e.g. "vertex counts
//! differ (100 vs 98)" or "face 7 differs: (1, 2, 3) vs (1, 3, 2)".
std::optional<SameConnectivity> same_connectivity(const Mesh& original, const Mesh& processed,
                                                  std::string* reason = nullptr);
//! The same from the two meshes' derived data (mesh_data.h).
std::optional<SameConnectivity> same_connectivity(const MeshData& original, const MeshData& processed,
                                                  std::string* reason = nullptr);

}  // namespace meshdiff
