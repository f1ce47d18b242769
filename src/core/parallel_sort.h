// Private: the ascending order of distinct elements, made on the OpenMP
// threads: one piece per thread sorted in parallel, then merged pairwise
// (the merges of a round in parallel) until two are left, whose merge hands
// the elements out in order, so that a caller that keeps a part of each
// (the Morton order keeps the ids) needs no second array for the last
// round. With no two elements equal there is one sorted order, so the
// result is std::sort's at any thread count.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace meshdiff::detail {

//! Sorts the pieces of \p v (whose elements are distinct) and calls
//! \p emit(element) for each element in ascending order; \p v is left in an
//! unspecified order.
template <class T, class Emit>
void for_each_sorted_distinct(std::vector<T>& v, Emit&& emit)
{
    const std::size_t n = v.size();
    std::size_t pieces = std::size_t(std::max(1, omp_get_max_threads()));
    constexpr std::size_t kSerial = std::size_t(1) << 16;  // below, the threads' start costs more than they save
    if (pieces < 2 || n < kSerial) {
        std::sort(v.begin(), v.end());
        for (const T& x : v) emit(x);
        return;
    }
    std::vector<std::size_t> cut(pieces + 1);
    for (std::size_t k = 0; k <= pieces; ++k) cut[k] = n * k / pieces;
    auto at = [&](std::size_t k) { return v.begin() + std::ptrdiff_t(cut[std::min(k, pieces)]); };
#pragma omp parallel for schedule(static, 1)
    for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(pieces); ++k) std::sort(at(std::size_t(k)), at(std::size_t(k) + 1));
    if (pieces > 2) {
        std::vector<T> merged(n);
        while (pieces > 2) {
#pragma omp parallel for schedule(static, 1)
            for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(pieces); k += 2)
                std::merge(at(std::size_t(k)), at(std::size_t(k) + 1), at(std::size_t(k) + 1), at(std::size_t(k) + 2),
                           merged.begin() + std::ptrdiff_t(cut[std::size_t(k)]));
            v.swap(merged);
            for (std::size_t k = 0; 2 * k <= pieces; ++k) cut[k] = cut[std::min(2 * k, pieces)];
            pieces = (pieces + 1) / 2;
            cut[pieces] = n;
            cut.resize(pieces + 1);
        }
    }
    auto a = at(0), a_end = at(1), b = at(1), b_end = at(2);
    while (a != a_end && b != b_end) emit(*b < *a ? *b++ : *a++);
    for (; a != a_end; ++a) emit(*a);
    for (; b != b_end; ++b) emit(*b);
}

}  // namespace meshdiff::detail
