//! \file derivations.h (detail)
//! \brief A log of the data derived from a mesh (its bounding box, degenerate
//! face mask, vertex-face incidence, validation), kept only while a test asks
//! for it: the check that one comparison derives each of them once per mesh
//! (tests/compare_test.cpp). Off, a note costs one relaxed atomic load.
#pragma once

#include "meshdiff/core/mesh.h"

#include <cstddef>
#include <map>
#include <utility>

namespace meshdiff::detail {

enum class Derived
{
    Box,             //!< bounding_box()
    DegenerateMask,  //!< degenerate_face_mask()
    VertexFaces,     //!< vertex_faces()
    Validation       //!< validate(const Mesh&)
};

//! A mesh as the log tells meshes apart: the address of its first point and
//! a hash of its points' bytes (two meshes alive at once differ in the
//! address; a mesh freed and another made at the same address differ in the
//! hash unless their points are the same, when the second derivation is a
//! repeat of the first's work).
using MeshKey = std::pair<const void*, std::size_t>;

//! The key of \p mesh.
MeshKey mesh_key(const Mesh& mesh);

//! Counts of each datum derived, by mesh.
using DerivationCounts = std::map<std::pair<MeshKey, Derived>, int>;

//! Records that \p what was derived from \p mesh, when the log is on.
void note_derivation(Derived what, const Mesh& mesh);

//! Starts a fresh log (one at a time; the process's other threads may add to it).
void start_derivation_log();

//! Stops the log and returns its counts.
DerivationCounts stop_derivation_log();

}  // namespace meshdiff::detail
