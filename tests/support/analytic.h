//! \file analytic.h
//! \brief Exact mean curvature of the analytic test surfaces (METHOD.md section 4).
#pragma once

#include "meshdiff/core/mesh.h"

namespace meshdiff::test {

//! Sphere of radius r: H = 1/r.
inline double sphere_H(double r)
{
    return 1.0 / r;
}

//! Torus with centre radius R and tube radius r, v the angle around the tube
//! (v = 0 on the outer equator): H = (R + 2 r cos v) / (2 r (R + r cos v)).
double torus_H(double R, double r, double cos_v);

//! Ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 at the surface point p (H > 0).
double ellipsoid_H(double a, double b, double c, const Vec3& p);

}  // namespace meshdiff::test
