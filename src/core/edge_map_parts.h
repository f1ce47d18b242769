// Private: the edge map with only the parts a caller reads (edge_map() and
// unique_edges() are its public forms).
#pragma once

#include "meshdiff/core/topology.h"

namespace meshdiff::detail {

//! What build_edge_map() fills besides the three counts.
enum class EdgeMapParts
{
    Edges,     //!< edges, offset, half_edge (unique_edges(mesh), the boundary mask)
    All,       //!< those, edge_of and opposite (edge_map())
    Opposite,  //!< opposite only (the sign check: 3 x 4 bytes a face, not 3 x 16 + 12 an edge)
};

//! The EdgeMap of \p mesh with \p parts (the others left empty), its half-edges
//! bucketed through \p vertex_faces when given (the mesh's incidence; the
//! opposite half-edges alone are then found in it, without sorting): the same
//! values as edge_map() in the parts filled.
EdgeMap build_edge_map(const Mesh& mesh, EdgeMapParts parts, const Adjacency* vertex_faces = nullptr);

}  // namespace meshdiff::detail
