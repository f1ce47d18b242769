//! \file colormap.h
//! \brief Colour ramps for per-vertex maps written as PLY colours.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace meshdiff {

using Rgb = std::array<std::uint8_t, 3>;

//! Diverging blue-white-red map of \p values over [-range, range] (blue low,
//! red high, white at 0); values outside are clamped; NaN is grey.
std::vector<Rgb> diverging_colors(const std::vector<double>& values, double range);

//! Sequential cool-to-warm ramp (blue, cyan, green, yellow, red) of \p values
//! over [lo, hi]; clamped outside; NaN is grey.
std::vector<Rgb> sequential_colors(const std::vector<double>& values, double lo, double hi);

//! A symmetric range that is robust to outliers: the 95th percentile of |v|
//! over the defined values (1 if there are none or it is 0).
double robust_symmetric_range(const std::vector<double>& values);

}  // namespace meshdiff
