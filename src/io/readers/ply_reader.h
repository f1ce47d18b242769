// Private: a strict PLY reader (ASCII, binary little and big endian) that
// keeps double coordinates as doubles. OpenMesh 9's PLY reader passes points
// through Vec3f, which loses the digits meshdiff's own double PLY output (and
// any double-precision input) carries, and it does not notice a binary file
// that ends early.
#pragma once

#include "meshdiff/core/mesh.h"

#include "io/readers/polygon_list.h"

#include <string>
#include <vector>

namespace meshdiff::detail {

struct PlySoup
{
    std::vector<Vec3> points;
    PolygonList polygons;
    std::vector<std::string> scalar_names;           //!< scalar vertex properties other than x, y, z
    std::vector<std::vector<double>> scalar_values;  //!< [property][vertex]
};

//! \throw IoError naming \p path on any syntax error or truncation.
PlySoup read_ply(const std::string& path);

}  // namespace meshdiff::detail
