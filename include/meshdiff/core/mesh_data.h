//! \file mesh_data.h
//! \brief The data that several stages derive from one mesh (its bounding
//! box, degenerate-face mask, vertex-face incidence and validation), each
//! derived once, on first use, and shared by every stage handed the same
//! MeshData: compare_meshes() makes one per input and passes it to the topology
//! report, the surface distance (sampling, signs, diagonals, indexes, the
//! certified Hausdorff distance) and the same-connectivity check; a caller
//! comparing one original with many meshes can keep the original's. The owner
//! may free the incidence between stages (detail::release_vertex_faces();
//! compare_meshes() does): the next stage derives it again.
//!
//! The values are exactly those of the free functions (bounding_box(),
//! degenerate_face_mask(), vertex_faces(), validate()): the same code, run
//! once. Safe to share between threads (std::call_once, a mutex).
#pragma once

#include "meshdiff/core/mesh.h"
#include "meshdiff/core/topology.h"

#include <mutex>
#include <string>
#include <vector>

namespace meshdiff {

class MeshData;

namespace detail {
//! Frees \p data's vertex-face incidence; the next vertex_faces() derives it
//! again. For the owner of \p data that knows no reference to it is in use
//! (compare_meshes(): the incidence is read at the start of its stages only).
void release_vertex_faces(const MeshData& data);
}  // namespace detail

class MeshData
{
public:
    //! Refers to \p mesh, which must outlive this and stay unchanged.
    explicit MeshData(const Mesh& mesh) : mesh_(mesh) {}
    MeshData(const MeshData&) = delete;
    MeshData& operator=(const MeshData&) = delete;

    const Mesh& mesh() const { return mesh_; }
    //! bounding_box(mesh()).
    const BoundingBox& box() const;
    //! degenerate_face_mask(mesh()), from box().
    const std::vector<char>& degenerate_faces() const;
    //! vertex_faces(mesh()).
    const Adjacency& vertex_faces() const;
    //! validate(mesh(), \p what) until it passes once; then nothing (a mesh
    //! that passed stays valid: it does not change).
    void validate(const std::string& what) const;

private:
    friend void detail::release_vertex_faces(const MeshData& data);

    const Mesh& mesh_;
    mutable std::once_flag box_once_, degenerate_once_, valid_once_;
    mutable BoundingBox box_;
    mutable std::vector<char> degenerate_;
    mutable std::mutex vertex_faces_mutex_;  // a mutex, not a once_flag: it can be released
    mutable bool has_vertex_faces_ = false;
    mutable Adjacency vertex_faces_;
};

//! The topology report from \p data's mask and incidence (topology_report()).
TopologyReport topology_report(const MeshData& data);

}  // namespace meshdiff
