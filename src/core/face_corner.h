// Private: the corner of a face at a vertex, for the loops that go from a
// vertex to its faces through the incidence (normals, pseudo-normals, the
// sign check's fans, the cotangent sums).
#pragma once

#include "meshdiff/core/mesh.h"

#include <cstddef>

namespace meshdiff::detail {

//! The position k (0..2) of vertex \p v in face \p t, 3 if absent.
inline int corner_of(const Face& t, std::size_t v)
{
    int k = 0;
    while (k < 3 && std::size_t(t[std::size_t(k)]) != v) ++k;
    return k;
}

}  // namespace meshdiff::detail
