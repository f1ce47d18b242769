// Private: the polygons of a mesh file as its reader lists them, in one flat
// array of corner indices with an offset per polygon (no allocation per
// polygon: a reader of a 2M-face file made 2M small vectors before).
#pragma once

#include "core/release.h"
#include "core/unset_allocator.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace meshdiff::detail {

//! Corner indices, not zeroed when resized.
using CornerArray = std::vector<int, UnsetAllocator<int>>;

//! Polygons of corner indices (0-based, not yet checked against the vertex
//! count), each a contiguous run of one array.
class PolygonList
{
public:
    //! One polygon's corners: a view into the list, valid until it grows.
    struct Polygon
    {
        const int* first;
        const int* last;
        const int* begin() const { return first; }
        const int* end() const { return last; }
        std::size_t size() const { return std::size_t(last - first); }
        int operator[](std::size_t k) const { return first[k]; }
    };

    std::size_t size() const { return uniform_ ? corners_.size() / uniform_ : start_.size() - 1; }
    bool empty() const { return size() == 0; }
    Polygon operator[](std::size_t i) const
    {
        if (uniform_) return {corners_.data() + uniform_ * i, corners_.data() + uniform_ * (i + 1)};
        return {corners_.data() + start_[i], corners_.data() + start_[i + 1]};
    }
    //! The corners per polygon when all have as many (assign_uniform()), else 0.
    std::size_t uniform() const { return uniform_; }
    //! The list becomes corners.size() / \p each polygons of \p each (> 0)
    //! corners (no offset per polygon); it must be empty.
    void assign_uniform(CornerArray&& corners, std::size_t each)
    {
        corners_ = std::move(corners);
        detail::release(start_);
        uniform_ = each;
    }
    //! Room for \p n polygons of \p corners_each corners.
    void reserve(std::size_t n, std::size_t corners_each = 3)
    {
        start_.reserve(n + 1);
        corners_.reserve(n * corners_each);
    }
    void push_back(const std::vector<int>& poly) { push_back(poly.data(), poly.size()); }
    void push_back(const int* corners, std::size_t n)
    {
        // (Never after assign_uniform(): the readers fill a list one way.)
        corners_.insert(corners_.end(), corners, corners + n);
        start_.push_back(corners_.size());
    }

private:
    CornerArray corners_;
    std::vector<std::size_t> start_{0};
    std::size_t uniform_ = 0;  // corners per polygon when all have as many (start_ unused)
};

}  // namespace meshdiff::detail
