#include "meshdiff/geometry/point_triangle.h"

#include "meshdiff/error.h"

#include "geometry/point_triangle_kernels.h"

#include <cmath>
#include <limits>

namespace meshdiff {

ClosestPoint closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b)
{
    ClosestPoint r;
    r.point = detail::segment_point(p, a, b);
    r.distance = (p - r.point).norm();
    return r;
}

ClosestPoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    ClosestPoint r;
    r.point = detail::closest_triangle_point(p, a, b, c);
    r.distance = (p - r.point).norm();
    return r;
}

ClosestPoint closest_point_brute_force(const Mesh& mesh, const Vec3& p)
{
    validate(mesh, "closest_point_brute_force");
    double best_d2 = std::numeric_limits<double>::infinity();
    ClosestPoint best;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const Face& t = mesh.faces[f];
        const Vec3& a = mesh.points[std::size_t(t[0])];
        const Vec3& b = mesh.points[std::size_t(t[1])];
        const Vec3& c = mesh.points[std::size_t(t[2])];
        const Vec3 q = detail::closest_triangle_point(p, a, b, c);
        const double d2 = (p - q).squaredNorm();
        if (d2 < best_d2) {
            best_d2 = d2;
            best.point = q;
            best.face = std::uint32_t(f);
        }
    }
    best.distance = std::sqrt(best_d2);
    return best;
}

}  // namespace meshdiff
