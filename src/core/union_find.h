//! \file union_find.h
//! \brief Disjoint sets over 0..n-1 with path halving; the root of a set is its
//! smallest element (so counts and roots do not depend on the union order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace meshdiff::detail {

class UnionFind
{
public:
    explicit UnionFind(std::size_t n = 0) { reset(n); }

    //! n singletons again (reuses the storage).
    void reset(std::size_t n)
    {
        parent_.resize(n);
        std::iota(parent_.begin(), parent_.end(), 0u);
    }

    std::uint32_t find(std::uint32_t x)
    {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];
            x = parent_[x];
        }
        return x;
    }

    //! Joins the sets of a and b; false if they were one set already.
    bool unite(std::uint32_t a, std::uint32_t b)
    {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        if (a < b) std::swap(a, b);
        parent_[a] = b;
        return true;
    }

private:
    std::vector<std::uint32_t> parent_;
};

}  // namespace meshdiff::detail
