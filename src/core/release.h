// Private: emptying a container and giving its storage back. `v = {}` does
// not: for a std::vector it assigns an empty initializer list, which keeps
// the capacity (the plan's 3M edges, 60 MB, stayed allocated that way while
// the face samples were queried).
#pragma once

#include <utility>

namespace meshdiff::detail {

//! Empties \p v and frees its storage.
template <class Container>
void release(Container& v)
{
    Container().swap(v);
}

}  // namespace meshdiff::detail
