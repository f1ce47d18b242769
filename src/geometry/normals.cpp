#include "meshdiff/geometry/normals.h"

#include "meshdiff/core/tolerances.h"

#include <cmath>

namespace meshdiff {

std::vector<Vec3> vertex_normals(const Mesh& mesh)
{
    return vertex_normals(MeshData(mesh));
}

std::vector<Vec3> vertex_normals(const MeshData& data)
{
    const Mesh& mesh = data.mesh();
    std::vector<Vec3> normals(mesh.n_vertices(), Vec3::Zero());
    std::vector<double> weight(mesh.n_vertices(), 0.0);
    const std::vector<char>& degenerate = data.degenerate_faces();
    for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
        if (degenerate[f]) continue;
        const Face& t = mesh.faces[f];
        const Vec3 n = face_cross(mesh, f).normalized();
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = mesh.points[std::size_t(t[k])];
            const Vec3 e1 = mesh.points[std::size_t(t[(k + 1) % 3])] - p;
            const Vec3 e2 = mesh.points[std::size_t(t[(k + 2) % 3])] - p;
            // atan2 of |cross| and dot is accurate for tiny and near-straight angles.
            const double angle = std::atan2(e1.cross(e2).norm(), e1.dot(e2));
            normals[std::size_t(t[k])] += angle * n;
            weight[std::size_t(t[k])] += angle;
        }
    }
    // A sum that nearly cancels (back-to-back faces, folds) has a direction
    // made of rounding errors: treat it as no normal rather than a random one.
    for (std::size_t v = 0; v < normals.size(); ++v) {
        const double len = normals[v].norm();
        normals[v] = len > kMinNormalRatio * weight[v] && len > 0.0 ? Vec3(normals[v] / len) : Vec3(Vec3::Zero());
    }
    return normals;
}

}  // namespace meshdiff
