#include "meshdiff/geometry/vertex_areas.h"

#include <cmath>

namespace meshdiff {

std::vector<double> vertex_areas(const Mesh& mesh)
{
    std::vector<double> a(mesh.n_vertices(), 0.0);
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        const Face& t = mesh.faces[f];
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
        const double third = face_cross(mesh, f).norm() / 6.0;  // |cross| / 2 / 3
        if (!(third > 0.0) || !std::isfinite(third)) continue;
        for (int k = 0; k < 3; ++k) a[std::size_t(t[std::size_t(k)])] += third;
    }
    return a;
}

}  // namespace meshdiff
