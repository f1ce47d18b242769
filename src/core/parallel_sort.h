// Private: a sort of distinct elements on the OpenMP threads: one piece per
// thread sorted in parallel, then the pieces merged pairwise, the merges of
// a round in parallel. With no two elements equal there is one sorted
// order, so the result is std::sort's at any thread count.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace meshdiff::detail {

//! Sorts \p v (whose elements are distinct) ascending.
template <class T>
void sort_distinct(std::vector<T>& v)
{
    const std::size_t n = v.size();
    const auto pieces = std::size_t(std::max(1, omp_get_max_threads()));
    constexpr std::size_t kSerial = std::size_t(1) << 16;  // below, the threads' start costs more than they save
    if (pieces < 2 || n < kSerial) {
        std::sort(v.begin(), v.end());
        return;
    }
    std::vector<std::size_t> cut(pieces + 1);
    for (std::size_t k = 0; k <= pieces; ++k) cut[k] = n * k / pieces;
    const auto m = std::ptrdiff_t(pieces);
#pragma omp parallel for schedule(static, 1)
    for (std::ptrdiff_t k = 0; k < m; ++k)
        std::sort(v.begin() + std::ptrdiff_t(cut[std::size_t(k)]), v.begin() + std::ptrdiff_t(cut[std::size_t(k) + 1]));
    std::vector<T> merged(n);
    for (std::size_t width = 1; width < pieces; width *= 2) {
        const auto step = std::ptrdiff_t(2 * width);
#pragma omp parallel for schedule(static, 1)
        for (std::ptrdiff_t k = 0; k < m; k += step) {
            const auto lo = std::ptrdiff_t(cut[std::size_t(k)]);
            const auto mid = std::ptrdiff_t(cut[std::min(std::size_t(k) + width, pieces)]);
            const auto hi = std::ptrdiff_t(cut[std::min(std::size_t(k) + 2 * width, pieces)]);
            std::merge(v.begin() + lo, v.begin() + mid, v.begin() + mid, v.begin() + hi, merged.begin() + lo);
        }
        v.swap(merged);
    }
}

}  // namespace meshdiff::detail
