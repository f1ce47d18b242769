// Private: the polygons of a mesh file as its reader lists them, in one flat
// array of corner indices with an offset per polygon (no allocation per
// polygon: a reader of a 2M-face file made 2M small vectors before).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace meshdiff::detail {

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

    std::size_t size() const { return start_.size() - 1; }
    bool empty() const { return size() == 0; }
    Polygon operator[](std::size_t i) const { return {corners_.data() + start_[i], corners_.data() + start_[i + 1]}; }
    //! Room for \p n polygons of \p corners_each corners.
    void reserve(std::size_t n, std::size_t corners_each = 3)
    {
        start_.reserve(n + 1);
        corners_.reserve(n * corners_each);
    }
    void push_back(const std::vector<int>& poly) { push_back(poly.data(), poly.size()); }
    void push_back(const int* corners, std::size_t n)
    {
        corners_.insert(corners_.end(), corners, corners + n);
        start_.push_back(corners_.size());
    }

private:
    std::vector<int> corners_;
    std::vector<std::size_t> start_{0};
};

}  // namespace meshdiff::detail
