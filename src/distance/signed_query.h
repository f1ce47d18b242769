// Private: signed_query() (meshdiff/distance/signed_distance.h) with a side
// job for the query team, for the surface distance's chunks.
#pragma once

#include "meshdiff/distance/signed_distance.h"

#include <cstddef>
#include <cstdint>
#include <functional>

namespace meshdiff::detail {

//! signed_query() with \p beside run once by one thread of the team while the
//! others query (detail::distances_with_regions()); its exception is rethrown
//! once the queries are done.
void signed_query(const Mesh& mesh, const ClosestPointIndex& index, const PseudoNormals& normals, const Vec3* queries,
                  std::size_t n, double* distances, std::int8_t* signs, const std::function<void()>& beside);

}  // namespace meshdiff::detail
