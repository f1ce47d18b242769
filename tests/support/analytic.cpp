#include "support/analytic.h"

#include <cmath>

namespace meshdiff::test {

double torus_H(double R, double r, double cos_v)
{
    return (R + 2 * r * cos_v) / (2 * r * (R + r * cos_v));
}

double ellipsoid_H(double a, double b, double c, const Vec3& p)
{
    const double x = p.x(), y = p.y(), z = p.z();
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    const double num = x * x + y * y + z * z - a2 - b2 - c2;
    const double q = x * x / (a2 * a2) + y * y / (b2 * b2) + z * z / (c2 * c2);
    return std::abs(num) / (2 * a2 * b2 * c2 * std::pow(q, 1.5));
}

}  // namespace meshdiff::test
