// Private: signed_query() (meshdiff/distance/signed_distance.h) with a side
// job for the query team, for the surface distance's chunks, and the
// pseudo-normals without their face normals.
#pragma once

#include "meshdiff/distance/signed_distance.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace meshdiff::detail {

//! signed_query() with \p beside run once by one thread of the team while the
//! others query (detail::distances_with_regions()); its exception is rethrown
//! once the queries are done.
void signed_query(const Mesh& mesh, const ClosestPointIndex& index, const PseudoNormals& normals, const Vec3* queries,
                  std::size_t n, double* distances, std::int8_t* signs, const std::function<void()>& beside);

//! pseudo_normals(data, name, reason) with PseudoNormals::face left empty:
//! the vertex normals summed from face normals made as they are read (the
//! same values), never 24 bytes a face held at once (48 MB for 2M faces,
//! beside the index being built).
std::optional<PseudoNormals> pseudo_normals_without_faces(const MeshData& data, const std::string& name,
                                                          std::string* reason);

}  // namespace meshdiff::detail
