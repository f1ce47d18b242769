//! \file compensated_sum.h (detail)
//! \brief Neumaier's compensated sum (an improved Kahan sum), sequential: the
//! sums of the surface distance statistics and of the same-connectivity
//! metrics, whose order (index order) makes them reproducible.
#pragma once

#include <cmath>

namespace meshdiff::detail {

struct CompensatedSum
{
    double s = 0.0, c = 0.0;
    void add(double x)
    {
        const double t = s + x;
        c += std::abs(s) >= std::abs(x) ? (s - t) + x : (x - t) + s;
        s = t;
    }
    double value() const { return s + c; }
};

}  // namespace meshdiff::detail
