// The queries of one parallel block of ClosestPointIndex's batch queries
// (closest_point.cpp): within a block, each query starts from the previous
// query's triangle. Callers that split a batch into parts of a multiple of it
// get the same blocks, so the same queries, as one batch.
#pragma once

#include <cstddef>

namespace meshdiff::detail {

constexpr std::size_t kQueryBlock = 2048;

}  // namespace meshdiff::detail
